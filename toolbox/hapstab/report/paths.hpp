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

}  // namespace hapstab::report
