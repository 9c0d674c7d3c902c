// Record lines -> results.txt and points.csv (see table.hpp for the formats).
#include "hapstab/study/table.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <unordered_map>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::study {

namespace fs = std::filesystem;

namespace {

bool is_timing(const std::string& key) {
  const std::string tail = "_seconds";
  return key == "seconds" || (key.size() > tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0);
}

// Scalars under a record's "json" become cells named by their path (objects join keys with '_';
// an array's elements are named 0, 1, ... and, when it ends with two, renamed lo and hi); of the
// record's other keys "exit" and "error" are kept. Called by RecordScanner for each token.
class Flattener {
 public:
  FlatRecord out;
  bool has_exit = false;

  bool open(bool array) {
    if (levels_.empty()) {  // the record itself: an object
      if (array) return false;
      levels_.push_back({});
      return true;
    }
    Level next;
    next.array = array;
    next.skip = skipped() || (levels_.size() == 1 && levels_.back().name != "json");  // only "json" is flattened
    if (levels_.size() > 1) next.prefix = path() + "_";
    next.first_cell = out.cells.size();
    levels_.push_back(std::move(next));
    return true;
  }
  void close() {
    const Level done = std::move(levels_.back());
    levels_.pop_back();
    if (done.array && done.elements == 2) {  // an enclosure: NAME_lo, NAME_hi
      const std::size_t at = done.prefix.size();
      for (std::size_t c = done.first_cell; c < out.cells.size(); ++c) {
        std::string& name = out.cells[c].first;
        name.replace(at, 1, name[at] == '0' ? "lo" : "hi");
      }
    }
    if (!levels_.empty() && levels_.back().array) ++levels_.back().elements;
  }
  bool key(std::string k) {  // false for a key the object already has (a damaged record)
    Level& l = levels_.back();
    if (std::find(l.keys.begin(), l.keys.end(), k) != l.keys.end()) return false;
    l.keys.push_back(k);
    l.name = std::move(k);
    return true;
  }
  void scalar(std::string text) {
    if (levels_.size() == 1) {  // the record's own keys
      const std::string& k = levels_.back().name;
      if (k == "exit") out.exit = std::move(text), has_exit = true;
      else if (k == "error") out.error = std::move(text);
      else if (k == "json") out.cells.emplace_back("value", std::move(text));  // a command whose JSON is one value
      return;
    }
    if (!skipped()) out.cells.emplace_back(path(), std::move(text));
    if (levels_.back().array) ++levels_.back().elements;
  }

 private:
  struct Level {
    bool array = false;
    std::string prefix;  ///< the path of this object or array, with its trailing '_' when not empty
    std::string name;    ///< the current key (objects)
    std::vector<std::string> keys;  ///< the keys read so far (objects)
    std::size_t elements = 0, first_cell = 0;
    bool skip = false;   ///< under a timing key: nothing is kept
  };
  std::vector<Level> levels_;

  // The path of the value about to be read, and whether it is kept.
  std::string path() const {
    const Level& l = levels_.back();
    return l.prefix + (l.array ? std::to_string(l.elements) : l.name);
  }
  bool skipped() const {
    const Level& l = levels_.back();
    return l.skip || (!l.array && is_timing(l.name));
  }
};

// A strict JSON reader (RFC 8259) for one record: strings are checked UTF-8 and unescaped,
// numbers keep the text they are written with (the worker wrote them with json::dump, which
// prints a double so that it reads back to itself: the text dump() gives for the parsed value).
// Iterative, and nesting is limited (max_depth). nlohmann's lexer, building a string a character
// at a time, was half the cost of a fast point's row.
class RecordScanner {
 public:
  /// Containers nested deeper than this are refused (a command's JSON nests 3 or 4 deep; a path
  /// per level would make a deep one cost memory quadratic in its depth).
  static constexpr std::size_t max_depth = 64;

  RecordScanner(const char* p, const char* end) : p_(p), end_(end) {}

  bool run(Flattener& f) {
    std::vector<char> open;  // '{' or '[' of each container being read
    for (;;) {
      const Read r = value(f, open);
      if (r == Read::bad) return false;
      if (r == Read::opened) continue;  // its first value next
      for (;;) {  // after a value: ',' for the next one, or the containers it closes
        ws();
        if (open.empty()) return p_ == end_;
        if (p_ == end_) return false;
        if (*p_ == ',') {
          ++p_;
          if (open.back() == '{' && !member_key(f)) return false;
          break;
        }
        if (*p_ != (open.back() == '{' ? '}' : ']')) return false;
        ++p_;
        open.pop_back();
        f.close();
      }
    }
  }

 private:
  const char* p_;
  const char* end_;

