#pragma once
// printf-style formatting of one number for the CLI's messages (e.g. "%.3g").
#include <cstdio>
#include <string>

namespace scatterlab {

inline std::string formatNumber(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace scatterlab
