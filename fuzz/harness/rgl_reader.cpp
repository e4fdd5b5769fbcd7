// Fuzz harness (fuzz/harness/harness.h): an RGL .bsdf file (materials/measured/tensor_file.h,
// rgl_brdf.h): the tensor_file reader on the bytes, then the RGL model built from what it read
// (every field's name, dtype, shape and values validated), then one evaluation, pdf and sample,
// which must be finite for a file the reader accepted.
#include <cmath>
#include <cstdlib>

#include "fuzz/harness/harness.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/measured/tensor_file.h"

namespace scatterlab::fuzz {

void rglReader(Input data) {
  try {
    const TensorFile file = parseTensorFile(std::as_bytes(data), "fuzz.bsdf");
    const RglBrdf brdf(file, "fuzz.bsdf");
    const Vec3d wi(0.0, 0.6, 0.8), wo(0.6, 0.0, 0.8);  // unit vectors above the surface
    const Rgb f = brdf.eval(wi, wo);
    const double pdf = brdf.pdf(wi, wo);
    if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z) || !std::isfinite(pdf))
      std::abort();
    if (const auto s = brdf.sample(wi, 0.5, Vec2d(0.3, 0.7)))
      if (!std::isfinite(s->weight.x) || !std::isfinite(s->pdf)) std::abort();
  } catch (const TensorFileError&) {}
}

}  // namespace scatterlab::fuzz