  void ws() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
  }
  bool member_key(Flattener& f) {
    ws();
    std::string k;
    if (!string(k)) return false;
    ws();
    if (p_ == end_ || *p_ != ':') return false;
    ++p_;
    return f.key(std::move(k));
  }
  enum class Read { bad, value, opened };
  // One value: a scalar, an empty container, or a container opened (with its first key read),
  // whose values run() reads next and closes.
  Read value(Flattener& f, std::vector<char>& open) {
    ws();
    if (p_ == end_) return Read::bad;
    const char c = *p_;
    if (c == '{' || c == '[') {
      ++p_;
      if (!f.open(c == '[')) return Read::bad;
      ws();
      if (p_ != end_ && *p_ == (c == '{' ? '}' : ']')) {  // empty
        ++p_;
        f.close();
        return Read::value;
      }
      if (open.size() >= max_depth) return Read::bad;  // each level's cells carry its whole path
      open.push_back(c);
      return c == '[' || member_key(f) ? Read::opened : Read::bad;
    }
    if (open.empty()) return Read::bad;  // the record is an object
    std::string text;
    if (c == '"') {
      if (!string(text)) return Read::bad;
    } else if (c == 't' || c == 'f' || c == 'n') {
      const char* word = c == 't' ? "true" : c == 'f' ? "false" : "null";
      const std::size_t n = std::strlen(word);
      if (std::size_t(end_ - p_) < n || std::memcmp(p_, word, n) != 0) return Read::bad;
      p_ += n;
      if (c != 'n') text = word;  // null is an empty cell
    } else if (!number(text)) {
      return Read::bad;
    }
    f.scalar(std::move(text));
    return Read::value;
  }
  // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  bool number(std::string& out) {
    const char* start = p_;
    const auto digits = [&] {
      const char* d = p_;
      while (p_ != end_ && *p_ >= '0' && *p_ <= '9') ++p_;
      return p_ != d;
    };
    if (p_ != end_ && *p_ == '-') ++p_;
    if (p_ != end_ && *p_ == '0') ++p_;
    else if (!digits()) return false;
    if (p_ != end_ && *p_ == '.') {
      ++p_;
      if (!digits()) return false;
    }
    if (p_ != end_ && (*p_ == 'e' || *p_ == 'E')) {
      ++p_;
      if (p_ != end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (!digits()) return false;
    }
    out.assign(start, p_);
    // beyond a double (1e400, or an integer too long for 64 bits): not a number JSON readers
    // agree on, and nlohmann refuses it
    if (out.find_first_of(".eE") != std::string::npos || out.size() > 19) return std::isfinite(std::strtod(out.c_str(), nullptr));
    return true;
  }
  bool hex4(unsigned& u) {
    if (end_ - p_ < 4) return false;
    u = 0;
    for (int i = 0; i < 4; ++i, ++p_) {
      const char h = *p_;
      const int d = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : -1;
      if (d < 0) return false;
      u = u * 16 + unsigned(d);
    }
    return true;
  }
  static void put_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += char(cp);
    } else if (cp < 0x800) {
      out += char(0xC0 | (cp >> 6)), out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += char(0xE0 | (cp >> 12)), out += char(0x80 | ((cp >> 6) & 0x3F)), out += char(0x80 | (cp & 0x3F));
    } else {
      out += char(0xF0 | (cp >> 18)), out += char(0x80 | ((cp >> 12) & 0x3F)), out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    }
  }
  // The length of the well-formed UTF-8 sequence at p_ (Unicode's table 3-7), 0 if it is not one.
  std::size_t utf8_length() const {
    const auto b = [&](std::size_t i) { return i < std::size_t(end_ - p_) ? (unsigned char)p_[i] : 0u; };
    const auto cont = [&](std::size_t i, unsigned lo = 0x80, unsigned hi = 0xBF) { return b(i) >= lo && b(i) <= hi; };
    const unsigned c = b(0);
    if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
    if (c == 0xE0) return cont(1, 0xA0) && cont(2) ? 3 : 0;
    if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) return cont(1) && cont(2) ? 3 : 0;
    if (c == 0xED) return cont(1, 0x80, 0x9F) && cont(2) ? 3 : 0;
    if (c == 0xF0) return cont(1, 0x90) && cont(2) && cont(3) ? 4 : 0;
    if (c >= 0xF1 && c <= 0xF3) return cont(1) && cont(2) && cont(3) ? 4 : 0;
    if (c == 0xF4) return cont(1, 0x80, 0x8F) && cont(2) && cont(3) ? 4 : 0;
    return 0;
  }
  bool string(std::string& out) {
    if (p_ == end_ || *p_ != '"') return false;
    ++p_;
    for (;;) {
      const char* run = p_;  // plain ASCII copied in one piece
      while (p_ != end_ && *p_ != '"' && *p_ != '\\' && (unsigned char)*p_ >= 0x20 && (unsigned char)*p_ < 0x80) ++p_;
      out.append(run, p_);
      if (p_ == end_) return false;
      const unsigned char c = (unsigned char)*p_;
      if (c == '"') {
        ++p_;
        return true;
      }
      if (c < 0x20) return false;  // a control character must be escaped
      if (c >= 0x80) {
        const std::size_t n = utf8_length();
        if (n == 0) return false;
        out.append(p_, n);
        p_ += n;
        continue;
      }
      if (++p_ == end_) return false;  // a backslash
      const char e = *p_++;
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned u = 0;
          if (!hex4(u)) return false;
          if (u >= 0xDC00 && u <= 0xDFFF) return false;  // a low surrogate first
          if (u >= 0xD800 && u <= 0xDBFF) {               // a high surrogate: its low one follows
            unsigned lo = 0;
            if (end_ - p_ < 2 || p_[0] != '\\' || p_[1] != 'u') return false;
            p_ += 2;
            if (!hex4(lo) || lo < 0xDC00 || lo > 0xDFFF) return false;
            u = 0x10000 + ((u - 0xD800) << 10) + (lo - 0xDC00);
          }
          put_utf8(out, u);
          break;
        }
        default: return false;
      }
    }
  }
};

