// Parsing JSON text the tool is given (docs/reliability.md, "Limits"): material descriptions, fit
// model specs, the manifests it reads back. Every such text goes through parseJsonText, so
// every one gets the same limits and the same messages:
//  - nesting deeper than MaxJsonDepth arrays and objects is refused before the parser builds
//    anything (a pre-scan), so that no recursive code downstream (value formatting, path
//    resolution, json::dump) can run out of stack;
//  - a number that does not fit a double (1e999) names the key it belongs to;
//  - a syntax error names the key being read, the line and the column.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace scatterlab {

// Far above any description the tool reads (a blend nested 8 levels deep is 17 levels), far
// below what recursion over the value could not survive.
inline constexpr int MaxJsonDepth = 64;
// A material file or spec is a few kB; 4 MB leaves room for generated descriptions while a
// mistaken /dev/zero or image file is refused before it is read (bounded_file.h).
inline constexpr uintmax_t MaxJsonFileBytes = uintmax_t(4) << 20;

// What went wrong, for callers that phrase their own messages.
struct JsonTextProblem {
  enum class Kind { Syntax, TooDeep, NumberOverflow };
  Kind kind = Kind::Syntax;
  std::string key;     // "alpha", "materials.0.alpha"; empty outside any object member
  std::string detail;  // "line 1, column 22: syntax error ...", the number's text, ...
};

// what(): "SOURCE: PROBLEM; allowed: ...", the key named when there is one.
class JsonTextError : public std::runtime_error {
 public:
  JsonTextError(JsonTextProblem problem, const std::string& message)
      : std::runtime_error(message), problem_(std::move(problem)) {}
  const JsonTextProblem& problem() const { return problem_; }

 private:
  JsonTextProblem problem_;
};

// Parses `text`; `source` names it in messages ("inline JSON", "material file \"gold.json\"").
// Throws JsonTextError.
nlohmann::json parseJsonText(std::string_view text, const std::string& source);

// The deepest nesting of arrays and objects in `value` (a scalar is 0), without recursion: a
// guard for JSON built by code rather than parsed.
int jsonDepth(const nlohmann::json& value);

}  // namespace scatterlab
