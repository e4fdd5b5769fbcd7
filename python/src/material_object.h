// A material as the Python package holds it (docs/python.md, "Materials"): the description
// validated once into the registry's typed value, and the BSDF built from it (none for a
// subsurface material). Shared by the materials API, the kit and the renderer's bindings.
#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "materials/bsdf/bsdf.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::python {

class MaterialObject {
 public:
  // `label` names the material in check rows and messages (its JSON, or the file it came from).
  MaterialObject(ValidatedMaterial material, std::string label);

  const ValidatedMaterial& validated() const { return material_; }
  const std::string& label() const { return label_; }
  bool isSubsurface() const { return material_.isSubsurface(); }
  // The BSDF; ValueError saying what `use` needs when the material is a subsurface one.
  const BsdfModel& bsdf(const char* use) const;

 private:
  ValidatedMaterial material_;
  std::string label_;
  std::unique_ptr<BsdfModel> bsdf_;
};

// sl.material's argument as a material: a dict, a JSON string, or the path (str or os.PathLike)
// of a material file or measured table, read as the command line reads a MATERIAL argument.
MaterialObject materialFromPython(pybind11::handle spec);

}  // namespace scatterlab::python
