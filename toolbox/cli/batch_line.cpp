#include "cli/batch_line.hpp"

#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {

std::vector<std::string> split_batch_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool in = false, any = false;
  char q = 0;
  for (char ch : line) {
    if (q) {
      if (ch == q) q = 0;
      else cur += ch;
    } else if (ch == '\'' || ch == '"') {
      q = ch;
      any = true;
    } else if (ch == ' ' || ch == '\t') {
      if (in || any) out.push_back(cur);
      cur.clear();
      in = any = false;
    } else {
      cur += ch;
      in = true;
    }
  }
  if (q) throw InputError("unterminated quote in batch line");
  if (in || any) out.push_back(cur);
  return out;
}

}  // namespace hapstab::cli
