// Every error the libraries raise for bad input becomes a Python ValueError carrying the
// library's message unchanged (it names the file, key or value and what is allowed, as the
// command line prints it); nothing else is translated, so a bug stays a RuntimeError.
#include <stdexcept>

#include "app/exit_code.h"
#include "integrator/render_error.h"
#include "materials/bsdf/direction_pairs.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/tensor_file.h"
#include "materials/registry/parameter_spec.h"
#include "python/src/bindings.h"

namespace scatterlab::python {

void bindErrors(pybind11::module_&) {
  pybind11::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const MaterialError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InputFileError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const JsonTextError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const MerlError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const TensorFileError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const DirectionError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const RenderInputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace scatterlab::python
