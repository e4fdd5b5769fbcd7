// Plugins that the loader must refuse with one clear message (exit 2), one per build of this
// file (plugins.cmake defines one of):
//  BAD_PLUGIN_WRONG_ABI        its ABI stamp is not the loader's (built against another scatterlab)
//  BAD_PLUGIN_DUPLICATE        it registers "phong", a built-in type
//  BAD_PLUGIN_NO_DEFAULT       a parameter of its model has no default
//  BAD_PLUGIN_THROWS           its registration throws
//  BAD_PLUGIN_NOT_A_PLUGIN     a shared library without the entry points
//  BAD_PLUGIN_NO_REGISTER      the right ABI stamp but no registration entry point
#include <memory>
#include <stdexcept>

#include "materials/bsdf/lambertian.h"
#include "materials/registry/plugin.h"

namespace {

using namespace scatterlab;

[[maybe_unused]] std::unique_ptr<BsdfModel> buildLambertian(const MaterialParameters&) {
  return std::make_unique<LambertianBsdf>(Rgb(0.5));
}

[[maybe_unused]] MaterialModel model(std::string type, nlohmann::json albedoDefault) {
  MaterialModel m{.type = std::move(type),
                  .description = "bad test plugin",
                  .citation = "tests/app/plugins/bad_plugin.cpp",
                  .parameters = {numberParameter("albedo", ValueRange::closed(0.0, 1.0), 0.5, "albedo")},
                  .build = buildLambertian};
  m.parameters[0].defaultValue = std::move(albedoDefault);
  return m;
}

[[maybe_unused]] void registerModels(PluginRegistrar& registrar) {
#if defined(BAD_PLUGIN_DUPLICATE)
  registrar.addModel(model("phong", 0.5));
#elif defined(BAD_PLUGIN_NO_DEFAULT)
  registrar.addModel(model("no-default-lobe", nullptr));
#elif defined(BAD_PLUGIN_THROWS)
  (void)registrar;
  throw std::runtime_error("deliberate failure while registering");
#else
  registrar.addModel(model("wrong-abi-lobe", 0.5));
#endif
}

}  // namespace

#if defined(BAD_PLUGIN_WRONG_ABI)
// The entry points SCATTERLAB_PLUGIN defines, with the stamp of a scatterlab that does not exist.
extern "C" __attribute__((visibility("default"))) const char* scatterlab_plugin_abi() {
  return "scatterlab plugin interface 0, scatterlab 0.0.0";
}
extern "C" __attribute__((visibility("default"))) void scatterlab_plugin_register(
    PluginRegistrar& registrar) {
  registerModels(registrar);
}
#elif defined(BAD_PLUGIN_NOT_A_PLUGIN)
extern "C" __attribute__((visibility("default"))) int not_a_scatterlab_plugin() { return 0; }
#elif defined(BAD_PLUGIN_NO_REGISTER)
// Half of what SCATTERLAB_PLUGIN defines: the stamp matches, the registration is missing.
extern "C" __attribute__((visibility("default"))) const char* scatterlab_plugin_abi() {
  static const std::string stamp = pluginAbiStamp();
  return stamp.c_str();
}
#else
SCATTERLAB_PLUGIN(registerModels)
#endif
