// The published fits of the MERL materials (Ngan, Durand & Matusik 2005, "Experimental
// Analysis of BRDF Models", EGSR), one line per material as collected by the bsdfbenchmark
// project (data/published-fits/README.md):
//   name = Aggregate(Lambertian(albedo = [r, g, b]), NganCookTorrance(albedo = [...], eta = x, roughness =
//   y))
// Each line becomes the registry materials whose sum it is: a Lambertian term and the lobe.
// The lobe's scatterlab type takes the fit's parameters under the same names where it can
// (ngan-cook-torrance, ngan-ward, ngan-ashikhmin-shirley); NganBlinnPhong maps to blinn-phong
// (ks = albedo, exponent = sharpness, kd = 0) and NganLafortune to lafortune (cx = cy = Cxy,
// normalization "ngan", kd = 0), the Lambertian term carrying the diffuse part.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/core/math.h"

namespace scatterlab {

struct PublishedFit {
  std::string name;       // "alum-bronze"
  std::string lobeModel;  // "NganCookTorrance"
  std::string line;       // as in the file
  Rgb diffuseAlbedo{0.0};
  nlohmann::json lobeParameters;  // the lobe's parameters as in the file: {"albedo": [..], "eta": ..}

  // The registry materials whose sum is the fit (not yet validated: makeBsdf does that).
  std::vector<nlohmann::json> components() const;
};

// One line; throws MaterialError saying what is wrong with it.
PublishedFit parsePublishedFitLine(const std::string& line);

// Every fit in a file (lines starting with '#' and blank lines skipped). Throws MaterialError
// naming the file (not found, not readable) or the file and line number of a malformed line.
std::vector<PublishedFit> readPublishedFits(const std::filesystem::path& file);

// The lobe models a fit line may use.
std::vector<std::string> publishedFitModels();

}  // namespace scatterlab
