// cli/mat_level5.cpp -- see mat_level5.hpp.
#include "cli/mat_level5.hpp"

#include <zlib.h>

#include <cstdint>
#include <limits>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::cli {
namespace {

constexpr std::size_t max_elements = std::size_t(1) << 24;         // entries of one array (128 MB of doubles)
constexpr std::size_t max_inflated_bytes = std::size_t(256) << 20;  // all compressed variables together
constexpr int max_depth = 16;                                       // cells and structs inside each other
constexpr std::uint32_t max_dims = 32;

// Data types (miXXX) and array classes (mxXXX) of the format.
enum : std::uint32_t { mi_int8 = 1, mi_int32 = 5, mi_uint32 = 6, mi_matrix = 14, mi_compressed = 15 };
enum : unsigned { mx_cell = 1, mx_struct = 2, mx_object = 3, mx_char = 4, mx_sparse = 5, mx_double = 6, mx_uint64 = 15 };

// Bytes per entry of a numeric data type, 0 for the types that are not numeric arrays.
std::size_t type_size(std::uint32_t type) {
  switch (type) {
    case 1: case 2: return 1;          // miINT8, miUINT8
    case 3: case 4: return 2;          // miINT16, miUINT16
    case 5: case 6: case 7: return 4;  // miINT32, miUINT32, miSINGLE
    case 9: case 12: case 13: return 8;  // miDOUBLE, miINT64, miUINT64
    default: return 0;
  }
}

struct Element {
  std::uint32_t type = 0;
  std::size_t data = 0, bytes = 0;  ///< where its data starts, and how many bytes
  std::size_t next = 0;             ///< where the element after it starts
};

class Walker {
 public:
  Walker(std::string where, bool swap) : where_(std::move(where)), swap_(swap) {}

