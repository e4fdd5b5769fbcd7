#include "fitting/material_writer.h"

#include <algorithm>
#include <cstdio>

#include "materials/registry/spec_validation.h"

namespace scatterlab::fitting {

namespace {

using nlohmann::json;

// Sums within this of 1 are 1: the fitted scales sit on their bounds up to round-off.
constexpr double Slack = 1e-9;

json rgbJson(const Rgb& v) { return {v.x, v.y, v.z}; }

Rgb rgbOf(const json& value) {
  if (value.is_number()) return Rgb(value.get<double>());
  return Rgb(value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>());
}

// What a scalable part needs: the largest of its scales, per channel.
Rgb needOf(const FittedPart& part) {
  Rgb need(0.0);
  for (const std::string& key : part.scaleKeys) need = glm::max(need, rgbOf(part.material.at(key)));
  return need;
}

}  // namespace

WrittenMaterial writeMaterial(const std::vector<FittedPart>& input) {
  std::vector<FittedPart> parts;
  // Parts carried with a fixed weight first, then the scalable ones.
  for (const FittedPart& part : input)
    if (!part.scalable) parts.push_back(part);
  const size_t fixed = parts.size();
  for (const FittedPart& part : input)
    if (part.scalable) parts.push_back(part);
  if (parts.empty()) return {std::nullopt, "the model has no components"};
  if (fixed == parts.size()) {
    FittedPart black;
    black.material = json{{"type", "lambertian"}, {"albedo", 0.0}};
    black.scalable = true;
    black.scaleKeys = {"albedo"};
    parts.push_back(black);
  }

  // Per channel: the weight c of every part (header comment).
  std::vector<Rgb> c(parts.size(), Rgb(0.0));
  Rgb remaining(1.0), scalableNeed(0.0);
  for (size_t i = 0; i < fixed; ++i) {
    c[i] = parts[i].weight;
    remaining -= parts[i].weight;
  }
  for (size_t i = fixed; i < parts.size(); ++i) scalableNeed += needOf(parts[i]);
  for (int ch = 0; ch < 3; ++ch) {
    if (remaining[ch] < -Slack || scalableNeed[ch] > remaining[ch] + Slack) {
      char text[200];
      std::snprintf(
          text, sizeof text,
          "in channel %c the parts' scales add up to %.6g (> 1), which no blend of registry materials "
          "reproduces",
          "rgb"[ch], 1.0 - remaining[ch] + scalableNeed[ch]);
      return {std::nullopt, text};
    }
  }
  const size_t scalableCount = parts.size() - fixed;
  for (size_t i = fixed; i < parts.size(); ++i) {
    const Rgb need = needOf(parts[i]);
    for (int ch = 0; ch < 3; ++ch) {
      const double room = std::max(remaining[ch], 0.0);
      c[i][ch] = scalableNeed[ch] > 0 ? room * need[ch] / scalableNeed[ch] : room / double(scalableCount);
    }
    // The scales divided by the part's weight: at most 1 (the check above).
    for (const std::string& key : parts[i].scaleKeys) {
      const Rgb v = rgbOf(parts[i].material.at(key));
      Rgb scaled;
      for (int ch = 0; ch < 3; ++ch) scaled[ch] = c[i][ch] > 0 ? std::clamp(v[ch] / c[i][ch], 0.0, 1.0) : 0.0;
      parts[i].material[key] = rgbJson(scaled);
    }
  }

  // Parts with no weight in any channel (the black Lambertian when the fixed parts take
  // everything) are left out; the weights still add up to 1.
  for (size_t i = parts.size(); i-- > 0;) {
    if (parts.size() > 1 && std::max({c[i].x, c[i].y, c[i].z}) <= 1e-15) {
      parts.erase(parts.begin() + std::ptrdiff_t(i));
      c.erase(c.begin() + std::ptrdiff_t(i));
    }
  }

  // The chain, innermost blend first.
  json material = parts.back().material;
  Rgb before(0.0);  // c_1 + ... + c_(i-1) for the outermost i still to wrap
  std::vector<Rgb> preceding(parts.size(), Rgb(0.0));
  for (size_t i = 0; i < parts.size(); ++i) {
    preceding[i] = before;
    before += c[i];
  }
  for (size_t i = parts.size() - 1; i-- > 0;) {
    Rgb w;
    for (int ch = 0; ch < 3; ++ch) {
      const double left = 1.0 - preceding[i][ch];
      w[ch] = left > 0 ? std::clamp(c[i][ch] / left, 0.0, 1.0) : 0.0;
    }
    material = json{
        {"type", "blend"}, {"weight", rgbJson(w)}, {"materials", json::array({parts[i].material, material})}};
  }
  try {
    return {completeMaterial(material), ""};
  } catch (const MaterialError& error) {
    return {std::nullopt, std::string("the registry refuses the fitted material: ") + error.what()};
  }
}

}  // namespace scatterlab::fitting
