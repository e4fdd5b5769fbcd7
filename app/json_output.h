// JSON the command line prints or writes. Paths and labels come from the user's arguments and
// may hold bytes that are not UTF-8 (a file name on Linux can); json::dump would throw on them,
// turning a finished run into an internal error. They are written as U+FFFD instead.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace scatterlab {

inline std::string jsonText(const nlohmann::json& value, int indent = 2) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace scatterlab
