// Record lines -> results.txt and points.csv (see table.hpp for the formats).
#include "hapstab/study/table.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <unordered_map>

#include "hapstab/numeric/error.hpp"

namespace hapstab::study {

namespace fs = std::filesystem;

namespace {

bool is_timing(const std::string& key) {
  const std::string tail = "_seconds";
  return key == "seconds" || (key.size() > tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0);
}

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

void flatten_into(const nlohmann::json& j, const std::string& name, std::vector<std::pair<std::string, std::string>>& out) {
  const std::string pre = name.empty() ? "" : name + "_";
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!is_timing(it.key())) flatten_into(it.value(), pre + it.key(), out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i)
      flatten_into(j[i], pre + (j.size() == 2 ? (i == 0 ? "lo" : "hi") : std::to_string(i)), out);
  } else {
    out.emplace_back(name.empty() ? "value" : name, cell(j));
  }
}

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

std::vector<std::pair<std::string, std::string>> flatten(const nlohmann::json& j) {
  std::vector<std::pair<std::string, std::string>> out;
  flatten_into(j, "", out);
  return out;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

RecordStore::RecordStore(PointRange range) : range_(range), at_(range.count) {}

void RecordStore::add_file(const fs::path& file) {
  std::ifstream f(file, std::ios::binary);
  if (!f) throw InputError("cannot read '" + file.string() + "'");
  const int id = static_cast<int>(files_.size());
  files_.push_back(file);
  streams_.push_back(std::make_unique<std::ifstream>(file, std::ios::binary));
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
  auto& f = *streams_[static_cast<size_t>(loc.file)];
  f.clear();
  std::string s(loc.length, '\0');
  f.seekg(static_cast<std::streamoff>(loc.offset));
  f.read(s.data(), loc.length);
  if (!f) throw InputError("cannot read '" + files_[static_cast<size_t>(loc.file)].string() + "'");
  return s;
}

nlohmann::json RecordStore::parse_record(const std::string& s) {
  const auto sp = s.find(' ');
  if (sp == std::string::npos) throw InputError("a damaged record: " + s.substr(0, 80));
  auto j = nlohmann::json::parse(s.begin() + static_cast<std::ptrdiff_t>(sp) + 1, s.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("exit"))
    throw InputError("a damaged record: " + s.substr(0, 80));
  return j;
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
    const nlohmann::json rec = RecordStore::parse_record(line);
    const auto flat = rec.contains("json") ? flatten(rec["json"]) : std::vector<std::pair<std::string, std::string>>{};
    const auto n = static_cast<uint32_t>(flat.size());
    std::fwrite(&n, sizeof n, 1, scratch.get());
    for (const auto& [key, text] : flat) {
      auto [it, added] = column_id.emplace(key, static_cast<uint32_t>(columns.size()));
      if (added) columns.push_back(key);
      std::fwrite(&it->second, sizeof it->second, 1, scratch.get());
      put_text(scratch.get(), text);
    }
    const std::string error = rec.value("error", std::string());
    put_text(scratch.get(), rec["exit"].dump());
    put_text(scratch.get(), error);
    ++(error.empty() ? counts.ok : counts.failed);
  }
  std::string head = "index";
  for (const Axis& a : spec.axes) head += "," + csv_field(a.name);
  for (const auto& c : columns) {  // a key named like an axis or a fixed column gets a json_ prefix
    const bool taken = c == "index" || c == "exit" || c == "error" ||
                       std::any_of(spec.axes.begin(), spec.axes.end(), [&](const Axis& a) { return a.name == c; });
    head += "," + csv_field(taken ? "json_" + c : c);
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
    for (const auto& v : point_values(spec, r.index(k))) row += "," + csv_field(v);
    for (const auto& c : cells) row += "," + csv_field(c);
    const std::string exit = get_text(scratch.get());
    row += "," + exit + "," + csv_field(get_text(scratch.get())) + "\n";
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