  /// The top-level elements of `bytes` from `offset`: each a variable, maybe compressed.
  void variables(const std::string& bytes, std::size_t offset) {
    while (offset < bytes.size()) {
      if (bytes.size() - offset < 8) fail("trailing bytes after the last variable", offset);
      const Element e = tag(bytes, offset, bytes.size(), /*top=*/true);
      name_.clear();
      if (e.type == mi_compressed)
        compressed(bytes, e);
      else if (e.type == mi_matrix)
        matrix(bytes, e, 0);
      else
        fail("an element of type " + std::to_string(e.type) + " where a variable (miMATRIX) belongs", offset);
      offset = e.next;
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t at) const {
    throw InputError(where_ + (name_.empty() ? "" : ":" + report::text(name_)) + ": not a valid .mat file: " + what +
                     " (byte " + std::to_string(at) + (inflated_ ? " of its inflated data" : "") + ")");
  }

  std::uint32_t u32(const std::string& b, std::size_t at) const {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      const auto byte = static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]));
      v |= swap_ ? byte << (8 * (3 - i)) : byte << (8 * i);
    }
    return v;
  }

  // The element at `at`, which must end by `end`. Inside a miMATRIX elements are padded to 8
  // bytes; top-level elements are not (a compressed variable has no padding).
  Element tag(const std::string& b, std::size_t at, std::size_t end, bool top = false) const {
    if (end < at || end - at < 8) fail("an element tag runs past the end of its variable", at);
    const std::uint32_t first = u32(b, at);
    Element e;
    if (first >> 16) {  // small data element: type and byte count in 4 bytes, data in the next 4
      e.type = first & 0xffff;
      e.bytes = first >> 16;
      if (e.bytes > 4) fail("a small data element of " + std::to_string(e.bytes) + " bytes (at most 4)", at);
      e.data = at + 4;
      e.next = at + 8;
      return e;
    }
    e.type = first;
    e.bytes = u32(b, at + 4);
    e.data = at + 8;
    const std::size_t padded = top ? e.bytes : (e.bytes + 7) / 8 * 8;
    if (padded > end - e.data)
      fail("an element declares " + std::to_string(e.bytes) + " bytes, " + std::to_string(end - e.data) + " are left", at);
    e.next = e.data + padded;
    return e;
  }

  void compressed(const std::string& b, const Element& e) {
    if (inflated_) fail("a compressed element inside a compressed element", e.data);
    z_stream z{};
    if (inflateInit(&z) != Z_OK) throw NumericalError("zlib cannot start inflating");
    std::string out;
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(b.data() + e.data));
    z.avail_in = static_cast<uInt>(e.bytes);
    int rc = Z_OK;
    while (rc == Z_OK) {
      if (inflated_total_ + out.size() >= max_inflated_bytes) {
        inflateEnd(&z);
        fail("its compressed variables inflate to more than " + std::to_string(max_inflated_bytes >> 20) + " MB", e.data);
      }
      char chunk[1 << 14];
      z.next_out = reinterpret_cast<Bytef*>(chunk);
      z.avail_out = sizeof chunk;
      rc = inflate(&z, Z_NO_FLUSH);
      out.append(chunk, sizeof chunk - z.avail_out);
      if (rc == Z_BUF_ERROR && z.avail_in > 0) rc = Z_OK;  // no progress possible only when input is left
    }
    inflateEnd(&z);
    if (rc != Z_STREAM_END) fail("its compressed data is corrupt or cut short (zlib " + std::to_string(rc) + ")", e.data);
    inflated_total_ += out.size();
    inflated_ = true;
    const Element inner = tag(out, 0, out.size(), true);
    if (inner.type != mi_matrix) fail("a compressed element that holds no variable (miMATRIX)", 0);
    matrix(out, inner, 0);
    inflated_ = false;
  }

  // One miMATRIX: array flags, dimensions, name, then what its class holds.
  void matrix(const std::string& b, const Element& m, int depth) {
    if (depth > max_depth) fail("cells or structs nested more than " + std::to_string(max_depth) + " deep", m.data);
    if (m.bytes == 0) return;  // an empty cell entry or field
    const std::size_t end = m.data + m.bytes;
    const Element flags = tag(b, m.data, end);
    if (flags.type != mi_uint32 || flags.bytes != 8) fail("a variable without its array flags", m.data);
    const unsigned cls = u32(b, flags.data) & 0xff;
    const std::uint32_t nzmax = u32(b, flags.data + 4);
    const Element dims = tag(b, flags.next, end);
    if (dims.type != mi_int32 || dims.bytes % 4 || dims.bytes / 4 < 2 || dims.bytes / 4 > max_dims)
      fail("dimensions that are not 2 to " + std::to_string(max_dims) + " int32 values", flags.next);
    std::size_t count = 1;
    for (std::size_t k = 0; k < dims.bytes / 4; ++k) {
      const std::uint32_t d = u32(b, dims.data + 4 * k);
      if (d > std::numeric_limits<std::int32_t>::max()) fail("a negative dimension", dims.data);
      if (d != 0 && count > std::numeric_limits<std::size_t>::max() / d) fail("dimensions whose product overflows", dims.data);
      count *= d;
    }
    const Element name = tag(b, dims.next, end);
    if (name.type != mi_int8 || name.bytes > 63) fail("a variable name that is not int8 of at most 63 characters", dims.next);
    if (depth == 0) name_.assign(b, name.data, name.bytes);
    std::size_t at = name.next;
    switch (cls) {
      case mx_cell:
        if (count > (end - at) / 8) fail(std::to_string(count) + " cell entries in " + std::to_string(end - at) + " bytes", at);
        for (std::size_t k = 0; k < count; ++k) at = child(b, at, end, depth);
        return;
      case mx_struct: {
        const Element len = tag(b, at, end);
        const std::uint32_t field_len = len.bytes == 4 ? u32(b, len.data) : 0;
        if (len.type != mi_int32 || field_len == 0 || field_len > 64) fail("a struct without a field name length of 1 to 64", at);
        const Element names = tag(b, len.next, end);
        if (names.type != mi_int8 || names.bytes % field_len) fail("struct field names that do not fill their length", len.next);
        const std::size_t fields = names.bytes / field_len;
        at = names.next;
        if (fields != 0 && count > (end - at) / 8 / fields)
          fail(std::to_string(count) + " structs of " + std::to_string(fields) + " fields in " + std::to_string(end - at) + " bytes", at);
        for (std::size_t k = 0; k < count * fields; ++k) at = child(b, at, end, depth);
        return;
      }
      case mx_sparse: {
        if (nzmax > max_elements) fail("a sparse matrix of " + std::to_string(nzmax) + " nonzeros", flags.data);
        for (int part = 0; part < 4 && at < end; ++part) at = tag(b, at, end).next;  // ir, jc, pr, pi
        return;
      }
      case mx_object: fail("a MATLAB object; hapstab reads double matrices, structs and cells", m.data);
      default:
        if (cls < mx_char || cls > mx_uint64) fail("an array of class " + std::to_string(cls) + " (function handle or opaque)", m.data);
    }
    if (count > max_elements) fail(std::to_string(count) + " entries (at most " + std::to_string(max_elements) + ")", dims.data);
    for (int part = 0; part < 2 && at < end; ++part) {  // real part, then the imaginary part if complex
      const Element d = tag(b, at, end);
      const std::size_t size = type_size(d.type);
      if (cls != mx_char && (size == 0 || d.bytes != count * size))
        fail("numeric data of " + std::to_string(d.bytes) + " bytes for " + std::to_string(count) + " entries", at);
      at = d.next;
    }
  }

  std::size_t child(const std::string& b, std::size_t at, std::size_t end, int depth) {
    const Element e = tag(b, at, end);
    if (e.type != mi_matrix) fail("a cell entry or struct field that is not an array (miMATRIX)", at);
    matrix(b, e, depth + 1);
    return e.next;
  }

  std::string where_, name_;
  bool swap_ = false, inflated_ = false;
  std::size_t inflated_total_ = 0;
};

}  // namespace

void check_level5_structure(const std::string& bytes, const std::string& where) {
  if (bytes.size() < 128) throw InputError(where + ": not a MATLAB level-5 .mat file (shorter than its 128-byte header)");
  // the endian indicator: "IM" for a little-endian file (what we read natively), "MI" swapped
  const bool swap = bytes[126] == 'M' && bytes[127] == 'I';
  Walker(where, swap).variables(bytes, 128);
}

}  // namespace hapstab::cli
