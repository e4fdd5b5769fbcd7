// sl.profile (docs/python.md, "Subsurface profiles"): `scatterlab profile` without printing, the
// document --json prints as a dict (app/profile_command.h profileReport): a subsurface material's
// radial profile per channel in annuli, with --reference walk the random-walk reference beside
// it, with --compare every profile model against one walk.
#include "app/profile_command.h"
#include "python/src/bindings.h"
#include "python/src/command_options.h"
#include "python/src/json_conversion.h"

namespace scatterlab::python {

namespace py = pybind11;

void bindProfile(py::module_& module) {
  module.def(
      "_profile",
      [](const std::string& material, const py::dict& keywords, bool progress) {
        ProfileCommandOptions options;
        CommandOptions command("sl.profile", [&](CLI::App& app) { return addProfileCommand(app, options); },
                               {"json"});
        command.parse(keywords, {material});
        return pythonFromJson(command.run([&] { return profileReport(options, progress); }));
      },
      py::arg("material"), py::arg("keywords"), py::arg("progress"),
      "`scatterlab profile MATERIAL --KEYWORD=VALUE...` as the dict --json prints; see sl.profile");
}

}  // namespace scatterlab::python
