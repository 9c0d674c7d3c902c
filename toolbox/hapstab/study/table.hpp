// hapstab/study/table.hpp -- the results of a sweep: one record line per point ("INDEX JSON"),
// collected from checkpoint or shard files, checked for missing and duplicate indices, and
// written as results.txt (the records in index order) and points.csv (index, axis values, the
// command's JSON flattened, exit, error).
//
// A record is {"exit": code, "json": {...}} or {"exit": code, "error": "message"}. Flattening:
// nested objects join their keys with '_', 2-element arrays become NAME_lo and NAME_hi, other
// arrays NAME_0, NAME_1, ...; keys named "seconds" or ending in "_seconds" (timings) are dropped,
// so that two runs of one spec give the same bytes. The columns are the union of every row's keys
// in order of first appearance over the points in index order: they depend on the points only,
// not on how they were split into jobs or shards. A key named like an axis, index, exit or error
// is written json_KEY. Every cell of points.csv goes through report::csv::cell (the one CSV
// writer, report/escape.hpp): RFC 4180 quoting, and a text cell a spreadsheet would evaluate as a
// formula (a received shard's record is untrusted) is neutralised with a leading '.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/study/spec.hpp"

namespace hapstab::study {

/// The points a run covers: index(k) = first + k * stride, k < count.
struct PointRange {
  uint64_t first = 0, stride = 1, count = 0;
  uint64_t index(uint64_t k) const { return first + k * stride; }
  /// Shard `shard` of `shards` of a sweep of `points`: indices shard, shard + shards, ...
  static PointRange shard_of(uint64_t points, uint64_t shard, uint64_t shards);
};

/// One record line, without its newline.
std::string record_line(uint64_t index, const nlohmann::json& record);

/// A record line taken apart: the command's JSON flattened to (column, text) pairs (timings
/// dropped), the exit code as written, and the error message ("" when none).
struct FlatRecord {
  std::vector<std::pair<std::string, std::string>> cells;
  std::string exit, error;
};
/// Flattens a record line in one pass over its text, without building the JSON (a fast sweep
/// point costs less than parsing its record into a JSON tree did). InputError when the line is
/// not a record: not "INDEX JSON", not an object, no "exit", a key twice in an object, or a
/// column twice ("a_b" beside {"a": {"b": ...}}).
FlatRecord flatten_record(const std::string& line);

/// Record lines of the points of a range, read from files (each a sequence of complete lines; an
/// unterminated last line -- a write torn by a kill -- is ignored).
class RecordStore {
 public:
  explicit RecordStore(PointRange range);
  /// Adds the lines of `file`. A second line of an index already present is kept as a duplicate.
  void add_file(const std::filesystem::path& file);
  bool has(uint64_t k) const { return at_[k].file >= 0; }
  uint64_t present() const { return present_; }
  /// Indices without a record, and indices with two (at most `limit` of each).
  std::vector<uint64_t> missing(size_t limit) const;
  const std::vector<uint64_t>& duplicates() const { return duplicates_; }
  /// The record line of position k (InputError when it has none).
  std::string line(uint64_t k) const;
  const PointRange& range() const { return range_; }

 private:
  struct Loc {
    int file = -1;
    uint64_t offset = 0;
    uint32_t length = 0;
  };
  PointRange range_;
  std::vector<std::filesystem::path> files_;
  mutable std::vector<std::unique_ptr<std::ifstream>> streams_;
  mutable std::vector<uint64_t> position_;  ///< where each stream will read next
  std::vector<Loc> at_;
  std::vector<uint64_t> duplicates_;
  uint64_t present_ = 0;
};

struct TableCounts {
  uint64_t ok = 0, failed = 0;  ///< failed: a record with an error message
};

/// Writes dir/results.txt and dir/points.csv for every point of the store's range (each must be
/// present), each to a temporary name renamed into place.
TableCounts write_table(const Spec& spec, const RecordStore& store, const std::filesystem::path& dir);

/// Writes `text` to `path` through a temporary file renamed into place (fsync'ed first).
void write_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace hapstab::study