/// A file written under a temporary name, fsync'ed and renamed into place by commit().
class AtomicFile {
 public:
  explicit AtomicFile(fs::path path) : path_(std::move(path)), tmp_(path_.string() + ".tmp") {
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (!f_) throw InputError("cannot write '" + tmp_.string() + "'");
  }
  ~AtomicFile() {
    if (f_) std::fclose(f_), std::remove(tmp_.c_str());
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  void write(const std::string& s) {
    if (std::fwrite(s.data(), 1, s.size(), f_) != s.size()) throw InputError("cannot write '" + tmp_.string() + "'");
  }
  void commit() {
    const bool ok = std::fflush(f_) == 0 && fsync(fileno(f_)) == 0;
    std::fclose(f_);
    f_ = nullptr;
    if (!ok) throw InputError("cannot write '" + tmp_.string() + "'");
    fs::rename(tmp_, path_);
  }

 private:
  fs::path path_, tmp_;
  std::FILE* f_ = nullptr;
};

}  // namespace

PointRange PointRange::shard_of(uint64_t points, uint64_t shard, uint64_t shards) {
  return {shard, shards, shard < points ? (points - shard + shards - 1) / shards : 0};
}

std::string record_line(uint64_t index, const nlohmann::json& record) {
  return std::to_string(index) + " " + record.dump();
}

RecordStore::RecordStore(PointRange range) : range_(range), at_(range.count) {}

void RecordStore::add_file(const fs::path& file) {
  std::ifstream f(file, std::ios::binary);
  if (!f) throw InputError("cannot read '" + file.string() + "'");
  const int id = static_cast<int>(files_.size());
  files_.push_back(file);
  streams_.push_back(std::make_unique<std::ifstream>(file, std::ios::binary));
  position_.push_back(0);
  uint64_t offset = 0;
  for (std::string line; std::getline(f, line);) {
    const uint64_t here = offset;
    offset += line.size() + 1;
    if (f.eof()) break;  // no newline: a torn last write
    char* end = nullptr;
    const unsigned long long index = std::strtoull(line.c_str(), &end, 10);
    if (end == line.c_str() || *end != ' ')
      throw InputError(file.string() + ": a line that is not a record (\"INDEX JSON\") at byte " + std::to_string(here));
    if (index < range_.first || (index - range_.first) % range_.stride != 0 ||
        (index - range_.first) / range_.stride >= range_.count)
      throw InputError(file.string() + ": point " + std::to_string(index) + " does not belong to this sweep or shard");
    Loc& loc = at_[(index - range_.first) / range_.stride];
    if (loc.file >= 0) {
      duplicates_.push_back(index);
      continue;
    }
    loc = {id, here, static_cast<uint32_t>(line.size())};
    ++present_;
  }
}

std::vector<uint64_t> RecordStore::missing(size_t limit) const {
  std::vector<uint64_t> out;
  for (uint64_t k = 0; k < range_.count && out.size() < limit; ++k)
    if (at_[k].file < 0) out.push_back(range_.index(k));
  return out;
}

std::string RecordStore::line(uint64_t k) const {
  const Loc& loc = at_.at(k);
  if (loc.file < 0) throw InputError("point " + std::to_string(range_.index(k)) + " has no record");
  const auto id = static_cast<size_t>(loc.file);
  auto& f = *streams_[id];
  std::string s(loc.length, '\0');
  if (position_[id] != loc.offset) {  // a seek empties the stream's buffer: only when the records are not in order
    f.clear();
    f.seekg(static_cast<std::streamoff>(loc.offset));
  }
  f.read(s.data(), loc.length);
  f.ignore(1);  // the newline
  position_[id] = loc.offset + loc.length + 1;
  if (!f) throw InputError("cannot read '" + files_[id].string() + "'");
  return s;
}

