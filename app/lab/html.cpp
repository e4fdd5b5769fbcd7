#include "app/lab/html.h"

#include <cmath>
#include <cstdio>

namespace scatterlab::html {

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

std::string startTag(std::string_view tag, Attributes attributes) {
  std::string out = "<" + std::string(tag);
  for (const auto& [name, value] : attributes) out += " " + std::string(name) + "=\"" + escape(value) + "\"";
  return out + ">";
}

}  // namespace

std::string element(std::string_view tag, std::string_view content, Attributes attributes) {
  return startTag(tag, attributes) + std::string(content) + "</" + std::string(tag) + ">";
}

std::string voidElement(std::string_view tag, Attributes attributes) { return startTag(tag, attributes); }

std::string textElement(std::string_view tag, std::string_view text, Attributes attributes) {
  return element(tag, escape(text), attributes);
}

std::string number(double value, int significant) {
  if (std::isnan(value)) return "-";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

std::string rgb(const Rgb& c, int significant) {
  return number(c.x, significant) + ", " + number(c.y, significant) + ", " + number(c.z, significant);
}

std::string degrees(double value, int significant) { return number(value, significant) + "\u00b0"; }

std::string jsonForScript(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

}  // namespace scatterlab::html
