// Adaptive quadrature, shared by models that need an integral of their own (diffuse Fresnel
// reflectance, energy tables) and by the test kit: expected chi-square counts, pdf normalisation and
// directional albedo are integrals of model functions over cells of the sphere.
//
// Nested adaptive Simpson (Lyness 1969 error estimate, Richardson-corrected), the scheme
// pbrt-v3/v4's chi-square tests use, with three changes that matter for narrow lobes:
//  - a minimum depth, so a cell is never accepted from its five initial points alone;
//  - a deep maximum depth (a GGX alpha 0.001 lobe is 1e-6 wide in cos(theta));
//  - an absolute tolerance floor, so empty cells do not refine forever chasing round-off.
// Values may be scalars or fixed-size vectors (glm::dvec4 to integrate pdf and f|cos| in one
// pass); the error of a vector is its largest component.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace scatterlab {

struct QuadratureOptions {
  double relativeTolerance = 1e-6;
  double absoluteTolerance = 1e-12;
  int minDepth = 2;
  int maxDepth = 24;
};

inline double quadratureErrorNorm(double v) { return std::abs(v); }
template <int N> double quadratureErrorNorm(const glm::vec<N, double>& v) {
  double m = 0;
  for (int i = 0; i < N; ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

// Componentwise |v|, for error estimates of vector integrals.
inline double quadratureAbs(double v) { return std::abs(v); }
template <int N> glm::vec<N, double> quadratureAbs(const glm::vec<N, double>& v) { return glm::abs(v); }

// An integral and the quadrature's own estimate of its error, per component: the sum over the
// accepted intervals of |S(left) + S(right) - S(whole)| / 15, Lyness's estimate of the error of
// the two-panel Simpson sum (the returned value also carries the Richardson correction, so it
// is usually far more accurate than this bound says). Intervals accepted at maxDepth count
// with their estimate like any other.
template <typename V> struct QuadratureEstimate {
  V value;
  V error;
};

namespace detail {

template <typename F, typename V>
V adaptiveSimpsonStep(const F& f, double a, double b, const V& fa, const V& fm, const V& fb, const V& whole,
                      double tolerance, int depth, const QuadratureOptions& options, V& error) {
  const double m = 0.5 * (a + b);
  const V flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
  const V left = ((m - a) / 6.0) * (fa + 4.0 * flm + fm);
  const V right = ((b - m) / 6.0) * (fm + 4.0 * frm + fb);
  const V delta = left + right - whole;
  if (depth >= options.maxDepth || quadratureErrorNorm(delta) <= 15.0 * tolerance) {
    error = error + quadratureAbs(delta) / 15.0;
    return left + right + delta / 15.0;
  }
  const double half = 0.5 * tolerance;
  // Left half first, as its own statement: the order in which `error` accumulates is then the
  // same on every compiler (the operands of an overloaded + are evaluated in an unspecified order,
  // right first with gcc, left first with clang), and validation/batched_quadrature.h can repeat it.
  const V leftIntegral = adaptiveSimpsonStep(f, a, m, fa, flm, fm, left, half, depth + 1, options, error);
  return leftIntegral + adaptiveSimpsonStep(f, m, b, fm, frm, fb, right, half, depth + 1, options, error);
}

// The inner integrals of adaptiveSimpson2D carry their own error estimates through the outer
// quadrature, which adapts to the values alone.
template <typename V> struct WithInnerError {
  V value, innerError;
  WithInnerError() : value(0.0), innerError(0.0) {}
  explicit WithInnerError(double x) : value(x), innerError(0.0) {}
  WithInnerError(const V& v, const V& e) : value(v), innerError(e) {}
  friend WithInnerError operator+(const WithInnerError& a, const WithInnerError& b) {
    return {a.value + b.value, a.innerError + b.innerError};
  }
  friend WithInnerError operator-(const WithInnerError& a, const WithInnerError& b) {
    return {a.value - b.value, a.innerError - b.innerError};
  }
  friend WithInnerError operator*(double s, const WithInnerError& a) {
    return {s * a.value, s * a.innerError};
  }
  friend WithInnerError operator/(const WithInnerError& a, double s) {
    return {a.value / s, a.innerError / s};
  }
};
template <typename V> double quadratureErrorNorm(const WithInnerError<V>& v) {
  return scatterlab::quadratureErrorNorm(v.value);
}
template <typename V> WithInnerError<V> quadratureAbs(const WithInnerError<V>& v) {
  return {scatterlab::quadratureAbs(v.value), scatterlab::quadratureAbs(v.innerError)};
}

}  // namespace detail

// Integral of f over [a, b] and its error estimate. [a, b] is first cut into 2^minDepth equal
// pieces; their Simpson sum is the coarse estimate that the relative tolerance refers to (an
// estimate from 3 points could have missed the lobe entirely). Each piece then refines on its
// own share.
template <typename F>
auto adaptiveSimpsonEstimate(const F& f, double a, double b, const QuadratureOptions& options = {}) {
  using V = decltype(f(a));
  constexpr int MaxPieces = 64;
  const int n = std::min(1 << std::max(options.minDepth, 0), MaxPieces);
  const double h = (b - a) / n;
  V fx[MaxPieces + 1], fmid[MaxPieces], piece[MaxPieces];
  for (int i = 0; i <= n; ++i) fx[i] = f(i == n ? b : a + i * h);
  V coarse = V(0.0);
  for (int i = 0; i < n; ++i) {
    fmid[i] = f(a + (i + 0.5) * h);
    piece[i] = (h / 6.0) * (fx[i] + 4.0 * fmid[i] + fx[i + 1]);
    coarse = coarse + piece[i];
  }
  const double tolerance =
      std::max(options.relativeTolerance * quadratureErrorNorm(coarse), options.absoluteTolerance) / n;
  QuadratureEstimate<V> total{V(0.0), V(0.0)};
  for (int i = 0; i < n; ++i) {
    const double x0 = a + i * h, x1 = (i + 1 == n) ? b : a + (i + 1) * h;
    total.value =
        total.value + detail::adaptiveSimpsonStep(f, x0, x1, fx[i], fmid[i], fx[i + 1], piece[i], tolerance,
                                                  options.minDepth, options, total.error);
  }
  return total;
}

// Integral of f over [a, b] (adaptiveSimpsonEstimate without the error estimate).
template <typename F>
auto adaptiveSimpson(const F& f, double a, double b, const QuadratureOptions& options = {}) {
  return adaptiveSimpsonEstimate(f, a, b, options).value;
}

// Integral of f(x, y) over [x0, x1] x [y0, y1], as an outer integral over x of inner
// integrals over y, and its error estimate: the outer quadrature's own, plus the integral over
// x of the inner integrals' estimates. The inner tolerance is scaled so that its error summed
// over the outer interval stays within the outer tolerance.
template <typename F> auto adaptiveSimpson2DEstimate(const F& f, double x0, double x1, double y0, double y1,
                                                     const QuadratureOptions& options = {}) {
  using V = decltype(f(x0, y0));
  QuadratureOptions inner = options;
  inner.absoluteTolerance = options.absoluteTolerance / std::max(x1 - x0, 1e-300) * 0.1;
  auto integrateY = [&](double x) {
    const QuadratureEstimate<V> e = adaptiveSimpsonEstimate([&](double y) { return f(x, y); }, y0, y1, inner);
    return detail::WithInnerError<V>(e.value, e.error);
  };
  const auto outer = adaptiveSimpsonEstimate(integrateY, x0, x1, options);
  return QuadratureEstimate<V>{outer.value.value, outer.error.value + quadratureAbs(outer.value.innerError)};
}

template <typename F> auto adaptiveSimpson2D(const F& f, double x0, double x1, double y0, double y1,
                                             const QuadratureOptions& options = {}) {
  return adaptiveSimpson2DEstimate(f, x0, x1, y0, y1, options).value;
}

}  // namespace scatterlab
