// Christensen & Burley 2015, "Approximate Reflectance Profiles for Efficient Subsurface
// Scattering" (Pixar Technical Memo 15-04), normalised diffusion:
//   R(r) = A (e^(-r/d) + e^(-r/(3d))) / (8 pi d r),   integral_0^inf 2 pi r R dr = A,
//   CDF F(r) = 1 - e^(-r/d) / 4 - 3 e^(-r/(3d)) / 4, inverted in closed form (u' = 1 - u,
//   G = 1 + 4 u' (2 u' + sqrt(1 + 4 u'^2)), x = 1 + G^(1/3) + G^(-1/3), r = 3 d ln(x / (4 u'))),
// with d = l / s and the shape factor s(A) from one of the paper's three Monte Carlo fits
// (mfp = 1, g = 0, half-space): burleyShapeFactor.
#pragma once

#include "materials/bssrdf/bssrdf.h"

namespace scatterlab {

// Which Monte Carlo configuration s(A) was fitted to, and what the length l in d = l / s is.
enum class BurleyFit {
  Searchlight,           // normal incidence, l = mean free path 1 / sigma_t':   s = 1.85 - A + 7 |A - 0.8|^3
  DiffuseTransmission,   // diffuse surface transmission, l = mean free path:    s = 1.9 - A + 3.5 (A - 0.8)^2
  SearchlightDiffuseMfp  // normal incidence, l = diffuse mean free path 1 / sigma_tr: s = 3.5 + 100 (A -
                         // 0.33)^4
};

template <typename T> T burleyShapeFactor(BurleyFit fit, const T& A) {
  using std::abs;
  switch (fit) {
    case BurleyFit::Searchlight: {
      const T x = abs(A - T(0.8));
      return T(1.85) - A + T(7) * x * x * x;
    }
    case BurleyFit::DiffuseTransmission: return T(1.9) - A + T(3.5) * sqr(A - T(0.8));
    case BurleyFit::SearchlightDiffuseMfp: return T(3.5) + T(100) * sqr(sqr(A - T(0.33)));
  }
  return T(1);
}

// R(r) diverges like A / (4 pi d r) at 0: radii below 1e-12 d are evaluated at 1e-12 d, so
// the value and its derivatives stay finite there.
template <typename T> T burleyProfile(const T& A, const T& d, const T& r) {
  using std::exp;
  const T rr = r > T(1e-12) * d ? r : T(1e-12) * d;
  return A * (exp(-rr / d) + exp(-rr / (T(3) * d))) / (T(8 * Pi) * d * rr);
}

// integral_0^r 2 pi r' R(r') dr' = A F(r), F written with expm1 so it keeps its relative
// precision at small r.
template <typename T> T burleyCumulative(const T& A, const T& d, const T& r) {
  using std::expm1;
  return -A * (T(0.25) * expm1(-r / d) + T(0.75) * expm1(-r / (T(3) * d)));
}

// The radius density per unit radius, 2 pi r R / A = (e^(-r/d) + e^(-r/(3d))) / (4 d).
template <typename T> T burleyRadiusPdf(const T& d, const T& r) {
  using std::exp;
  return (exp(-r / d) + exp(-r / (T(3) * d))) / (T(4) * d);
}

// F^-1(u) for u in [0, 1) (Christensen & Burley 2015, section 4.2's cubic in e^(-r/(3d))).
double burleySampleRadius(double d, double u);

class BurleyProfile final : public RadialProfile {
 public:
  // Per channel: A in [0, 1] and d > 0 (mm).
  BurleyProfile(const Rgb& albedo, const Rgb& shape);

  std::string name() const override { return "burley"; }
  Rgb eval(double r) const override;
  Rgb totalReflectance() const override { return albedo_; }
  double radiusCdf(int channel, double r) const override;
  double radiusPdf(int channel, double r) const override;
  double sampleRadius(int channel, double u) const override;

  const Rgb& shape() const { return shape_; }

 private:
  Rgb albedo_, shape_;
};

}  // namespace scatterlab
