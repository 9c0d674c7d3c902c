// A small program built against the installed hapstab package (find_package(hapstab)).
// It parses a virtual wall H(z) = K + B (z-1)/(T z) exactly and prints the exact real part
// of T H(z)/(1 - z) on the unit circle as a rational function of t = tan(wT/2) -- the
// quantity whose maximum over w is the passivity bound (paper 001, (45)) -- and its values
// at t -> 0 (w -> 0) and t -> infinity (wT -> pi).
#include <hapstab/lti/parse.hpp>
#include <hapstab/numeric/decimal.hpp>
#include <hapstab/poly/unit_circle.hpp>
#include <iostream>

int main() {
  using namespace hapstab;
  ParseOptions opt;
  opt.T = rational(1, 1000);
  opt.parameters = {{"K", rational(1000)}, {"B", rational(5)}};
  TransferFunction H = parse_tf("K + B*(z-1)/(T*z)", opt);
  // T/(1 - z) on the unit circle = T/2 + j T/(2t); objective = (T/2) Re H - T/(2t) Im H.
  ReIm parts = on_unit_circle(H.H);
  RationalFunction<rational> half_T(Polynomial<rational>(opt.T / 2));
  RationalFunction<rational> over_t(Polynomial<rational>(rational(1)), Polynomial<rational>::monomial(1));
  RationalFunction<rational> objective = half_T * parts.re - half_T * over_t * parts.im;
  std::cout << "H(z) = " << H.to_string() << "\n";
  std::cout << "Re{T H/(1-z)}(t) = (" << to_string(objective.num(), "t") << ")/(" << to_string(objective.den(), "t")
            << ")\n";
  std::cout << "at w -> 0:     " << to_decimal(objective(rational(0)), 20) << "\n";
  const auto& n = objective.num();
  const auto& d = objective.den();
  rational at_pi = n.degree() == d.degree() ? n.leading() / d.leading() : rational(0);
  std::cout << "at wT -> pi:   " << to_decimal(at_pi, 20) << "   (closed form KT/2 + B = 5.5)\n";
  return at_pi == rational(11, 2) ? 0 : 1;
}
