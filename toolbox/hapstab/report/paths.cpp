#include "hapstab/report/paths.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::report {

namespace fs = std::filesystem;

std::string file_component(std::string_view name, const std::string& what) {
  const std::string shown = "'" + text(name) + "'";
  if (name.empty()) throw InputError(what + ": an empty name cannot be a file name");
  if (name.size() > 255) throw InputError(what + ": a name longer than 255 bytes cannot be a file name");
  if (!is_clean_text(name))
    throw InputError(what + ": " + shown + " holds control characters or malformed UTF-8, not allowed in a file name");
  if (name.find_first_of("/\\") != std::string_view::npos)
    throw InputError(what + ": " + shown + " holds a path separator; a name must stay one file name");
  if (name == "." || name == "..") throw InputError(what + ": " + shown + " is not a file name");
  if (name.front() == '-') throw InputError(what + ": " + shown + " starts with '-', which programs read as an option");
  return std::string(name);
}

fs::path input_file_inside(const fs::path& base, std::string_view relative, const std::string& what,
                           std::uintmax_t max_bytes) {
  const std::string shown = "'" + text(relative) + "'";
  if (relative.empty()) throw InputError(what + ": empty file name");
  if (!is_clean_text(relative)) throw InputError(what + ": " + shown + " holds control characters or malformed UTF-8");
  const fs::path rel(relative);
  if (rel.is_absolute() || rel.has_root_name() || rel.has_root_directory())
    throw InputError(what + ": " + shown + " is an absolute path; name a file in the scene's own folder (relative)");
  for (const auto& part : rel)
    if (part == "..")
      throw InputError(what + ": " + shown + " climbs out of the scene's folder with '..'; name a file inside it");
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(fs::absolute(base), ec);
  if (ec) throw InputError(what + ": cannot resolve the folder '" + text(base.string()) + "': " + ec.message());
  const fs::path full = fs::weakly_canonical(root / rel, ec);
  if (ec || !fs::exists(full)) throw InputError(what + ": cannot read " + shown + " (no such file)");
  // A symbolic link inside the folder may still point out of it.
  auto r = root.begin();
  auto f = full.begin();
  for (; r != root.end(); ++r, ++f)
    if (f == full.end() || *f != *r)
      throw InputError(what + ": " + shown + " leads out of the scene's folder (through a symbolic link)");
  if (!fs::is_regular_file(full, ec)) throw InputError(what + ": " + shown + " is not a regular file");
  const auto size = fs::file_size(full, ec);
  if (ec) throw InputError(what + ": cannot read " + shown + ": " + ec.message());
  if (size > max_bytes)
    throw InputError(what + ": " + shown + " has " + std::to_string(size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes));
  return full;
}

std::string read_input_file(const fs::path& path, const std::string& what, std::uintmax_t max_bytes) {
  const std::string shown = "'" + text(path.string()) + "'";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(what + ": " + shown + (fs::exists(path, ec) ? " is not a regular file" : ": no such file"));
  const auto size = fs::file_size(path, ec);
  if (ec) throw InputError(what + ": cannot read " + shown + ": " + ec.message());
  if (size > max_bytes)
    throw InputError(what + ": " + shown + " has " + std::to_string(size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(what + ": cannot read " + shown);
  std::string bytes(static_cast<std::size_t>(size) + 1, '\0');  // one more: a file that grew is refused
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.size() > size)
    throw InputError(what + ": " + shown + " grew while it was read");
  return bytes;
}

PrivateFolder::PrivateFolder(const std::string& prefix) {
  const char* tmp = std::getenv("TMPDIR");
  std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + "-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!::mkdtemp(buf.data()))  // mode 0700
    throw NumericalError("cannot create a private folder " + text(templ) + ": " + std::strerror(errno));
  path_ = buf.data();
}

PrivateFolder::~PrivateFolder() {
  std::error_code ec;
  fs::remove_all(path_, ec);  // does not follow symbolic links
}

namespace {

/// Closes fd on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

fs::path install_file(const fs::path& source, const fs::path& dir, const std::string& name, const std::string& what) {
  file_component(name, what);
  const std::string shown = "'" + text(dir.string()) + "'";
  if (::mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    throw InputError(what + ": cannot create the folder " + shown + ": " + std::strerror(errno));
  const Fd d{::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)};
  if (d.fd < 0)
    throw InputError(what + ": " + shown + (errno == ELOOP || errno == ENOTDIR ? " is a symbolic link or not a folder; "
                                                                                 "hapstab writes only into a real folder"
                                                                               : std::string(": ") + std::strerror(errno)));
  const std::string bytes = read_input_file(source, what, std::uintmax_t(1) << 30);
  std::random_device rd;
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
    tmp = "." + name + ".tmp" + std::to_string(rd());
    fd = ::openat(d.fd, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) throw InputError(what + ": cannot write into " + shown + ": " + std::strerror(errno));  // e.g. read-only
  bool ok = true;
  for (std::size_t done = 0; ok && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  ok = ::close(fd) == 0 && ok;
  if (!ok || ::renameat(d.fd, tmp.c_str(), d.fd, name.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlinkat(d.fd, tmp.c_str(), 0);
    throw NumericalError(what + ": cannot write " + text((dir / name).string()) + ": " + why);
  }
  return dir / name;
}

}  // namespace hapstab::report
