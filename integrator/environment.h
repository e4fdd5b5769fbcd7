// The light from infinitely far away: a constant radiance (the white furnace) or an
// equirectangular map, importance-sampled.
//
// Equirectangular convention (Blender/Cycles, peers/make_envmap.py; +Z up): the pixel at
// column u = (i + 0.5) / W and row-from-top t = (j + 0.5) / H looks along
//   theta = pi t (from +Z),  phi = pi - 2 pi u (from +X toward +Y),
// so the image centre faces +X and the left edge -X. A rotation (map to world) turns the map.
// Radiance between pixel centres is bilinear (Cycles' "Linear"), wrapping around in u.
//
// Sampling: cell (row r, column c) of the map is chosen with a 2-D piecewise-constant
// distribution (materials/core/piecewise_constant_2d.h) proportional to the luminance of the
// bilinear radiance integrated over the cell times the cell's solid angle, then a direction
// uniform in the cell's solid angle (phi uniform, cos theta uniform in the row's band). The
// density is therefore constant over each cell (stored in float beside the texel, below),
//   pdf(w) = P(r, c) / (dphi (cos theta_r - cos theta_{r+1})),   dphi = 2 pi / W,
// bounded at the poles (no 1 / sin theta), and positive wherever the bilinear radiance is: the
// integral over a cell weighs the 3 x 3 pixels around it with (1/8, 3/4, 1/8)^2 > 0, and those
// are the only pixels bilinear interpolation inside the cell uses.
//
// Memory layout, for speed: each texel is stored once as (R, G, B) x strength followed by the
// density of its cell, 16 bytes, so the bilinear lookup of a direction also reads that
// direction's density from the same cache lines (evalWithPdf): an escaping ray's radiance and
// MIS density cost two cache lines, not the four or more of separate image and CDF tables.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "integrator/image.h"
#include "integrator/transform.h"
#include "materials/core/piecewise_constant_2d.h"

namespace scatterlab {

struct EnvironmentSample {
  Vec3d direction;  // world, toward the light
  Rgb radiance;
  double pdf;  // per unit solid angle
};

// Radiance along a direction and the density with which sample() draws that direction.
struct EnvironmentValue {
  Rgb radiance;
  double pdf;
};

// Rec. 709 luminance of linear RGB.
inline double luminance(const Rgb& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

class Environment {
 public:
  // The white furnace: radiance 1 from every direction.
  Environment() = default;
  static Environment constant(const Rgb& radiance);
  // An equirectangular map (3-channel image, width == 2 * height, every value finite and
  // >= 0; std::invalid_argument otherwise: the loader, environment_map_file.h, checks files
  // and names the offending pixel), scaled by `strength`, turned by `mapToWorld` (a rotation).
  static Environment fromMap(Image map, double strength = 1.0, const Transform& mapToWorld = Transform());

  // Radiance arriving from `direction` (world, unit): what a ray escaping along it sees.
  Rgb eval(const Vec3d& direction) const;
  // eval and pdf together, sharing the direction's lookup.
  EnvironmentValue evalWithPdf(const Vec3d& direction) const;
  // A direction from u in [0, 1)^2 with its radiance and density; nothing when the
  // environment is black.
  std::optional<EnvironmentSample> sample(const Vec2d& u) const;
  double pdf(const Vec3d& direction) const;

  // The equirect coordinates (u, t) in [0, 1]^2 of a map-space direction, and back.
  static Vec2d equirectFromDirection(const Vec3d& w);
  static Vec3d directionFromEquirect(const Vec2d& ut);

  // False for a constant environment.
  bool hasMap() const { return bool(map_); }
  // The luminance integrated over the sphere of directions, sr: how much light the environment
  // sends (light paths choose among lights by it).
  double luminanceIntegral() const;

 private:
  struct Map {
    int width = 0, height = 0;
    std::vector<float> texels;  // per texel: R, G, B (times strength), density of its cell
    glm::dmat3 mapToWorld, worldToMap;
    PiecewiseConstant2D distribution;  // rows x columns of the image
    std::vector<double> rowCos;        // cos theta at the H + 1 row edges
    bool black = true;                 // nothing to sample
    double luminanceIntegral = 0.0;    // of the cell weights: luminance times solid angle, summed

    const float* texel(int x, int y) const { return texels.data() + (size_t(y) * width + x) * 4; }
  };

  // Bilinear radiance at (u, t) and the density of the cell (u, t) lies in.
  EnvironmentValue lookup(const Vec2d& ut) const;

  Rgb constant_{1.0};
  std::shared_ptr<const Map> map_;  // shared: copies of a scene's environment share one map
};

}  // namespace scatterlab
