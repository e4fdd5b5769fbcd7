#include "materials/core/json_text.h"

#include <utility>
#include <vector>

#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// The key whose value the parser is reading, so that an error inside a value (NaN is not
// JSON, 1e999 overflows) can still name the key. A key at depth d starts; the event that
// completes a value at depth d (a scalar, or the end of an array or object) ends it.
class KeyTracker {
 public:
  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    const auto level = static_cast<size_t>(depth);
    switch (event) {
      case json::parse_event_t::key:
        keys_.resize(level > 0 ? level - 1 : 0);
        keys_.push_back(parsed.get<std::string>());
        break;
      case json::parse_event_t::value:
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (level > 0 && keys_.size() == level) keys_.pop_back();
        break;
      default: break;
    }
    return true;
  }
  // "alpha", or "outer.inner" inside nested objects; empty outside any value.
  std::string currentKey() const {
    std::string out;
    for (const std::string& key : keys_) out += (out.empty() ? "" : ".") + key;
    return out;
  }

 private:
  std::vector<std::string> keys_;
};

// "line 1, column 22: syntax error ..." from nlohmann's what().
std::string withoutExceptionPrefix(std::string text) {
  if (const auto id = text.find("] "); text.starts_with("[json.exception.") && id != std::string::npos)
    text.erase(0, id + 2);
  constexpr std::string_view Prefix = "parse error at ";
  if (text.starts_with(Prefix)) text.erase(0, Prefix.size());
  return text;
}

// Where nesting first exceeds MaxJsonDepth ("line L, column C"), or empty. Brackets inside
// strings do not count; the text need not be valid JSON (the parser judges that).
std::string firstTooDeep(std::string_view text) {
  int depth = 0;
  size_t line = 1, column = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > MaxJsonDepth)
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return "";
}

std::string keyPart(const std::string& key) { return key.empty() ? "" : "key " + inQuotes(key) + ": "; }

}  // namespace

json parseJsonText(std::string_view text, const std::string& source) {
  if (const std::string where = firstTooDeep(text); !where.empty())
    throw JsonTextError({JsonTextProblem::Kind::TooDeep, "", where},
                        source + ", " + where + ": arrays and objects nested more than " +
                            std::to_string(MaxJsonDepth) + " levels deep; allowed: at most " +
                            std::to_string(MaxJsonDepth) + " levels");
  KeyTracker tracker;
  try {
    return json::parse(text, std::ref(tracker));
  } catch (const json::parse_error& error) {
    JsonTextProblem problem{JsonTextProblem::Kind::Syntax, tracker.currentKey(),
                            withoutExceptionPrefix(error.what())};
    const std::string message = keyPart(problem.key) + source + ", " + problem.detail +
                                "; allowed: JSON, numbers finite (NaN and Infinity are not JSON)";
    throw JsonTextError(std::move(problem), message);
  } catch (const json::out_of_range& error) {
    // 406: "number overflow parsing '1e999'"; the number's text is between the quotes.
    std::string number = withoutExceptionPrefix(error.what());
    if (const auto open = number.find('\''), close = number.rfind('\'');
        open != std::string::npos && close > open)
      number = number.substr(open + 1, close - open - 1);
    JsonTextProblem problem{JsonTextProblem::Kind::NumberOverflow, tracker.currentKey(), number};
    const std::string message = keyPart(problem.key) + source + ": the number " + shortened(number) +
                                " is too large for a double; allowed: a finite number, |x| < 1.8e308";
    throw JsonTextError(std::move(problem), message);
  }
}

int jsonDepth(const json& value) {
  int deepest = 0;
  std::vector<std::pair<const json*, int>> stack{{&value, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (!node->is_structured()) continue;
    deepest = std::max(deepest, depth + 1);
    for (const json& child : *node) stack.emplace_back(&child, depth + 1);
  }
  return deepest;
}

}  // namespace scatterlab
