// sl.material, sl.models, sl.load_plugin and the Material class: a registry model's eval, pdf and
// sample on numpy arrays (docs/python.md, "Materials"). The loops run in C++ over TBB with the
// GIL released, one virtual call per element through the same BsdfModel the renderer and the kit
// call, so the values are the C++ values bit for bit.
#include <filesystem>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "app/json_output.h"
#include "app/plugin_loader.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "python/src/array_arguments.h"
#include "python/src/bindings.h"
#include "python/src/json_conversion.h"
#include "python/src/material_object.h"

namespace py = pybind11;

namespace scatterlab::python {

MaterialObject::MaterialObject(ValidatedMaterial material, std::string label)
    : material_(std::move(material)), label_(std::move(label)) {
  if (!material_.isSubsurface()) bsdf_ = makeBsdf(material_);
}

const BsdfModel& MaterialObject::bsdf(const char* use) const {
  if (!bsdf_)
    throw py::value_error("material " + label_ + " is a subsurface material (type \"" +
                          material_.model->type + "\"): " + use +
                          " takes a BSDF; sl.profile takes a subsurface material");
  return *bsdf_;
}

MaterialObject materialFromPython(py::handle spec) {
  if (py::isinstance<py::dict>(spec)) {
    const nlohmann::json material = jsonFromPython(spec, "");
    return MaterialObject(validateMaterial(material), jsonText(material, -1));
  }
  std::string argument;
  if (py::isinstance<py::str>(spec))
    argument = spec.cast<std::string>();
  else if (py::hasattr(spec, "__fspath__"))
    argument = py::str(spec.attr("__fspath__")()).cast<std::string>();
  else
    throw py::type_error("sl.material takes a dict, a JSON string or the path of a material file, not " +
                         py::str(spec.get_type().attr("__name__")).cast<std::string>());
  const nlohmann::json material = loadMaterialArgument(argument);
  return MaterialObject(validateMaterial(material),
                        isInlineMaterial(argument) ? jsonText(material, -1) : argument);
}

namespace {

TransportMode transportMode(const std::string& mode) {
  if (mode == "radiance") return TransportMode::Radiance;
  if (mode == "importance") return TransportMode::Importance;
  throw py::value_error("mode: \"" + mode + "\" is not a transport mode (\"radiance\" or \"importance\")");
}

// for (i in [0, n)) body(i), over TBB with the GIL released; the bodies write disjoint rows.
template <typename Body> void parallelRows(size_t n, const Body& body) {
  py::gil_scoped_release release;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) body(i);
  });
}

py::array_t<double> evalRows(const MaterialObject& material, py::handle wiValue, py::handle woValue,
                             const std::string& modeName) {
  const BsdfModel& model = material.bsdf("eval");
  const TransportMode mode = transportMode(modeName);
  const ArrayRows wi = directionArgument(wiValue, "wi"), wo = directionArgument(woValue, "wo");
  const size_t n = commonRowCount({{"wi", &wi}, {"wo", &wo}});
  py::array_t<double> f = newArray(n, 3);
  double* out = f.mutable_data();
  parallelRows(n, [&](size_t i) {
    const Rgb value = model.eval(wi.direction(i), wo.direction(i), mode);
    out[3 * i] = value.x;
    out[3 * i + 1] = value.y;
    out[3 * i + 2] = value.z;
  });
  return f;
}

py::array_t<double> pdfRows(const MaterialObject& material, py::handle wiValue, py::handle woValue,
                            const std::string& modeName) {
  const BsdfModel& model = material.bsdf("pdf");
  const TransportMode mode = transportMode(modeName);
  const ArrayRows wi = directionArgument(wiValue, "wi"), wo = directionArgument(woValue, "wo");
  const size_t n = commonRowCount({{"wi", &wi}, {"wo", &wo}});
  py::array_t<double> pdf = newArray(n, 0);
  double* out = pdf.mutable_data();
  parallelRows(n, [&](size_t i) { out[i] = model.pdf(wi.direction(i), wo.direction(i), mode); });
  return pdf;
}

