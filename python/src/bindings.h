// The parts of the `_scatterlab` extension module (module.cpp), each binding one part of the
// Python API (docs/python.md): errors, materials on arrays, the test kit, fits, renders, subsurface profiles.
#pragma once

#include <pybind11/pybind11.h>

namespace scatterlab::python {

void bindErrors(pybind11::module_& module);
void bindMaterials(pybind11::module_& module);
void bindCheck(pybind11::module_& module);
void bindFit(pybind11::module_& module);
void bindRender(pybind11::module_& module);
void bindProfile(pybind11::module_& module);

}  // namespace scatterlab::python
