// A plugin (materials/registry/plugin.h) of models for the command-line tests of plugins:
//  - "numeric-phong": the example's Phong lobe (examples/own-bsdf) registered without a fit
//    kernel, so `scatterlab fit` differentiates it numerically;
//  - "throwing-lobe": the same lobe whose eval throws, which a command must report (exit 2);
//  - "nan-lobe": the same lobe whose eval returns NaN, which the checks must fail and the
//    renderer must count, without a crash.
#include <limits>
#include <memory>
#include <stdexcept>

#include "example_phong.h"  // examples/own-bsdf
#include "materials/registry/plugin.h"

namespace {

using namespace scatterlab;
using own_bsdf::ExamplePhong;

// How a test model misbehaves.
enum class Fault { None, Throws, NaN };

template <Fault F> class FaultyPhong final : public BsdfModel {
 public:
  FaultyPhong(const Rgb& ks, double exponent) : lobe_(ks, exponent) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    if constexpr (F == Fault::Throws) throw std::runtime_error("deliberate failure of the test plugin");
    if constexpr (F == Fault::NaN) return Rgb(std::numeric_limits<double>::quiet_NaN());
    return lobe_.eval(wi, wo, mode);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return lobe_.pdf(wi, wo, mode);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    auto s = lobe_.sample(wi, uLobe, u, mode);
    if (s) s->weight = eval(wi, s->wo, mode) * (s->wo.z / s->pdf);
    return s;
  }
  LobeFlags flags() const override { return lobe_.flags(); }

 private:
  ExamplePhong lobe_;
};

template <typename Model> std::unique_ptr<BsdfModel> build(const MaterialParameters& p) {
  return std::make_unique<Model>(p.rgb("ks"), p.number("exponent"));
}

MaterialModel lobeModel(std::string type, BuildBsdfFunction buildFunction) {
  return {
      .type = std::move(type),
      .description = "test plugin lobe",
      .citation = "tests/app/plugins/test_plugin_models.cpp",
      .parameters = {numberParameter("exponent", ValueRange::closed(0.0, 10000.0), 30.0, "Phong exponent n"),
                     rgbParameter("ks", 0.8, "specular albedo")},
      .build = buildFunction,
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false};
}

void registerModels(PluginRegistrar& registrar) {
  registrar.addModel(lobeModel("numeric-phong", build<FaultyPhong<Fault::None>>));
  registrar.addModel(lobeModel("throwing-lobe", build<FaultyPhong<Fault::Throws>>));
  registrar.addModel(lobeModel("nan-lobe", build<FaultyPhong<Fault::NaN>>));
}

}  // namespace

SCATTERLAB_PLUGIN(registerModels)
