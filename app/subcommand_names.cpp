#include "app/subcommand_names.h"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/exit_code.h"
#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

// Levenshtein distance, with a transposition counted as one edit ("chekc").
size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] =
          std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Visible subcommands (generate-table is hidden from the list, but still found).
std::vector<const CLI::App*> subcommandsOf(CLI::App& app) {
  std::vector<const CLI::App*> out;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) out.push_back(sub);
  return out;
}

int error(const std::string& message) {
  std::cerr << "scatterlab: error: " << message << "\n";
  return static_cast<int>(ExitCode::BadInput);
}

}  // namespace

std::optional<int> handleSubcommandWord(CLI::App& app, int argc, char** argv) {
  int first = 1;
  while (first < argc && argv[first][0] == '-') ++first;
  if (first >= argc) return std::nullopt;
  const std::string word = argv[first];
  const auto subcommands = subcommandsOf(app);
  for (const CLI::App* sub : subcommands)
    if (sub->get_name() == word) return std::nullopt;

  if (word == "help") {
    if (first + 1 < argc) {
      const std::string topic = argv[first + 1];
      for (const CLI::App* sub : subcommands)
        if (sub->get_name() == topic) {
          std::cout << sub->help();
          return static_cast<int>(ExitCode::Success);
        }
      return error("help: " + inQuotes(topic) +
                   " is not a subcommand; allowed: `scatterlab help` for the list");
    }
    std::cout << app.help();
    return static_cast<int>(ExitCode::Success);
  }

  std::string names, nearest;
  size_t best = std::string::npos;
  for (const CLI::App* sub : subcommands) {
    if (sub->get_group().empty()) continue;  // hidden
    names += (names.empty() ? "" : ", ") + sub->get_name();
    const size_t distance = editDistance(word, sub->get_name());
    if (distance < best) {
      best = distance;
      nearest = sub->get_name();
    }
  }
  // Close enough to be a typo: at most a third of the word wrong (two edits for "chek").
  const bool typo = best <= std::max<size_t>(1, std::min<size_t>(2, word.size() / 3 + 1));
  const std::string shown = "'" + shortened(word) + "'";
  if (typo) return error("unknown subcommand " + shown + "; did you mean '" + nearest + "'?");
  return error("unknown subcommand " + shown + "; allowed: one of " + names + " (`scatterlab help`)");
}

}  // namespace scatterlab
