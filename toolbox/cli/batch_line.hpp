// cli/batch_line.hpp -- one line of a `hapstab bound --batch FILE`, split into arguments the way
// a shell would for the simple cases, but by hapstab, not by a shell: words separated by spaces
// or tabs; '...' and "..." group a word (no escapes inside, quotes do not nest); "" is an empty
// word. An unterminated quote is an InputError. Nothing is expanded ($, `, *, ~ are characters).
#pragma once

#include <string>
#include <vector>

namespace hapstab::cli {

std::vector<std::string> split_batch_line(const std::string& line);

}  // namespace hapstab::cli
