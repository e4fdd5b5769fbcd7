// Special functions the standard library lacks. ln Gamma and Beta are for model kernels with
// T = ceres::Jet, where std:: has no overload (std::lgamma has none for Jets): written with
// arithmetic, log and exp only, so the derivative comes from the same expression as the value.
// The inverse error functions (double only) invert the Beckmann distribution's slope
// distribution (materials/bsdf/microfacet.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

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

// ---- Inverse error functions (Newton on std::erf / std::erfc) ----

// Winitzki 2008, "A handy approximation for the error function and its inverse": a start
// for Newton, within 2e-3 relative over (-1, 1) including the tails. 1 - z^2 is passed as
// oneMinusZ2 so that tails given as erfc values keep their precision.
inline double erfinvInitialGuess(double z, double oneMinusZ2) {
  constexpr double a = 0.147;
  const double logTerm = std::log(oneMinusZ2);
  const double t = 2.0 / (Pi * a) + 0.5 * logTerm;
  const double y = std::sqrt(std::max(0.0, std::sqrt(t * t - logTerm / a) - t));
  return std::copysign(y, z);
}

inline double inverseErfc(double q);

// erf^-1(z) for z in (-1, 1). |z| <= 1/2: Newton on erf, which is steep there (erf' > 0.88).
// |z| > 1/2: the tail is solved as erfc^-1(1 - |z|), exact in floating point for those z, so
// that the answer is not limited by the rounding of z near +-1.
inline double erfinv(double z) {
  if (std::abs(z) > 0.5) return std::copysign(inverseErfc(1.0 - std::abs(z)), z);
  double y = erfinvInitialGuess(z, (1.0 - z) * (1.0 + z));
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double step = (std::erf(y) - z) / (2.0 / SqrtPi * std::exp(-y * y));
    y -= step;
    if (std::abs(step) <= 1e-15 * std::abs(y)) break;
  }
  return y;
}

// erfc^-1(q) for q in (0, 2); q is clamped to [DBL_MIN, 2 - DBL_MIN], so the answer stays
// finite (|y| <= ~26.5, where erfc underflows). For q < 1/2 the equation log erfc(y) = log q
// is solved by Newton inside the bracket [erfc^-1(1/2), 27]: log erfc is concave and close to
// quadratic, so Newton converges in a few steps even for q = 1e-300.
inline double inverseErfc(double q) {
  q = std::clamp(q, std::numeric_limits<double>::min(), 2.0 - std::numeric_limits<double>::min());
  if (q > 1.0) return -inverseErfc(2.0 - q);
  if (q >= 0.5) return erfinv(1.0 - q);
  double lo = 0.4769362762044698, hi = 27.0;  // erfc(lo) = 1/2 > q > erfc(27)
  double y = std::clamp(erfinvInitialGuess(1.0, q * (2.0 - q)), lo, hi);
  const double logQ = std::log(q);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double e = std::erfc(y);
    const double excess = std::log(e) - logQ;  // decreasing in y
    if (excess > 0)
      lo = y;
    else
      hi = y;
    const double slope = -2.0 / SqrtPi * std::exp(-y * y) / e;
    const double newton = y - excess / slope;
    // Tested before the bracket: a converged step may land on the bracket's end.
    if (std::abs(newton - y) <= 1e-15 * y) return newton;
    y = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    if (hi - lo <= 1e-15 * y) break;
  }
  return y;
}

}  // namespace scatterlab
