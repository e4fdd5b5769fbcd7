#include "app/showcase.h"

namespace scatterlab {

std::vector<ShowcaseMaterial> showcaseMaterials() {
  using nlohmann::json;
  return {
      {"lambertian-0.8", json{{"type", "lambertian"}, {"albedo", 0.8}}},
      // Anisotropy 3:1 and wi off the tangent axes: an axis mix-up cannot pass.
      {"gold-anisotropic-ggx",
       json{{"type", "conductor"}, {"distribution", "ggx"}, {"alpha", {0.3, 0.1}}, {"metal", "Au"}}},
      {"copper-beckmann-classic", json{{"type", "conductor"},
                                       {"distribution", "beckmann"},
                                       {"alpha", 0.3},
                                       {"metal", "Cu"},
                                       {"sampling", "classic"}}},
      // A lobe narrower than a grid cell: the expected counts must come from adaptive quadrature.
      {"silver-smooth-ggx",
       json{{"type", "conductor"}, {"distribution", "ggx"}, {"alpha", 0.02}, {"metal", "Ag"}}},
  };
}

}  // namespace scatterlab
