#include "materials/registry/plugin.h"

#include <algorithm>

#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

// True when `name` is in a set of alternatives other than the first, whose defaults apply when
// a material gives none (spec_validation.h): such a parameter needs no default of its own.
bool isInLaterAlternative(const MaterialModel& model, const std::string& name) {
  for (size_t set = 1; set < model.alternatives.size(); ++set)
    if (std::find(model.alternatives[set].begin(), model.alternatives[set].end(), name) !=
        model.alternatives[set].end())
      return true;
  return false;
}

// The number of fit-kernel slots of a model (material_model.h FitKernelFunction): 1 per number,
// 3 per rgb, 2 per pair parameter.
int numericSlots(const MaterialModel& model) {
  int slots = 0;
  for (const ParameterSpec& spec : model.parameters)
    slots += spec.kind == ParameterKind::Number ? 1
             : spec.kind == ParameterKind::Rgb  ? 3
             : spec.kind == ParameterKind::Pair ? 2
                                                : 0;
  return slots;
}

[[noreturn]] void refuse(const MaterialModel& model, const std::string& problem, const std::string& allowed) {
  throw MaterialError("model " + inQuotes(model.type) + ": " + problem + "; allowed: " + allowed);
}

}  // namespace

void checkPluginModel(const MaterialModel& model) {
  if (model.kind != MaterialKind::Bsdf)
    refuse(model, "a plugin's model is a subsurface material", "BSDF models (kind Bsdf)");
  for (const ParameterSpec& spec : model.parameters)
    if ((spec.defaultValue.is_null() || spec.required) && !isInLaterAlternative(model, spec.name))
      refuse(model, "parameter " + inQuotes(spec.name) + " has no default",
             "a default for every parameter of a plugin's model, so that {\"type\": " + inQuotes(model.type) +
                 "} is a complete material");
  checkModelSpec(model);
  if (model.fitKernel && model.fitKernel.slots != numericSlots(model))
    refuse(model,
           "its fit kernel reads " + std::to_string(model.fitKernel.slots) + " values, its spec has " +
               std::to_string(numericSlots(model)),
           "a kernel over the number (1 value), rgb (3) and pair (2) parameters, in the spec's order");
}

}  // namespace scatterlab
