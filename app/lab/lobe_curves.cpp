#include "app/lab/lobe_curves.h"

#include <cmath>

#include "materials/core/spherical.h"

namespace scatterlab {

double rec709Luminance(const Rgb& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

LobeCurve lobeInPlaneOfIncidence(const BsdfModel& model, double thetaInDeg, double phiDeg, int directions) {
  LobeCurve curve;
  curve.thetaInDeg = thetaInDeg;
  const Vec3d wi = directionFromDegrees(thetaInDeg, phiDeg);
  const double limit = hasAny(model.flags(), LobeFlags::Transmission) ? 180.0 : 90.0;
  const double phiOut = (phiDeg + 180.0) * Pi / 180.0;
  for (int k = 0; k < directions; ++k) {
    const double t = -limit + 2.0 * limit * k / std::max(directions - 1, 1);
    const double tRad = t * Pi / 180.0;
    const Vec3d wo(std::sin(tRad) * std::cos(phiOut), std::sin(tRad) * std::sin(phiOut), std::cos(tRad));
    curve.thetaOutDeg.push_back(t);
    curve.value.push_back(model.eval(wi, wo, TransportMode::Radiance));
  }
  return curve;
}

}  // namespace scatterlab
