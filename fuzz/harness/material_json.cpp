// Fuzz harness (fuzz/harness/harness.h): a material description. The first byte chooses the
// model whose "type" the description gets (byte i < the number of models: materialModels()[i],
// so every registry type is reached; a larger byte keeps the type the JSON gives), the rest is
// the JSON text. A description the registry accepts is built and evaluated at fixed
// directions: its values must be finite.
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "fuzz/harness/harness.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/json_text.h"
#include "materials/core/math.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::fuzz {

namespace {

using nlohmann::json;

// Finite values, or the harness reports a finding (an accepted description must not make
// NaN or infinity: docs/reliability.md, "Messages").
void expectFinite(bool finite) {
  if (!finite) std::abort();
}

void evaluateBsdf(const BsdfModel& model) {
  const Vec3d directions[] = {normalize(Vec3d(0.0, 0.0, 1.0)), normalize(Vec3d(0.6, 0.1, 0.79)),
                              normalize(Vec3d(-0.3, 0.9, 0.05)), normalize(Vec3d(0.2, -0.4, -0.89))};
  for (const Vec3d& wi : directions) {
    for (const Vec3d& wo : directions) {
      expectFinite(isFinite(model.eval(wi, wo)));
      expectFinite(std::isfinite(model.pdf(wi, wo)));
    }
    for (const double uLobe : {0.1, 0.6, 0.95})
      if (const auto sample = model.sample(wi, uLobe, Vec2d(0.37, 0.81)))
        expectFinite(isFinite(sample->weight) && std::isfinite(sample->pdf) && isFinite(sample->wo));
  }
}

void evaluateProfile(const RadialProfile& profile) {
  expectFinite(isFinite(profile.totalReflectance()));
  for (const double r : {0.0, 1e-3, 0.1, 1.0, 10.0}) expectFinite(isFinite(profile.eval(r)));
  for (int channel = 0; channel < 3; ++channel)
    for (const double u : {0.01, 0.5, 0.99}) {
      const double r = profile.sampleRadius(channel, u);
      expectFinite(std::isfinite(r) && std::isfinite(profile.radiusPdf(channel, r)));
    }
}

}  // namespace

void materialJson(Input data) {
  if (data.empty()) return;
  const auto models = materialModels();
  const size_t choice = data[0];
  const std::string_view text(reinterpret_cast<const char*>(data.data() + 1), data.size() - 1);
  json material;
  try {
    material = parseJsonText(text, "fuzz input");
  } catch (const JsonTextError&) {
    return;
  }
  if (choice < models.size() && material.is_object()) material["type"] = models[choice].type;
  try {
    if (isSubsurfaceMaterial(material))
      evaluateProfile(*makeSubsurface(material).profile);
    else
      evaluateBsdf(*makeBsdf(material));
  } catch (const MaterialError&) {}
}

}  // namespace scatterlab::fuzz
