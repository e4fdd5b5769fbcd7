#include "python/src/python_bsdf.h"

#include <algorithm>
#include <string>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace scatterlab::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// The object's result as float64 rows: (n, 3), or (n,) broadcast over RGB when `rgb`.
Array resultRows(py::handle value, const std::string& what, size_t n, bool rgb) {
  Array array;
  try {
    array = Array::ensure(py::module_::import("numpy").attr("asarray")(value, "float64"));
  } catch (const py::error_already_set&) {}
  if (!array)
    throw py::value_error(what + " returned " +
                          py::str(value.get_type().attr("__name__")).cast<std::string>() +
                          ", not an array of numbers");
  const bool rows = array.ndim() == 1 && size_t(array.shape(0)) == n;
  const bool rgbRows = rgb && array.ndim() == 2 && size_t(array.shape(0)) == n && array.shape(1) == 3;
  if (!rows && !rgbRows)
    throw py::value_error(what + " returned shape " + shapeText(array) + " for " + std::to_string(n) +
                          " queries; expected (" + std::to_string(n) + (rgb ? ", 3) or (" : ",) ") +
                          (rgb ? std::to_string(n) + ",)" : ""));
  return array;
}

Rgb rgbAt(const Array& array, size_t i) {
  const double* data = array.data();
  return array.ndim() == 1 ? Rgb(data[i]) : Rgb(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
}

py::array_t<double> columns(const std::vector<Miss>& queries, size_t begin, size_t end, size_t first,
                            size_t count) {
  py::array_t<double> array = count == 1
                                  ? py::array_t<double>({py::ssize_t(end - begin)})
                                  : py::array_t<double>({py::ssize_t(end - begin), py::ssize_t(count)});
  double* out = array.mutable_data();
  for (size_t i = begin; i < end; ++i)
    for (size_t c = 0; c < count; ++c) out[(i - begin) * count + c] = queries[i].query[first + c];
  return array;
}

// Directions [begin, end) as an (n, 3) array.
py::array_t<double> directionRows(std::span<const Vec3d> directions, size_t begin, size_t end) {
  py::array_t<double> array({py::ssize_t(end - begin), py::ssize_t(3)});
  double* out = array.mutable_data();
  for (size_t i = begin; i < end; ++i)
    for (int c = 0; c < 3; ++c) out[3 * (i - begin) + c] = directions[i][c];
  return array;
}

bool flag(const py::object& object, const char* name, bool fallback) {
  if (!py::hasattr(object, name)) return fallback;
  const py::object value = object.attr(name);
  if (!py::isinstance<py::bool_>(value))
    throw py::value_error(std::string("the object's attribute \"") + name + "\" is " +
                          py::repr(value).cast<std::string>() + "; it must be True or False");
  return value.cast<bool>();
}

}  // namespace

PythonBsdf::PythonBsdf(py::object object) : object_(std::move(object)) {
  for (const char* method : {"eval", "pdf", "sample"})
    if (!py::hasattr(object_, method) || !PyCallable_Check(object_.attr(method).ptr()))
      throw py::type_error(std::string("sl.check: the object has no method ") + method +
                           "(); it needs eval(wi, wo), pdf(wi, wo) and sample(wi, u_lobe, u) on numpy "
                           "arrays (docs/python.md)");
  declared_.lossless = flag(object_, "lossless", false);
  declared_.reciprocal = flag(object_, "reciprocal", true);
  // A BTDF says transmission = True: the kit then also checks it from below and its histograms
  // cover the whole sphere (validation/bsdf_check.h).
  const bool transmits = flag(object_, "transmission", false);
  if (transmits) declared_.flags = declared_.flags | LobeFlags::GlossyTransmission;
  if (flag(object_, "delta", false))
    declared_.flags = declared_.flags | LobeFlags::SpecularReflection |
                      (transmits ? LobeFlags::SpecularTransmission : LobeFlags::None);
  if (py::hasattr(object_, "lossless_accuracy")) {
    const py::object value = object_.attr("lossless_accuracy");
    const double accuracy =
        py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ? value.cast<double>() : -1.0;
    if (!(accuracy >= 0.0 && accuracy < 1.0))
      throw py::value_error("the object's attribute \"lossless_accuracy\" is " +
                            py::repr(value).cast<std::string>() +
                            "; it must be a number in [0, 1): how far from 1 its albedo may be");
    declared_.losslessAccuracy = accuracy;
  }
}

void PythonBsdf::answer(ReplayedBsdf& model, const ReplayedBsdf::Misses& misses) const {
  for (const std::vector<Miss>* evals : misses.evals) answerEvals(model, *evals);
  for (const std::vector<Miss>* pdfs : misses.pdfs) answerPdfs(model, *pdfs);
  for (const std::vector<Miss>* samples : misses.samples) answerSamples(model, *samples);
}

