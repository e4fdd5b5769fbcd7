#include "materials/bssrdf/dipole.h"

#include "materials/bsdf/diffuse_fresnel.h"

namespace scatterlab {

double jensenBoundaryFactor(double eta) {
  const double fdr = diffuseFresnelReflectance(1.0 / eta);
  return (1.0 + fdr) / (1.0 - fdr);
}

JensenDipoleProfile::JensenDipoleProfile(const Rgb& sigmaSPrime, const Rgb& sigmaA, double eta) {
  const double boundary = jensenBoundaryFactor(eta);
  Rgb total, meanFreePath;
  for (int c = 0; c < 3; ++c) {
    channels_[c] = makeJensenDipole(sigmaSPrime[c], sigmaA[c], boundary);
    total[c] = jensenDipoleTotal(channels_[c].alphaPrime, boundary);
    meanFreePath[c] = channels_[c].zr;
  }
  prepareSampling(total, meanFreePath);
}

}  // namespace scatterlab
