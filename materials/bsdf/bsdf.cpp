#include "materials/bsdf/bsdf.h"

namespace scatterlab {

std::string toString(LobeFlags flags) {
  if (flags == LobeFlags::None) return "none";
  std::string out;
  auto add = [&](LobeFlags f, const char* name) {
    if (!hasAny(flags, f)) return;
    if (!out.empty()) out += '|';
    out += name;
  };
  add(LobeFlags::Reflection, "reflection");
  add(LobeFlags::Transmission, "transmission");
  add(LobeFlags::Diffuse, "diffuse");
  add(LobeFlags::Glossy, "glossy");
  add(LobeFlags::Specular, "specular");
  return out;
}

}  // namespace scatterlab