void PythonBsdf::evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, std::span<Rgb> f,
                            std::span<double> pdf) const {
  for (size_t begin = 0; begin < wo.size(); begin += BatchRows) {
    const size_t end = std::min(wo.size(), begin + BatchRows), n = end - begin;
    const py::array_t<double> wiRows = directionRows(wi, begin, end), woRows = directionRows(wo, begin, end);
    const Array fRows = resultRows(object_.attr("eval")(wiRows, woRows), "eval(wi, wo)", n, true);
    const Array pdfRows = resultRows(object_.attr("pdf")(wiRows, woRows), "pdf(wi, wo)", n, false);
    for (size_t i = 0; i < n; ++i) {
      f[begin + i] = rgbAt(fRows, i);
      pdf[begin + i] = pdfRows.data()[i];
    }
  }
}

void PythonBsdf::answerEvals(ReplayedBsdf& model, const std::vector<Miss>& evals) const {
  for (size_t begin = 0; begin < evals.size(); begin += BatchRows) {
    const size_t end = std::min(evals.size(), begin + BatchRows);
    const Array f =
        resultRows(object_.attr("eval")(columns(evals, begin, end, 0, 3), columns(evals, begin, end, 3, 3)),
                   "eval(wi, wo)", end - begin, true);
    for (size_t i = begin; i < end; ++i) model.answerEval(evals[i], rgbAt(f, i - begin));
  }
}

void PythonBsdf::answerPdfs(ReplayedBsdf& model, const std::vector<Miss>& pdfs) const {
  for (size_t begin = 0; begin < pdfs.size(); begin += BatchRows) {
    const size_t end = std::min(pdfs.size(), begin + BatchRows);
    const Array pdf =
        resultRows(object_.attr("pdf")(columns(pdfs, begin, end, 0, 3), columns(pdfs, begin, end, 3, 3)),
                   "pdf(wi, wo)", end - begin, false);
    for (size_t i = begin; i < end; ++i) model.answerPdf(pdfs[i], pdf.data()[i - begin]);
  }
}

void PythonBsdf::answerSamples(ReplayedBsdf& model, const std::vector<Miss>& samples) const {
  for (size_t begin = 0; begin < samples.size(); begin += BatchRows) {
    const size_t end = std::min(samples.size(), begin + BatchRows), n = end - begin;
    const py::object result =
        object_.attr("sample")(columns(samples, begin, end, 0, 3), columns(samples, begin, end, 3, 1),
                               columns(samples, begin, end, 4, 2));
    if (!py::isinstance<py::tuple>(result) && !py::isinstance<py::list>(result))
      throw py::value_error(
          "sample(wi, u_lobe, u) must return (wo, weight, pdf, valid) or (wo, weight, pdf, "
          "valid, is_delta), not " +
          py::str(result.get_type().attr("__name__")).cast<std::string>());
    const py::sequence parts = result.cast<py::sequence>();
    if (parts.size() != 4 && parts.size() != 5)
      throw py::value_error(
          "sample(wi, u_lobe, u) returned " + std::to_string(parts.size()) +
          " arrays; expected (wo, weight, pdf, valid) or (wo, weight, pdf, valid, is_delta)");
    if (parts.size() == 5 && !hasAny(declared_.flags, LobeFlags::Specular))
      throw py::value_error(
          "sample(wi, u_lobe, u) returned is_delta, but the object does not declare "
          "delta = True (the kit must know it has delta lobes)");
    const Array wo = resultRows(parts[0], "sample(): wo", n, true);
    if (wo.ndim() != 2) throw py::value_error("sample(): wo must have shape (" + std::to_string(n) + ", 3)");
    const Array weight = resultRows(parts[1], "sample(): weight", n, true);
    const Array pdf = resultRows(parts[2], "sample(): pdf", n, false);
    const Array valid = resultRows(parts[3], "sample(): valid", n, false);
    // A default-constructed py::array_t is an empty array, not a null handle: say explicitly
    // whether is_delta came.
    const bool hasDelta = parts.size() == 5;
    const Array delta = hasDelta ? resultRows(parts[4], "sample(): is_delta", n, false) : Array();
    for (size_t i = 0; i < n; ++i) {
      if (valid.data()[i] == 0.0) {
        model.answerSample(samples[begin + i], std::nullopt);
        continue;
      }
      BsdfSample s;
      s.wo = rgbAt(wo, i);
      s.weight = rgbAt(weight, i);
      s.pdf = pdf.data()[i];
      const bool isDelta = hasDelta && delta.data()[i] != 0.0;
      const bool below = s.wo.z < 0;
      s.lobe = isDelta ? (below ? LobeFlags::SpecularTransmission : LobeFlags::SpecularReflection)
                       : (below ? LobeFlags::GlossyTransmission : LobeFlags::GlossyReflection);
      model.answerSample(samples[begin + i], s);
    }
  }
}

}  // namespace scatterlab::python
