#include "validation/check_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "validation/chi_square.h"

namespace scatterlab {

bool CheckReport::passed() const {
  for (const CheckRow& row : rows)
    if (!row.passed) return false;
  return true;
}

const CheckRow* CheckReport::find(const std::string& test, double wiThetaDeg) const {
  for (const CheckRow& row : rows)
    if (row.test == test && row.wiThetaDeg && *row.wiThetaDeg == wiThetaDeg) return &row;
  return nullptr;
}

CheckRow chiSquareRow(const std::string& material, const std::string& test, std::optional<double> wiThetaDeg,
                      const ChiSquareResult& result) {
  CheckRow row;
  row.material = material;
  row.test = test;
  row.wiThetaDeg = wiThetaDeg;
  row.passed = result.passed;
  row.dof = result.dof;
  if (result.hasPValue()) {
    row.statistic = result.statistic;
    row.pValue = result.pValue;
    row.threshold = result.threshold;
    row.note = result.failure.empty() ? std::to_string(result.pooledCells) + " cells pooled" : result.failure;
    return row;
  }
  // No degrees of freedom: no p-value is invented; the row shows the count test instead.
  row.statistic = result.countZ;
  row.threshold = CountSigmas;
  char note[160];
  std::snprintf(note, sizeof note,
                "no degrees of freedom (every sample in one scored cell): no p-value; count |O - E| / "
                "sqrt(E) = %.3g",
                result.countZ);
  row.note = result.failure.empty() ? std::string(note) : result.failure;
  return row;
}

std::string formatTable(const CheckReport& report) {
  std::string out;
  char line[512];
  std::string current;
  for (const CheckRow& row : report.rows) {
    if (row.material != current || out.empty()) {
      current = row.material;
      out += '\n';
      out += current;
      out += '\n';
      std::snprintf(line, sizeof line, "  %-36s %7s %13s %6s %10s %10s  %s\n", "test", "wi(deg)", "statistic",
                    "dof", "p-value", "threshold", "result");
      out += line;
    }
    const std::string wi = row.wiThetaDeg ? std::to_string(*row.wiThetaDeg).substr(0, 5) : "-";
    const std::string dof = row.dof ? std::to_string(*row.dof) : "-";
    char p[32] = "-";
    if (row.pValue) std::snprintf(p, sizeof p, "%.4g", *row.pValue);
    std::snprintf(line, sizeof line, "  %-36s %7s %13.6g %6s %10s %10.3g  %s  %s\n", row.test.c_str(),
                  wi.c_str(), row.statistic, dof.c_str(), p, row.threshold, row.passed ? "PASS" : "FAIL",
                  row.note.c_str());
    out += line;
  }
  size_t failed = 0;
  for (const CheckRow& row : report.rows) failed += row.passed ? 0 : 1;
  std::snprintf(line, sizeof line, "\n%zu passed, %zu failed\n", report.rows.size() - failed, failed);
  out += line;
  return out;
}

nlohmann::json toJson(const CheckReport& report) {
  nlohmann::json rows = nlohmann::json::array();
  for (const CheckRow& row : report.rows) {
    nlohmann::json j = {{"material", row.material},   {"test", row.test},     {"statistic", row.statistic},
                        {"threshold", row.threshold}, {"passed", row.passed}, {"note", row.note}};
    j["wi_theta_deg"] = row.wiThetaDeg ? nlohmann::json(*row.wiThetaDeg) : nlohmann::json(nullptr);
    j["dof"] = row.dof ? nlohmann::json(*row.dof) : nlohmann::json(nullptr);
    j["p_value"] = row.pValue ? nlohmann::json(*row.pValue) : nlohmann::json(nullptr);
    // JSON has no NaN/inf: a non-finite statistic is written as a string.
    if (!std::isfinite(row.statistic)) j["statistic"] = std::to_string(row.statistic);
    rows.push_back(std::move(j));
  }
  return {{"passed", report.passed()}, {"rows", std::move(rows)}};
}

}  // namespace scatterlab
