#include "hapstab/report/paths.hpp"

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

}  // namespace hapstab::report
