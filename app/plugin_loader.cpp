#include "app/plugin_loader.h"

#include <dlfcn.h>

#include <set>
#include <vector>

#include "app/exit_code.h"
#include "materials/registry/model_list.h"
#include "materials/registry/plugin.h"

namespace scatterlab {

namespace {

namespace fs = std::filesystem;

constexpr const char* PluginAllowed =
    "a shared library built against this scatterlab that defines SCATTERLAB_PLUGIN (docs/own-bsdf.md, "
    "examples/own-bsdf)";

// The registrar a plugin's registration function calls: checks each model and adds it to the
// registry under the library's name.
class LibraryRegistrar final : public PluginRegistrar {
 public:
  explicit LibraryRegistrar(std::string library) : library_(std::move(library)) {}

  void addModel(MaterialModel model) override {
    model.plugin = library_;
    checkPluginModel(model);
    addMaterialModel(std::move(model));
    ++added_;
  }
  int added() const { return added_; }

 private:
  std::string library_;
  int added_ = 0;
};

std::string describe(const std::string& source, const fs::path& library) {
  return source + " " + inQuotes(library.string());
}

}  // namespace

void loadPlugin(const fs::path& library, const std::string& source) {
  static std::set<fs::path> loaded;
  const std::string where = describe(source, library);
  std::error_code error;
  if (!fs::is_regular_file(library, error))
    throw InputError(where + ": " + (fs::exists(library, error) ? "is not a file" : "no such file") +
                     "; allowed: " + PluginAllowed);
  const fs::path canonical = fs::canonical(library, error);
  if (error) throw InputError(where + ": cannot resolve the path (" + error.message() + ")");
  if (loaded.count(canonical)) return;

  // RTLD_LOCAL: the plugin's symbols (its own copy of scatterlab::materials) stay its own.
  // Never closed: its models' code must live as long as the registry.
  void* handle = dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror();
    throw InputError(where + ": cannot be loaded (" + std::string(reason ? reason : "unknown reason") +
                     "); allowed: " + PluginAllowed);
  }
  const auto abi = reinterpret_cast<PluginAbiFunction>(dlsym(handle, PluginAbiSymbol));
  const auto registerModels = reinterpret_cast<PluginRegisterFunction>(dlsym(handle, PluginRegisterSymbol));
  if (!abi || !registerModels) {
    dlclose(handle);
    throw InputError(where + ": is not a scatterlab plugin (no " +
                     (abi ? PluginRegisterSymbol : PluginAbiSymbol) + " symbol); allowed: " + PluginAllowed);
  }
  const std::string expected = pluginAbiStamp();
  // Copied before anything else: the text lives in the plugin, which dlclose unmaps.
  const char* stampText = abi();
  const std::string stamp = stampText ? stampText : "(no stamp)";
  if (!stampText || expected != stamp) {
    dlclose(handle);
    throw InputError(where + ": was built for " + inQuotes(stamp) +
                     ", this scatterlab is " + inQuotes(expected) +
                     "; allowed: a plugin rebuilt against this installation of scatterlab");
  }
  loaded.insert(canonical);

  LibraryRegistrar registrar(canonical.string());
  try {
    registerModels(registrar);
  } catch (const MaterialError& refused) {
    throw MaterialError(where + ": " + refused.what());
  } catch (const std::exception& thrown) {
    throw InputError(where + ": its registration threw: " + std::string(thrown.what()));
  } catch (...) {
    throw InputError(where + ": its registration threw an exception that is not a std::exception");
  }
  if (registrar.added() == 0)
    throw InputError(where + ": registered no model; allowed: a plugin that adds at least one model");
}

}  // namespace scatterlab
