// One verdict table: what `scatterlab check` prints and what the tests assert on.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace scatterlab {

struct ChiSquareResult;

// One row per test: chi-square (statistic, dof, p-value, threshold = Sidak-corrected
// significance, passes when p >= threshold) or a bound check (statistic, threshold, passes
// when statistic <= threshold).
struct CheckRow {
  std::string material;  // the material's label (its JSON, or a showcase name)
  std::string test;      // "chi2", "consistency", "normalisation", "albedo", ...
  std::optional<double> wiThetaDeg;
  double statistic = 0.0;
  std::optional<int> dof;
  std::optional<double> pValue;
  double threshold = 0.0;
  bool passed = false;
  std::string note;  // what was compared, or why it failed, in words
};

struct CheckReport {
  std::vector<CheckRow> rows;
  bool passed() const;
  // The row of one test at one incident angle; null when the report has none.
  const CheckRow* find(const std::string& test, double wiThetaDeg) const;
  void append(const CheckReport& other) { rows.insert(rows.end(), other.rows.begin(), other.rows.end()); }
};

// The row of a chi-square test: statistic, dof, p-value against the Sidak-corrected threshold;
// with no degrees of freedom no p-value exists, and the row shows the count test
// (|O - E| / sqrt(E) against CountSigmas) and says so.
CheckRow chiSquareRow(const std::string& material, const std::string& test, std::optional<double> wiThetaDeg,
                      const ChiSquareResult& result);

// Fixed-width table, one row per line, for the terminal.
std::string formatTable(const CheckReport& report);
nlohmann::json toJson(const CheckReport& report);

}  // namespace scatterlab
