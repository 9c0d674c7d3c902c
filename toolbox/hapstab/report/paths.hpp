// hapstab/report/paths.hpp -- file names that come from input, kept inside the folder they
// belong to (docs/security.md): output files inside --out, files a scene reads inside the
// scene's own folder.
//
// A name used as one file-name component (a figure name, a scene's file stem, a shard folder)
// must be clean text (report::is_clean_text), 1-255 bytes, hold no '/' or '\', not be "." or
// "..", and not start with '-' (a program given it as an argument would read an option).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace hapstab::report {

/// `name` when it is a safe file-name component (above); else throws InputError naming `what`.
std::string file_component(std::string_view name, const std::string& what);

/// A file an input names, resolved against `base` (the input's folder) and required to stay
/// inside it: a relative path without "..", no absolute path, symbolic links resolved, a
/// regular file of at most `max_bytes`. Throws InputError naming `what` otherwise.
std::filesystem::path input_file_inside(const std::filesystem::path& base, std::string_view relative,
                                        const std::string& what, std::uintmax_t max_bytes);

/// The bytes of an input file: a regular file (not a FIFO, a device or a folder; symbolic links
/// followed) of at most `max_bytes`, checked before it is opened and again while it is read.
/// Throws InputError naming `what` otherwise.
std::string read_input_file(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes);

/// A fresh folder only this user can enter (mkdtemp, mode 0700) in $TMPDIR (else /tmp), removed
/// with everything in it when the object goes. For files hapstab writes and then hands to another
/// program (gnuplot): nobody else can have put a file there, or replace one.
class PrivateFolder {
 public:
  explicit PrivateFolder(const std::string& prefix);  ///< prefix: "hapstab-plot" -> /tmp/hapstab-plot-XXXXXX
  ~PrivateFolder();
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// Copies `source` to dir/name, where dir is a folder the user named (created when missing) and
/// may hold anything: dir itself must not be a symbolic link (refused), and dir/name is written
/// as a new file (O_EXCL | O_NOFOLLOW) renamed over the old name, so a symbolic link planted at
/// dir/name is replaced, never followed. Every write is checked. Returns dir/name; InputError
/// naming `what` when dir is a symbolic link, not a folder or not writable (a read-only mount),
/// NumericalError when a write fails (disk full).
std::filesystem::path install_file(const std::filesystem::path& source, const std::filesystem::path& dir,
                                   const std::string& name, const std::string& what);

}  // namespace hapstab::report
