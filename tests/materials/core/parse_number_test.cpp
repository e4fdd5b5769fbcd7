// fromCharsByStrtod (parse_number.h), what the WebAssembly build reads numbers with, against
// std::from_chars, what the native build reads them with: the same double, the same end and
// the same error for every kind of text the readers meet.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "materials/core/parse_number.h"

namespace scatterlab {
namespace parse_number_test {

TEST(ParseNumber, StrtodVariantAgreesWithFromChars) {
  for (const std::string text : {"0",
                                 "1",
                                 "-2.5",
                                 "0.1",
                                 "3.14159265358979323846",
                                 "1e-300",
                                 "6.02214076e23",
                                 "1.7976931348623157e308",
                                 "2.2250738585072014e-308",
                                 "4.9e-324",
                                 "12abc",
                                 "7,8",
                                 "1.5 2",
                                 ".5",
                                 "-.5",
                                 "5.",
                                 "inf",
                                 "-inf",
                                 "nan",
                                 "0x1p3",
                                 "-0x10",
                                 "1e999",
                                 "-1e999",
                                 "",
                                 " 1",
                                 "+1",
                                 "-",
                                 "e5",
                                 "abc",
                                 "1e",
                                 "1e+",
                                 "0.30000000000000004"}) {
    double native = -7, portable = -7;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const auto expected = std::from_chars(first, last, native);
    const auto got = fromCharsByStrtod(first, last, portable);
    EXPECT_EQ(got.ec, expected.ec) << '"' << text << '"';
    EXPECT_EQ(got.ptr - first, expected.ptr - first) << '"' << text << '"';
    if (expected.ec == std::errc()) {
      if (native != native)
        EXPECT_NE(portable, portable) << '"' << text << '"';  // NaN
      else
        EXPECT_EQ(std::memcmp(&portable, &native, sizeof native), 0) << '"' << text << "\": " << portable;
    }
  }
}

}  // namespace parse_number_test
}  // namespace scatterlab