FlatRecord flatten_record(const std::string& line) {
  const auto damaged = [&] { return InputError("a damaged record: " + line.substr(0, 80)); };
  const auto sp = line.find(' ');
  if (sp == std::string::npos) throw damaged();
  Flattener f;
  if (!RecordScanner(line.data() + sp + 1, line.data() + line.size()).run(f) || !f.has_exit) throw damaged();
  std::vector<std::string> names;  // a column twice (a key written twice) is a damaged record too
  for (const auto& c : f.out.cells) names.push_back(c.first);
  std::sort(names.begin(), names.end());
  if (std::adjacent_find(names.begin(), names.end()) != names.end()) throw damaged();
  return std::move(f.out);
}

namespace {

// The scratch file between write_table's two passes: per row, its cells as (column id, text) and
// then exit and error, length-prefixed, so that each record is parsed once.
void put_text(std::FILE* f, const std::string& s) {
  const auto n = static_cast<uint32_t>(s.size());
  if (std::fwrite(&n, sizeof n, 1, f) != 1 || std::fwrite(s.data(), 1, n, f) != n)
    throw InputError("sweep: cannot write the scratch file");
}
uint32_t get_u32(std::FILE* f) {
  uint32_t n = 0;
  if (std::fread(&n, sizeof n, 1, f) != 1) throw InputError("sweep: the scratch file is short");
  return n;
}
std::string get_text(std::FILE* f) {
  std::string s(get_u32(f), '\0');
  if (!s.empty() && std::fread(s.data(), 1, s.size(), f) != s.size()) throw InputError("sweep: the scratch file is short");
  return s;
}

}  // namespace

TableCounts write_table(const Spec& spec, const RecordStore& store, const fs::path& dir) {
  const PointRange& r = store.range();
  std::vector<std::string> columns;  // the command's flattened keys, in order of first appearance
  std::unordered_map<std::string, uint32_t> column_id;
  AtomicFile results(dir / "results.txt"), csv(dir / "points.csv");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> scratch(std::tmpfile(), &std::fclose);
  if (!scratch) throw InputError("sweep: cannot create a scratch file");
  TableCounts counts;
  for (uint64_t k = 0; k < r.count; ++k) {  // pass 1: results.txt, the columns, the cells
    const std::string line = store.line(k);
    results.write(line + "\n");
    const FlatRecord rec = flatten_record(line);
    const auto n = static_cast<uint32_t>(rec.cells.size());
    std::fwrite(&n, sizeof n, 1, scratch.get());
    for (const auto& [key, text] : rec.cells) {
      auto [it, added] = column_id.emplace(key, static_cast<uint32_t>(columns.size()));
      if (added) columns.push_back(key);
      std::fwrite(&it->second, sizeof it->second, 1, scratch.get());
      put_text(scratch.get(), text);
    }
    put_text(scratch.get(), rec.exit);
    put_text(scratch.get(), rec.error);
    ++(rec.error.empty() ? counts.ok : counts.failed);
  }
  std::string head = "index";
  for (const Axis& a : spec.axes) head += "," + report::csv::cell(a.name);
  for (const auto& c : columns) {  // a key named like an axis or a fixed column gets a json_ prefix
    const bool taken = c == "index" || c == "exit" || c == "error" ||
                       std::any_of(spec.axes.begin(), spec.axes.end(), [&](const Axis& a) { return a.name == c; });
    head += "," + report::csv::cell(taken ? "json_" + c : c);
  }
  csv.write(head + ",exit,error\n");
  std::rewind(scratch.get());
  std::vector<std::string> cells(columns.size());
  for (uint64_t k = 0; k < r.count; ++k) {  // pass 2: the rows
    std::fill(cells.begin(), cells.end(), std::string());
    for (uint32_t c = 0, n = get_u32(scratch.get()); c < n; ++c) {
      const uint32_t id = get_u32(scratch.get());
      cells.at(id) = get_text(scratch.get());
    }
    std::string row = std::to_string(r.index(k));
    for (const auto& v : point_values(spec, r.index(k))) row += "," + report::csv::cell(v);
    for (const auto& c : cells) row += "," + report::csv::cell(c);
    const std::string exit = get_text(scratch.get());
    row += "," + report::csv::cell(exit) + "," + report::csv::cell(get_text(scratch.get())) + "\n";
    csv.write(row);
  }
  results.commit();
  csv.commit();
  return counts;
}

void write_atomically(const fs::path& path, const std::string& text) {
  AtomicFile f(path);
  f.write(text);
  f.commit();
}

}  // namespace hapstab::study
