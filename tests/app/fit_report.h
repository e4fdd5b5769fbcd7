// Reading `scatterlab fit --json` reports in the CLI tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

namespace scatterlab::cli_runner {

// The fitted value of the parameter `name` ("model.parameter" or "model.parameter.channel");
// a test failure, and 0, when the report has none.
inline double fittedParameter(const nlohmann::json& report, const std::string& name) {
  for (const nlohmann::json& p : report.at("fit").at("parameters"))
    if (p.at("name") == name) return p.at("value").get<double>();
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

}  // namespace scatterlab::cli_runner
