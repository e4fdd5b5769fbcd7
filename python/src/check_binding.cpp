// sl.check: the test kit (validation/check_bsdf.h, docs/validation.md) on a scatterlab material
// or on any Python object with eval, pdf and sample (docs/python.md, "The kit on any object").
// A material runs the kit as `scatterlab check` does, with the GIL released. A Python object runs
// it through ReplayedBsdf: the kit's units (one incident angle, the reciprocity rows, one negative
// control at one angle) one at a time, each replayed until every value it used came from the
// object, so the rows are the kit's rows on the object.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include "app/check_command.h"
#include "app/json_output.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "python/src/bindings.h"
#include "python/src/json_conversion.h"
#include "python/src/material_object.h"
#include "python/src/python_bsdf.h"
#include "validation/check_bsdf.h"
#include "validation/subsurface_check.h"

namespace py = pybind11;

namespace scatterlab::python {
namespace {

// Far more rounds than any unit needs (its longest chain of dependent queries: the quadrature's
// refinement depth, QuadratureOptions::maxDepth = 24, plus sampling and the values at the sampled
// directions); more means the object answers the same query differently from call to call.
constexpr int MaxReplayRounds = 64;

void printProgress(const std::string& stage, double fraction) {
  std::cerr << "sl.check: " << stage << " (" << int(100 * fraction) << "%)" << std::endl;
}

CheckReport checkMaterial(const MaterialObject& material, const CheckBsdfOptions& options,
                          bool negativeControls) {
  if (material.isSubsurface()) {
    const SubsurfaceMaterial subsurface = makeSubsurface(material.validated());
    const SubsurfaceCheckOptions subsurfaceOptions = subsurfaceCheckOptions(options.kit);
    py::gil_scoped_release release;
    CheckReport report =
        runSubsurfaceChecks(subsurface.bssrdf(), options.label, subsurfaceOptions, options.progress);
    if (negativeControls)
      report.append(runSubsurfaceNegativeControls(*subsurface.profile, options.label, subsurfaceOptions,
                                                  options.progress));
    return report;
  }
  CheckBsdfOptions withControls = options;
  withControls.negativeControls = negativeControls;
  const std::unique_ptr<BsdfModel> mismatch =
      negativeControls ? makeRoughnessMismatchSampler(material.validated()) : nullptr;
  withControls.roughnessMismatchSampler = mismatch.get();
  py::gil_scoped_release release;
  return checkBsdf(material.bsdf("sl.check"), withControls);
}

// One unit of the kit on the object, replayed until it asked for nothing unknown.
template <typename Unit> CheckReport replayUnit(const PythonBsdf& object, ReplayedBsdf& model,
                                                const std::string& stage, bool progress, const Unit& unit) {
  const auto start = std::chrono::steady_clock::now();
  size_t answered = 0;
  for (int round = 1;; ++round) {
    CheckReport report;
    {
      py::gil_scoped_release release;
      report = unit(model);
    }
    const ReplayedBsdf::Misses misses = model.takeMisses();
    if (misses.size() == 0) {
      if (progress)
        std::cerr << "sl.check: " << stage << ": " << round << " rounds, " << answered
                  << " values from the object, "
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s"
                  << std::endl;
      model.forget();
      return report;
    }
    if (round == MaxReplayRounds)
      throw py::value_error(
          "sl.check: " + stage + ": the kit still met unknown values after " +
          std::to_string(MaxReplayRounds) +
          " rounds; eval, pdf and sample must return the same value for the same arguments");
    object.answer(model, misses);
    answered += misses.size();
    model.clearMisses();
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C between rounds
  }
}

CheckReport checkPythonObject(const PythonBsdf& object, const CheckBsdfOptions& options,
                              bool negativeControls, bool progress) {
  if (options.kit.imageDir) std::filesystem::create_directories(*options.kit.imageDir);
  ReplayedBsdf model(object.declared(), [&object](std::span<const Vec3d> wi, std::span<const Vec3d> wo,
                                                  std::span<Rgb> f, std::span<double> pdf) {
    py::gil_scoped_acquire acquire;
    object.evalAndPdf(wi, wo, f, pdf);
  });
  const std::string& label = options.label;
  const BsdfCheckOptions& kit = options.kit;
  CheckReport report;
  const std::vector<double> angles = incidentAngles(kit, model);
  for (size_t k = 0; k < angles.size(); ++k)
    report.append(replayUnit(object, model, label + ": wi " + std::to_string(int(angles[k])) + " deg",
                             progress,
                             [&](const BsdfModel& m) { return runBsdfChecksAtAngle(m, label, kit, k); }));
  report.append(replayUnit(object, model, label + ": reciprocity", progress,
                           [&](const BsdfModel& m) { return runReciprocityChecks(m, label, kit); }));
  if (!negativeControls) return report;
  // A Python object has no lobe-width parameter the kit could change: the roughness-mismatch
  // control is reported as not applicable (one row), the others run at every angle.
  for (const NegativeControl control : allNegativeControls()) {
    const size_t angleCount = control == NegativeControl::RoughnessMismatch ? 1 : angles.size();
    for (size_t k = 0; k < angleCount; ++k)
      report.append(replayUnit(
          object, model, label + ": control " + toString(control) + " wi " + std::to_string(int(angles[k])),
          progress,
          [&](const BsdfModel& m) { return runNegativeControl(m, nullptr, label, kit, control, k); }));
  }
  return report;
}

py::dict rowDict(const CheckRow& row) {
  py::dict d;
  d["material"] = row.material;
  d["test"] = row.test;
  d["wi_theta"] = row.wiThetaDeg ? py::object(py::float_(*row.wiThetaDeg)) : py::object(py::none());
  d["statistic"] = row.statistic;
  d["dof"] = row.dof ? py::object(py::int_(*row.dof)) : py::object(py::none());
  d["p_value"] = row.pValue ? py::object(py::float_(*row.pValue)) : py::object(py::none());
  d["threshold"] = row.threshold;
  d["passed"] = row.passed;
  d["note"] = row.note;
  return d;
}

}  // namespace

void bindCheck(py::module_& module) {
  py::class_<CheckReport>(module, "CheckReport", "The kit's rows and verdict (docs/validation.md)")
      .def_property_readonly("passed", &CheckReport::passed, "True when every row passed")
      .def_property_readonly(
          "rows",
          [](const CheckReport& report) {
            py::list rows;
            for (const CheckRow& row : report.rows) rows.append(rowDict(row));
            return rows;
          },
          "One dict per row: material, test, wi_theta, statistic, dof, p_value, threshold, passed, note")
      .def(
          "to_json", [](const CheckReport& report, int indent) { return jsonText(toJson(report), indent); },
          py::arg("indent") = 2, "The report as `scatterlab check --json` writes it")
      .def("__str__", &formatVerdict)
      .def("__repr__", [](const CheckReport& report) {
        return "<scatterlab.CheckReport " + std::string(report.passed() ? "PASS" : "FAIL") + ", " +
               std::to_string(report.rows.size()) + " rows>";
      });

  module.def(
      "_check",
      [](py::object bsdf, std::vector<double> wiTheta, double wiPhi, uint64_t samples, uint64_t seed,
         std::pair<int, int> grid, bool negativeControls, double alpha, std::string label, bool progress,
         std::string imageDir, int threads) {
        // The same rows for any thread count (the kit's design, docs/validation.md); `threads`
        // only bounds the cores used, as the command line's --threads does.
        std::optional<tbb::global_control> threadLimit;
        if (threads > 0) threadLimit.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
        CheckBsdfOptions options;
        options.kit.wiThetaDeg = std::move(wiTheta);
        options.kit.wiPhiDeg = wiPhi;
        options.kit.samples = size_t(samples);
        options.kit.seed = seed;
        options.kit.thetaBins = grid.first;
        options.kit.phiBins = grid.second;
        options.kit.alpha = alpha;
        if (!imageDir.empty()) options.kit.imageDir = imageDir;
        if (progress) options.progress = printProgress;
        if (py::isinstance<MaterialObject>(bsdf)) {
          const MaterialObject& material = bsdf.cast<const MaterialObject&>();
          options.label = label.empty() ? material.label() : label;
          return checkMaterial(material, options, negativeControls);
        }
        options.label = label.empty() ? "python object" : label;
        return checkPythonObject(PythonBsdf(bsdf), options, negativeControls, progress);
      },
      py::arg("bsdf"), py::arg("wi_theta"), py::arg("wi_phi"), py::arg("samples"), py::arg("seed"),
      py::arg("grid"), py::arg("negative_controls"), py::arg("alpha"), py::arg("label"), py::arg("progress"),
      py::arg("image_dir"), py::arg("threads"));
}

}  // namespace scatterlab::python
