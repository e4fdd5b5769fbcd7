// Direction pairs at which the formula tests compare a model with its paper's formula written
// out: normal incidence, moderate angles, and one pair near grazing, with azimuths away from the
// tangent axes so that anisotropy shows. A pair is the library's DirectionPair.
#pragma once

#include <vector>

#include "materials/bsdf/direction_pairs.h"
#include "materials/core/spherical.h"

namespace scatterlab {

inline std::vector<DirectionPair> reflectionPairs() {
  return {{directionFromDegrees(0, 0), directionFromDegrees(10, 180)},
          {directionFromDegrees(30, 20), directionFromDegrees(35, 190)},
          {directionFromDegrees(60, 0), directionFromDegrees(50, 120)},
          {directionFromDegrees(80, 45), directionFromDegrees(75, 230)}};
}

}  // namespace scatterlab
