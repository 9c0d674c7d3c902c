// hapstab/numeric/result.hpp -- the one status vocabulary of hapstab: every number it reports
// is a Certified<T>, every yes/no answer (stable, passive, feasible, a claim holds) a Verdict.
//
//   exact      rational (or algebraic) and proven;
//   certified  an enclosure [lo, hi] proven to contain the true value;
//   numeric    an estimate, with its stated error bound (or none known);
//   failed     the computation did not produce a trustworthy value (reason in `note`).
// A verdict (stable, passive, feasible) is never drawn from a `numeric` result when a
// certificate was asked for: Verdict::proven() is true only for a decided outcome with an
// exact or certified status.
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
struct Certified {
  T value{};
  Status status = Status::numeric;
  std::optional<Enclosure<T>> enclosure;  ///< set for `certified` (and exact: [v, v])
  std::string method;                     ///< e.g. "closed form (44)", "Sturm isolation"
  std::string note;                       ///< reason for `failed`, or caveats

  static Certified exact_value(T v, std::string how) {
    Certified r;
    r.enclosure = Enclosure<T>{v, v};
    r.value = std::move(v);
    r.status = Status::exact;
    r.method = std::move(how);
    return r;
  }
  static Certified certified_value(T v, Enclosure<T> e, std::string how) {
    Certified r;
    r.value = std::move(v);
    r.enclosure = std::move(e);
    r.status = Status::certified;
    r.method = std::move(how);
    return r;
  }
  static Certified numeric_value(T v, std::string how) {
    Certified r;
    r.value = std::move(v);
    r.status = Status::numeric;
    r.method = std::move(how);
    return r;
  }
};

/// The answer to a yes/no question: holds, fails, or undecided (the computation could not tell).
enum class Outcome { holds, fails, undecided };

inline const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::holds: return "holds";
    case Outcome::fails: return "fails";
    case Outcome::undecided: return "undecided";
  }
  return "undecided";
}

/// Outcome + how it is known + what was computed. `status` exact: an exact (rational)
/// certificate; certified: proven by enclosures; numeric: floating point only; failed: no
/// answer (outcome undecided, reason in `evidence`).
struct Verdict {
  Outcome outcome = Outcome::undecided;
  Status status = Status::numeric;
  std::string evidence;  ///< what was proven or computed, in words

  bool holds() const { return outcome == Outcome::holds; }
  bool fails() const { return outcome == Outcome::fails; }
  bool decided() const { return outcome != Outcome::undecided; }
  /// A decided outcome with an exact or certified status.
  bool proven() const { return decided() && (status == Status::exact || status == Status::certified); }

  /// holds (true) or fails (false), with the given status.
  static Verdict of(bool holds, Status s, std::string evidence) {
    return {holds ? Outcome::holds : Outcome::fails, s, std::move(evidence)};
  }
};

}  // namespace hapstab
