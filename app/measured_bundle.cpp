#include "app/measured_bundle.h"

#include <array>
#include <cstdlib>

namespace scatterlab {

std::span<const BundleMaterial> measuredBundle() {
  // Diffuse, glossy plastic, paint and metal, from broad lobes (roughness 0.6) to near
  // mirrors (chrome, roughness 0.009).
  static constexpr std::array<BundleMaterial, 10> bundle{{
      {"pink-felt", "diffuse",
       "pink-felt = Aggregate(Lambertian(albedo = [0.277, 0.164, 0.104]), NganCookTorrance(albedo = [0.333, "
       "0.272, 0.179], eta = 0.129, roughness = 0.643))"},
      {"white-diffuse-bball", "diffuse",
       "white-diffuse-bball = Aggregate(Lambertian(albedo = [0.316, 0.233, 0.106]), NganCookTorrance(albedo "
       "= [0.187, 0.154, 0.103], eta = 0.0546, roughness = 0.19))"},
      {"red-plastic", "plastic",
       "red-plastic = Aggregate(Lambertian(albedo = [0.271, 0.0419, 0.00855]), NganCookTorrance(albedo = "
       "[0.193, 0.153, 0.105], eta = 0.085, roughness = 0.262))"},
      {"gray-plastic", "plastic",
       "gray-plastic = Aggregate(Lambertian(albedo = [0.104, 0.0905, 0.0586]), NganCookTorrance(albedo = "
       "[0.0757, 0.0652, 0.0402], eta = 0.0654, roughness = 0.026))"},
      {"red-specular-plastic", "plastic",
       "red-specular-plastic = Aggregate(Lambertian(albedo = [0.242, 0.0307, 0.00885]), "
       "NganCookTorrance(albedo = [0.0496, 0.0384, 0.0252], eta = 0.0978, roughness = 0.0157))"},
      {"gold-metallic-paint", "paint",
       "gold-metallic-paint = Aggregate(Lambertian(albedo = [0.0657, 0.0312, 0.00247]), "
       "NganCookTorrance(albedo = [0.231, 0.135, 0.0387], eta = 0.663, roughness = 0.241))"},
      {"dark-red-paint", "paint",
       "dark-red-paint = Aggregate(Lambertian(albedo = [0.253, 0.0308, 0.00838]), NganCookTorrance(albedo = "
       "[0.185, 0.138, 0.09], eta = 0.0405, roughness = 0.329))"},
      {"alum-bronze", "metal",
       "alum-bronze = Aggregate(Lambertian(albedo = [0.0886, 0.0602, 0.0299]), NganCookTorrance(albedo = "
       "[0.118, 0.0698, 0.0371], eta = 0.203, roughness = 0.0367))"},
      {"nickel", "metal",
       "nickel = Aggregate(Lambertian(albedo = [0.0342, 0.0256, 0.014]), NganCookTorrance(albedo = [0.16, "
       "0.124, 0.0798], eta = 0.733, roughness = 0.0424))"},
      {"chrome", "metal",
       "chrome = Aggregate(Lambertian(albedo = [0.0116, 0.00995, 0.00796]), NganCookTorrance(albedo = "
       "[0.0428, 0.0298, 0.0143], eta = 0.991, roughness = 0.00935))"},
  }};
  return bundle;
}

std::optional<std::filesystem::path> defaultCacheDirectory() {
  const auto environment = [](const char* name) -> std::optional<std::filesystem::path> {
    const char* value = std::getenv(name);
    if (!value || !*value) return std::nullopt;
    return std::filesystem::path(value);
  };
  if (const auto dir = environment("SCATTERLAB_CACHE_DIR")) return *dir;
  if (const auto dir = environment("XDG_CACHE_HOME")) return *dir / "scatterlab";
  if (const auto dir = environment("HOME")) return *dir / ".cache" / "scatterlab";
  return std::nullopt;
}

std::optional<std::filesystem::path> defaultBundleDirectory() {
  const auto cache = defaultCacheDirectory();
  return cache ? std::optional(*cache / "merl-bundle") : std::nullopt;
}

}  // namespace scatterlab
