// Special functions that model kernels need with T = ceres::Jet, where std:: has no overload
// (std::lgamma has none for Jets). Written with arithmetic, log and exp only, so the
// derivative comes from the same expression as the value.
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

namespace detail {
// ln Gamma(x) = stirlingSeries(z) - ln(product) after `shiftForStirling`, which moves x up to
// z >= 10 with Gamma(x) = Gamma(x + n) / (x (x + 1) ... (x + n - 1)); Stirling's series
// (Abramowitz & Stegun 6.1.41)
//   ln Gamma(z) = (z - 1/2) ln z - z + ln(2 pi) / 2 + sum_k B_2k / (2k (2k - 1) z^(2k - 1)),
// truncated after the z^-11 term, errs by less than 1 / (156 z^13) < 7e-16; what remains is
// the rounding of its ~ln Gamma(10) = 12.8 sized terms, a few 1e-15 absolute.
template <typename T> void shiftForStirling(T& x, T& product) {
  product = T(1);
  while (x < T(10)) {
    product *= x;
    x += T(1);
  }
}
template <typename T> T stirlingSeries(const T& z) {
  using std::log;
  const T inverse = T(1) / z;
  const T inverse2 = inverse * inverse;
  const T series =
      inverse *
      (T(1.0 / 12.0) -
       inverse2 * (T(1.0 / 360.0) -
                   inverse2 * (T(1.0 / 1260.0) -
                               inverse2 * (T(1.0 / 1680.0) -
                                           inverse2 * (T(1.0 / 1188.0) - inverse2 * T(691.0 / 360360.0))))));
  constexpr double HalfLog2Pi = 0.91893853320467274178;
  return (z - T(0.5)) * log(z) - z + T(HalfLog2Pi) + series;
}
}  // namespace detail

// ln Gamma(x) for x > 0, within ~1e-14 absolute (small |ln Gamma|) or relative of std::lgamma.
template <typename T> T logGamma(T x) {
  using std::log;
  T product;
  detail::shiftForStirling(x, product);
  return detail::stirlingSeries(x) - log(product);
}

// The Euler Beta function B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b) for a, b > 0, through
// Stirling's series so that large arguments do not overflow; the three shift products are
// combined outside the exponential (one exp, three logs). Written symmetrically: B(a, b) and
// B(b, a) round identically. Relative accuracy ~1e-14, and ~1e-16 (a + b) ln(a + b) for large
// arguments, from the cancellation of the series' large terms.
template <typename T> T betaFunction(T a, T b) {
  using std::exp;
  T c = a + b, productA, productB, productC;
  detail::shiftForStirling(a, productA);
  detail::shiftForStirling(b, productB);
  detail::shiftForStirling(c, productC);
  return exp((detail::stirlingSeries(a) + detail::stirlingSeries(b)) - detail::stirlingSeries(c)) *
         (productC / (productA * productB));
}

}  // namespace scatterlab
