// hapstab/check/affine.hpp -- the checkers' proof that an expression H(z) as written is affine in
// one of its parameters K: H = H0 + K H1 for every K (bound-max and stability-max certificates).
//
// Theorem: with H = P(K, z)/Q(K, z), the parser's degree bounds (dn, dd) of the expression in K
// (ParsedExpression::degree_bound, lti/parse.hpp: a name is (1, 0), a sum (max(n1 + d2, n2 + d1),
// d1 + d2), a product adds, a quotient crosses, a power multiplies) bound the numerator of
// H - H0 - K H1 by D = max(dn, dd + 1) in K. With H0 = H(0), H1 = H(1) - H(0), and
// H(k) = H0 + k H1 exactly at D - 1 more values k where the expression is defined (a parse that
// divides by zero at k is skipped: a rational function of K is evaluated exactly wherever the
// parse succeeds), that numerator has D + 1 roots and vanishes: H = H0 + K H1 for every K. The
// checker's own loop (not split_affine, which the producers call). Never sampled: proven.
#pragma once

#include <string>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

struct Affine {
  RationalFunction<rational> H0{Polynomial<rational>(rational(0))}, H1{Polynomial<rational>(rational(0))};
  long D = 0;  ///< the degree bound in K that the values proved
};

/// H = H0 + K H1 for the expression `text` parsed with `po` (K not among po.parameters), proven as
/// above. InputError naming model.H when it is not proven affine (a degree bound above 64, a value
/// where H(k) != H0 + k H1, undefined at too many values) or does not depend on K.
Affine prove_affine(const std::string& text, ParseOptions po, const std::string& K);

}  // namespace hapstab::check::detail
