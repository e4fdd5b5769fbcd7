// Small helpers for writing the report's HTML by hand: escaping, and elements with
// attributes. The report's structure is in report_page.cpp and the sections; this only keeps
// every piece of text escaped.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include "materials/core/math.h"

namespace scatterlab::html {

// Text for an element's content or an attribute value: & < > " ' escaped.
std::string escape(std::string_view text);

using Attributes = std::initializer_list<std::pair<std::string_view, std::string_view>>;

// <tag attributes>content</tag>; `content` is HTML (escape text first), attribute values are
// escaped here.
std::string element(std::string_view tag, std::string_view content, Attributes attributes = {});
// <tag attributes> without content or end tag (img, meta, link).
std::string voidElement(std::string_view tag, Attributes attributes);
// element() with escaped text as content.
std::string textElement(std::string_view tag, std::string_view text, Attributes attributes = {});

// A number for tables: `significant` significant digits, no trailing noise ("0.0312",
// "1.2e-05"); "-" for NaN, "inf" for infinity.
std::string number(double value, int significant = 4);

// Three numbers (an RGB triple) for tables and captions: "0.0576, 0.05, 0.0324".
std::string rgb(const Rgb& c, int significant = 3);

// An angle for captions: number(value, significant) and a degree sign.
std::string degrees(double value, int significant = 3);

// JSON for a <script type="application/json"> element: every '<' (it can only be inside a JSON
// string) is written as \u003c, so that no "</script" or "<!--" in a name can end the element.
std::string jsonForScript(std::string_view json);

}  // namespace scatterlab::html
