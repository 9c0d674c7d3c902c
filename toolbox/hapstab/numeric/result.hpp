// hapstab/numeric/result.hpp -- every number hapstab reports carries its status.
//
//   exact      rational (or algebraic) and proven;
//   certified  an enclosure [lo, hi] proven to contain the true value;
//   numeric    an estimate, with its stated error bound (or none known);
//   failed     the computation did not produce a trustworthy value (reason in `note`).
// A verdict (stable, passive, feasible) is never drawn from a `numeric` result when a
// certificate was asked for.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace hapstab {

enum class Status { exact, certified, numeric, failed };

inline const char* to_string(Status s) {
  switch (s) {
    case Status::exact: return "exact";
    case Status::certified: return "certified";
    case Status::numeric: return "numeric";
    case Status::failed: return "failed";
  }
  return "failed";
}

/// A closed interval [lo, hi] in the scalar type T.
template <class T>
struct Enclosure {
  T lo, hi;
  bool contains(const T& x) const { return lo <= x && x <= hi; }
  T width() const { return hi - lo; }
};

/// Value + status + (optional) enclosure + the method that produced it.
template <class T>
struct Result {
  T value{};
  Status status = Status::numeric;
  std::optional<Enclosure<T>> enclosure;  ///< set for `certified` (and exact: [v, v])
  std::string method;                     ///< e.g. "closed form (44)", "Sturm isolation"
  std::string note;                       ///< reason for `failed`, or caveats

  static Result exact_value(T v, std::string how) {
    Result r;
    r.enclosure = Enclosure<T>{v, v};
    r.value = std::move(v);
    r.status = Status::exact;
    r.method = std::move(how);
    return r;
  }
  static Result certified_value(T v, Enclosure<T> e, std::string how) {
    Result r;
    r.value = std::move(v);
    r.enclosure = std::move(e);
    r.status = Status::certified;
    r.method = std::move(how);
    return r;
  }
  static Result numeric_value(T v, std::string how) {
    Result r;
    r.value = std::move(v);
    r.status = Status::numeric;
    r.method = std::move(how);
    return r;
  }
};

}  // namespace hapstab
