// Plugins: shared libraries that add BSDF models to the material registry at run time, so that a
// model written outside scatterlab gets everything a built-in one has (`scatterlab check`,
// `render`, `lab`, `fit`, `models`), with the same parameter specs, ranges, defaults and error
// messages (docs/own-bsdf.md; examples/own-bsdf is a complete plugin).
//
// A plugin is a shared library (CMake: add_library(NAME MODULE ...) linked to
// scatterlab::materials) with one translation unit that says
//
//     void registerModels(scatterlab::PluginRegistrar& registrar) {
//       registrar.addModel({.type = "my-model", ..., .build = buildMyModel});
//     }
//     SCATTERLAB_PLUGIN(registerModels)
//
// `scatterlab COMMAND --plugin LIB.so` (or SCATTERLAB_PLUGIN_PATH) loads it before anything
// reads the registry. The loader first compares the plugin's ABI stamp with its own and refuses a
// plugin built against another scatterlab, standard library or JSON library (exit 2).
//
// What a plugin's model must satisfy (checkPluginModel): a BSDF model (kind Bsdf) with a build
// function, a type no other model has, and a default for every parameter (a set of alternatives
// other than the first aside), so that {"type": "my-model"} is a complete material. Its calls are
// guarded (plugin_bsdf.h): an exception from the plugin becomes a PluginError naming the model,
// the library, the call and its arguments; a NaN it returns is counted by the checks and the
// renderer like any model's.
#pragma once

#include <stdexcept>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "materials/registry/material_model.h"
#include "materials/registry/version.h"

namespace scatterlab {

// The version of the plugin interface (PluginRegistrar, MaterialModel, the entry points below).
inline constexpr int PluginInterfaceVersion = 2;

// What a plugin and the scatterlab loading it must agree on to share C++ objects: this interface,
// scatterlab's version, the standard library's ABI, the JSON and GLM versions, and the sizes of the
// objects that cross the boundary. Compiled into both sides (hidden, so a plugin never sees the
// loader's copy) and compared as text.
[[gnu::visibility("hidden")]] inline std::string pluginAbiStamp() {
  std::string stamp = "scatterlab plugin interface " + std::to_string(PluginInterfaceVersion) +
                      ", scatterlab " SCATTERLAB_VERSION_STRING;
#if defined(_GLIBCXX_RELEASE)
  stamp += ", libstdc++ " + std::to_string(_GLIBCXX_RELEASE) +
           (_GLIBCXX_USE_CXX11_ABI ? " (C++11 string ABI)" : " (old string ABI)");
#elif defined(_LIBCPP_VERSION)
  stamp += ", libc++ ABI " + std::to_string(_LIBCPP_ABI_VERSION);
#endif
  stamp += ", nlohmann_json " + std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
           std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." + std::to_string(NLOHMANN_JSON_VERSION_PATCH);
  stamp += ", glm " + std::to_string(GLM_VERSION);
  stamp += ", object sizes " + std::to_string(sizeof(MaterialModel)) + "/" +
           std::to_string(sizeof(ParameterSpec)) + "/" + std::to_string(sizeof(MaterialParameters)) + "/" +
           std::to_string(sizeof(nlohmann::json)) + "/" + std::to_string(sizeof(BsdfSample));
  return stamp;
}

// What the loader hands a plugin's registration function. Abstract, so that a call from the
// plugin runs the loader's code (a plugin links its own copy of scatterlab::materials, whose
// registry is not the one the commands read).
class PluginRegistrar {
 public:
  // Adds a BSDF model. Throws MaterialError when checkPluginModel refuses it or its type exists.
  virtual void addModel(MaterialModel model) = 0;

 protected:
  ~PluginRegistrar() = default;
};

// A plugin's failure at run time (it threw, or built no model): the message names the model, the
// library and the call. A MaterialError, so that the command line reports it as bad input (exit 2).
class PluginError : public MaterialError {
 public:
  using MaterialError::MaterialError;
};

// Checks a plugin's model before it is added (see the top of this file); throws MaterialError
// naming the model and what is wrong.
void checkPluginModel(const MaterialModel& model);

// The names of a plugin's two entry points (SCATTERLAB_PLUGIN defines them).
inline constexpr const char* PluginAbiSymbol = "scatterlab_plugin_abi";
inline constexpr const char* PluginRegisterSymbol = "scatterlab_plugin_register";
using PluginAbiFunction = const char* (*)();
using PluginRegisterFunction = void (*)(PluginRegistrar&);

}  // namespace scatterlab

// Defines a plugin's entry points: its ABI stamp, and `registerFunction`
// (void(scatterlab::PluginRegistrar&)) as its registration. Use once, in one source file.
#define SCATTERLAB_PLUGIN(registerFunction)                                               \
  extern "C" __attribute__((visibility("default"))) const char* scatterlab_plugin_abi() { \
    static const std::string stamp = ::scatterlab::pluginAbiStamp();                      \
    return stamp.c_str();                                                                 \
  }                                                                                       \
  extern "C" __attribute__((visibility("default"))) void scatterlab_plugin_register(      \
      ::scatterlab::PluginRegistrar& registrar) {                                         \
    registerFunction(registrar);                                                          \
  }
