// std::from_chars for a double, also where the standard library lacks it: Emscripten 3.1's
// libc++ (the explorer's WebAssembly build, docs/explorer.md) has from_chars for integers only.
// There fromCharsByStrtod keeps the same contract with strtod, which is correctly rounded like
// from_chars (musl; the module never changes the C locale), so both builds read every number to
// the same double: no leading blanks or '+', decimal or scientific notation, "inf" and "nan";
// the longest prefix that is a number; errc::invalid_argument when there is none,
// errc::result_out_of_range when it overflows. Tests compare the two natively.
#pragma once

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>

namespace scatterlab {

inline std::from_chars_result fromCharsByStrtod(const char* first, const char* last, double& value) {
  if (first == last || std::isspace(static_cast<unsigned char>(*first)) || *first == '+')
    return {first, std::errc::invalid_argument};
  // strtod reads hexadecimal floats, which from_chars's general format does not: "0x1p3" is 0.
  const char* digits = *first == '-' ? first + 1 : first;
  const bool hex = last - digits >= 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X');
  const std::string text(first, hex ? digits + 1 : last);  // strtod needs the terminating NUL
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return {first, std::errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE && (parsed > 1.0 || parsed < -1.0)) return {stop, std::errc::result_out_of_range};
  value = parsed;
  return {stop, std::errc()};
}

inline std::from_chars_result fromChars(const char* first, const char* last, double& value) {
#if defined(__EMSCRIPTEN__)
  return fromCharsByStrtod(first, last, value);
#else
  return std::from_chars(first, last, value);
#endif
}

}  // namespace scatterlab
