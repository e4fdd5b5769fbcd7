// The compiled half of the Python package `scatterlab` (docs/python.md); python/scatterlab/
// __init__.py is the other half and the place the public names are defined.
#include <pybind11/pybind11.h>

#include "materials/registry/version.h"
#include "python/src/bindings.h"

PYBIND11_MODULE(_scatterlab, module) {
  module.doc() = "scatterlab's libraries for Python: materials on numpy arrays, the test kit, fits, renders";
  module.attr("__version__") = SCATTERLAB_VERSION_STRING;
  scatterlab::python::bindErrors(module);
  scatterlab::python::bindMaterials(module);
  scatterlab::python::bindCheck(module);
  scatterlab::python::bindFit(module);
  scatterlab::python::bindRender(module);
  scatterlab::python::bindProfile(module);
}
