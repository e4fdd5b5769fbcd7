#include "materials/registry/plugin_bsdf.h"

#include <cstdio>
#include <exception>
#include <string>

#include "materials/registry/plugin.h"

namespace scatterlab {

namespace {

std::string formatVector(const Vec3d& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
  return buffer;
}

std::string modeName(TransportMode mode) {
  return mode == TransportMode::Radiance ? "radiance" : "importance";
}

std::string pairCall(const char* function, const Vec3d& wi, const Vec3d& wo, TransportMode mode) {
  return std::string(function) + "(wi = " + formatVector(wi) + ", wo = " + formatVector(wo) + ", " +
         modeName(mode) + ")";
}

// The exception being handled, in words.
std::string currentExceptionText() {
  try {
    throw;
  } catch (const std::exception& error) {
    return error.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

[[noreturn]] void throwPluginFailure(const MaterialModel& entry, const std::string& call,
                                     const std::string& what) {
  throw PluginError("plugin model " + inQuotes(entry.type) + " (" + entry.plugin + "): " + call + " " + what +
                    "; a plugin's functions must return a value (fix the plugin)");
}

}  // namespace

std::unique_ptr<BsdfModel> buildPluginBsdf(const MaterialModel& model, const MaterialParameters& parameters) {
  std::unique_ptr<BsdfModel> built;
  try {
    built = model.build(parameters);
  } catch (const MaterialError&) {
    throw;
  } catch (...) {
    throwPluginFailure(model, "build", "threw: " + currentExceptionText());
  }
  if (!built) throwPluginFailure(model, "build", "returned no model");
  return std::make_unique<PluginBsdf>(std::move(built), model);
}

PluginBsdf::PluginBsdf(std::unique_ptr<BsdfModel> model, const MaterialModel& entry)
    : model_(std::move(model)), entry_(&entry) {}

template <typename Call, typename Describe> auto PluginBsdf::guarded(Call&& call, Describe&& what) const {
  try {
    return call();
  } catch (...) {
    throwPluginFailure(*entry_, what(), "threw: " + currentExceptionText());
  }
}

Rgb PluginBsdf::eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const {
  return guarded([&] { return model_->eval(wi, wo, mode); }, [&] { return pairCall("eval", wi, wo, mode); });
}

double PluginBsdf::pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const {
  return guarded([&] { return model_->pdf(wi, wo, mode); }, [&] { return pairCall("pdf", wi, wo, mode); });
}

std::optional<BsdfSample> PluginBsdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                             TransportMode mode) const {
  return guarded([&] { return model_->sample(wi, uLobe, u, mode); },
                 [&] {
                   char randoms[96];
                   std::snprintf(randoms, sizeof randoms, "uLobe = %.17g, u = (%.17g, %.17g)", uLobe, u.x,
                                 u.y);
                   return "sample(wi = " + formatVector(wi) + ", " + randoms + ", " + modeName(mode) + ")";
                 });
}

LobeFlags PluginBsdf::flags() const {
  return guarded([&] { return model_->flags(); }, [] { return std::string("flags()"); });
}

bool PluginBsdf::isLossless() const {
  return guarded([&] { return model_->isLossless(); }, [] { return std::string("isLossless()"); });
}

double PluginBsdf::losslessAccuracy() const {
  return guarded([&] { return model_->losslessAccuracy(); },
                 [] { return std::string("losslessAccuracy()"); });
}

bool PluginBsdf::isReciprocal() const {
  return guarded([&] { return model_->isReciprocal(); }, [] { return std::string("isReciprocal()"); });
}

double PluginBsdf::interiorIndex() const {
  return guarded([&] { return model_->interiorIndex(); }, [] { return std::string("interiorIndex()"); });
}

}  // namespace scatterlab
