#include "materials/bsdf/metal_reduction.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

#include "materials/core/cie.h"
#include "materials/core/parse_number.h"

namespace scatterlab {

namespace {

constexpr double VisibleMin = 380.0, VisibleMax = 780.0;

// Parses one number from [first, last) after skipping blanks; advances first.
bool parseNumber(const char*& first, const char* last, double& value) {
  while (first != last && (*first == ' ' || *first == '\t' || *first == '\r')) ++first;
  const auto [end, error] = fromChars(first, last, value);
  if (error != std::errc() || end == first) return false;
  first = end;
  return true;
}

// The integer wavelengths both spectra cover, within the visible range.
std::pair<int, int> integrationRange(const Spectrum& a, const Spectrum& b) {
  const double lo = std::max({VisibleMin, a.wavelengths.front(), b.wavelengths.front()});
  const double hi = std::min({VisibleMax, a.wavelengths.back(), b.wavelengths.back()});
  const int first = int(std::ceil(lo)), last = int(std::floor(hi));
  if (last <= first) throw std::runtime_error("spectra do not overlap the visible range 380-780 nm");
  return {first, last};
}

// Trapezoid rule with 1 nm steps over [first, last] nm.
template <typename Value> Value integrate(int first, int last, const std::function<Value(double)>& f) {
  Value sum = 0.5 * (f(double(first)) + f(double(last)));
  for (int lambda = first + 1; lambda < last; ++lambda) sum += f(double(lambda));
  return sum;
}

double normalIncidenceReflectance(double n, double k) {
  return (sqr(n - 1.0) + sqr(k)) / (sqr(n + 1.0) + sqr(k));
}

}  // namespace

// R = ((n-1)^2 + k^2) / ((n+1)^2 + k^2) solved for k^2 at fixed n; when that is negative, k = 0
// and R = ((n-1) / (n+1))^2 solved for n on the same side of 1 as the given n.
ComplexIndex indexWithNormalReflectance(double eta, double reflectance) {
  if (!(reflectance >= 0.0 && reflectance < 1.0))
    throw std::domain_error("RGB reflectance " + std::to_string(reflectance) + " outside [0, 1)");
  const double k2 = (reflectance * sqr(eta + 1.0) - sqr(eta - 1.0)) / (1.0 - reflectance);
  if (k2 >= 0.0) return {eta, std::sqrt(k2)};
  const double r = std::sqrt(reflectance);
  return {eta >= 1.0 ? (1.0 + r) / (1.0 - r) : (1.0 - r) / (1.0 + r), 0.0};
}

double Spectrum::at(double lambda) const {
  if (lambda <= wavelengths.front()) return values.front();
  if (lambda >= wavelengths.back()) return values.back();
  const auto upper = std::upper_bound(wavelengths.begin(), wavelengths.end(), lambda);
  const size_t i = size_t(upper - wavelengths.begin());
  const double t = (lambda - wavelengths[i - 1]) / (wavelengths[i] - wavelengths[i - 1]);
  return values[i - 1] + t * (values[i] - values[i - 1]);
}

Spectrum parseSpd(std::istream& in, const std::string& sourceName) {
  Spectrum spectrum;
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const std::string content = line.substr(0, line.find('#'));
    if (content.find_first_not_of(" \t\r") == std::string::npos) continue;
    const char* first = content.data();
    const char* last = first + content.size();
    double lambda = 0, value = 0;
    const bool parsed = parseNumber(first, last, lambda) && parseNumber(first, last, value);
    const bool rest = std::all_of(first, last, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
    if (!parsed || !rest || !std::isfinite(lambda) || !std::isfinite(value))
      throw std::runtime_error(sourceName + ":" + std::to_string(lineNumber) +
                               ": expected 'wavelength-nm value', got '" + line + "'");
    if (!spectrum.wavelengths.empty() && !(lambda > spectrum.wavelengths.back()))
      throw std::runtime_error(sourceName + ":" + std::to_string(lineNumber) + ": wavelengths must increase");
    spectrum.wavelengths.push_back(lambda);
    spectrum.values.push_back(value);
  }
  if (spectrum.wavelengths.size() < 2) throw std::runtime_error(sourceName + ": fewer than two samples");
  return spectrum;
}

Spectrum readSpd(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return parseSpd(in, path.string());
}

namespace {

// Step 2 for a reflectance R(lambda) over [first, last] nm.
Rgb reflectanceRgbOver(int first, int last, const std::function<double(double)>& reflectance) {
  const Vec3d xyz = integrate<Vec3d>(
      first, last, [&](double lambda) { return reflectance(lambda) * cieXyzMatching(lambda); });
  const Vec3d whiteXyz = integrate<Vec3d>(first, last, [](double lambda) { return cieXyzMatching(lambda); });
  return xyzToLinearRec709(xyz) / xyzToLinearRec709(whiteXyz);
}

}  // namespace

Rgb normalIncidenceReflectanceRgb(const Spectrum& eta, const Spectrum& k) {
  const auto [first, last] = integrationRange(eta, k);
  return reflectanceRgbOver(
      first, last, [&](double lambda) { return normalIncidenceReflectance(eta.at(lambda), k.at(lambda)); });
}

Rgb reflectanceRgb(const Spectrum& reflectance) {
  const auto [first, last] = integrationRange(reflectance, reflectance);
  return reflectanceRgbOver(first, last, [&](double lambda) { return reflectance.at(lambda); });
}

MetalIor reduceMetalSpectra(const char* name, const Spectrum& eta, const Spectrum& k) {
  const auto [first, last] = integrationRange(eta, k);
  const auto positiveMatching = [](double lambda) { return glm::max(rec709Matching(lambda), Rgb(0.0)); };
  const Rgb weightedEta =
      integrate<Rgb>(first, last, [&](double lambda) { return eta.at(lambda) * positiveMatching(lambda); });
  const Rgb weight = integrate<Rgb>(first, last, positiveMatching);
  const Rgb meanEta = weightedEta / weight;
  const Rgb reflectance = normalIncidenceReflectanceRgb(eta, k);

  MetalIor metal{name, Rgb(0.0), Rgb(0.0)};
  for (int c = 0; c < 3; ++c) {
    const ComplexIndex index = indexWithNormalReflectance(meanEta[c], reflectance[c]);
    metal.eta[c] = index.eta;
    metal.k[c] = index.k;
  }
  return metal;
}

}  // namespace scatterlab
