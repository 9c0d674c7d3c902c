// hapstab/lti/tf.hpp -- SISO transfer functions with exact rational coefficients, in s
// (continuous) or z (discrete, sample period T > 0). Name after python-control's `tf`.
//
// The coefficients are exact (`rational`): "0.001" in an expression is 1/1000. The rational
// function is kept reduced (common factors cancelled, monic denominator), so a pole that
// cancels (e.g. (z-1)/(z-1)) is gone before any analysis looks at it.
#pragma once

#include <string>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab {

enum class Domain { s, z };

struct TransferFunction {
  RationalFunction<rational> H{Polynomial<rational>()};  ///< in the variable s or z (default 0)
  Domain domain = Domain::z;
  rational T = 0;  ///< sample period (z only; 0 for s)

  const Polynomial<rational>& num() const { return H.num(); }
  const Polynomial<rational>& den() const { return H.den(); }
  bool is_discrete() const { return domain == Domain::z; }
  /// deg num <= deg den. For z this is causality; for s, properness.
  bool is_proper() const { return num().degree() <= den().degree(); }
  /// deg den - deg num (negative for an improper/non-causal transfer function).
  int relative_degree() const { return den().degree() - num().degree(); }
  const char* variable() const { return domain == Domain::z ? "z" : "s"; }
  /// "(1001 z - 1000)/(z)" style rendering with exact coefficients.
  std::string to_string() const;
};

/// The factor of `written` (a denominator as the user wrote it: --num/--den's, det(zI - A) of a
/// state space, an expression's before an operation reduced it) that `reduced` (the denominator in
/// lowest terms, which divides it) lost, when one of its roots lies on or outside the stable region
/// (|z| >= 1 in z, Re s >= 0 in s): realised as written, a hidden mode that makes any loop NOT
/// stable, which hapstab does not reduce away silently (callers refuse the input by name). The zero
/// polynomial when every lost root is inside (a hidden stable mode, which changes no verdict).
Polynomial<rational> unstable_cancelled_factor(const Polynomial<rational>& written, const Polynomial<rational>& reduced,
                                               Domain domain);

/// tf(num, den, T): discrete when T > 0, continuous when T == 0. Throws InputError on a zero
/// denominator or T < 0.
TransferFunction tf(Polynomial<rational> num, Polynomial<rational> den, const rational& T = 0);

// Interconnections (python-control names). Operands must share domain and T.
TransferFunction series(const TransferFunction& a, const TransferFunction& b);    ///< a*b
TransferFunction parallel(const TransferFunction& a, const TransferFunction& b);  ///< a+b
/// Negative feedback a/(1 + a b) (sign = +1 gives positive feedback a/(1 - a b)).
TransferFunction feedback(const TransferFunction& a, const TransferFunction& b, int sign = -1);

}  // namespace hapstab
