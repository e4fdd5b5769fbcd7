// sl.fit (docs/python.md, "Fits"): `scatterlab fit` without printing or writing, its report as a
// dict and the parameters' covariance as a numpy array (app/fit_command.h fitReport).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "app/fit_command.h"
#include "python/src/bindings.h"
#include "python/src/command_options.h"
#include "python/src/json_conversion.h"

namespace scatterlab::python {

namespace py = pybind11;

void bindFit(py::module_& module) {
  module.def(
      "_fit",
      [](const std::string& data, const py::dict& keywords, bool progress) {
        FitCommandOptions options;
        CommandOptions command("sl.fit", [&](CLI::App& app) { return addFitCommand(app, options); },
                               {"out", "json"});
        command.parse(keywords, {data});
        FitReport report = command.run([&] { return fitReport(options, progress); });
        const size_t p = report.report["fit"]["parameters"].size();
        py::array_t<double> covariance({p, p});
        if (report.covariance.size() == p * p)
          std::copy(report.covariance.begin(), report.covariance.end(), covariance.mutable_data());
        else
          std::fill_n(covariance.mutable_data(), p * p, std::numeric_limits<double>::quiet_NaN());
        return py::make_tuple(pythonFromJson(report.report), covariance, report.good);
      },
      py::arg("data"), py::arg("keywords"), py::arg("progress"),
      "`scatterlab fit DATA --KEYWORD=VALUE...` as (report dict, covariance (p, p), good); see sl.fit");
}

}  // namespace scatterlab::python
