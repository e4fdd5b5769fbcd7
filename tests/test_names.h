// Names of parameterised tests that a person can read in `ctest -N` and in the log: GoogleTest
// allows letters, digits and '_' only, so every other run of characters becomes one '_'
// ("pdf +5% on half the sphere" -> "pdf_5_on_half_the_sphere").
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace scatterlab::test_names {

inline std::string readableTestName(std::string_view text) {
  std::string name;
  for (const char ch : text)
    if (std::isalnum(static_cast<unsigned char>(ch)))
      name += ch;
    else if (!name.empty() && name.back() != '_')
      name += '_';
  if (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

}  // namespace scatterlab::test_names