py::tuple sampleRows(const MaterialObject& material, py::handle wiValue, py::handle uLobeValue,
                     py::handle uValue, const std::string& modeName) {
  const BsdfModel& model = material.bsdf("sample");
  const TransportMode mode = transportMode(modeName);
  const ArrayRows wi = directionArgument(wiValue, "wi");
  const ArrayRows uLobe = unitIntervalArgument(uLobeValue, "u_lobe", 1);
  const ArrayRows u = unitIntervalArgument(uValue, "u", 2);
  const size_t n = commonRowCount({{"wi", &wi}, {"u_lobe", &uLobe}, {"u", &u}});
  py::array_t<double> wo = newArray(n, 3), weight = newArray(n, 3), pdf = newArray(n, 0);
  py::array_t<bool> valid({py::ssize_t(n)}), delta({py::ssize_t(n)});
  double *woOut = wo.mutable_data(), *weightOut = weight.mutable_data(), *pdfOut = pdf.mutable_data();
  bool *validOut = valid.mutable_data(), *deltaOut = delta.mutable_data();
  parallelRows(n, [&](size_t i) {
    const std::optional<BsdfSample> s = model.sample(wi.direction(i), uLobe.value(i), u.pair(i), mode);
    // A failed sample is all zeros and valid = False (the convention of bsdf.h: nothing, not NaN).
    const BsdfSample value = s.value_or(BsdfSample{Vec3d(0.0), Rgb(0.0), 0.0});
    for (int c = 0; c < 3; ++c) {
      woOut[3 * i + c] = value.wo[c];
      weightOut[3 * i + c] = value.weight[c];
    }
    pdfOut[i] = value.pdf;
    validOut[i] = s.has_value();
    deltaOut[i] = s && s->isDelta();
  });
  return py::make_tuple(wo, weight, pdf, valid, delta);
}

}  // namespace

void bindMaterials(py::module_& module) {
  py::class_<MaterialObject>(module, "Material",
                             "A registry material: eval, pdf and sample on (N, 3) float64 arrays in the "
                             "local frame (z = normal, both directions pointing away from the surface).")
      .def_property_readonly("type", [](const MaterialObject& m) { return m.validated().model->type; })
      .def_property_readonly("label", &MaterialObject::label)
      .def_property_readonly(
          "description", [](const MaterialObject& m) { return pythonFromJson(m.validated().completed); },
          "The description with every default filled in, as a dict")
      .def_property_readonly("is_subsurface", &MaterialObject::isSubsurface)
      .def_property_readonly("flags",
                             [](const MaterialObject& m) { return toString(m.bsdf("flags").flags()); })
      .def_property_readonly("lossless",
                             [](const MaterialObject& m) { return m.bsdf("lossless").isLossless(); })
      .def("eval", &evalRows, py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance",
           "f(wi, wo) per linear-RGB channel, without the cosine: (N, 3)")
      .def("pdf", &pdfRows, py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance",
           "The density of sample() per unit solid angle of wo: (N,)")
      .def("_sample", &sampleRows, py::arg("wi"), py::arg("u_lobe"), py::arg("u"),
           py::arg("mode") = "radiance")
      .def("__repr__", [](const MaterialObject& m) {
        return "scatterlab.Material(" + jsonText(m.validated().completed, -1) + ")";
      });
  module.def(
      "_material", [](py::handle spec) { return materialFromPython(spec); }, py::arg("spec"));
  module.def("_models", [] { return pythonFromJson(materialCatalogJson()); });
  module.def(
      "load_plugin",
      [](const std::string& path) { loadPlugin(std::filesystem::path(path), "sl.load_plugin"); },
      py::arg("path"),
      "Loads a scatterlab plugin (a shared library built with scatterlab_add_plugin) and registers its "
      "models");
}

}  // namespace scatterlab::python
