// The materials `scatterlab lab` reports on when given none: an analytic conductor, a rough
// plastic, a measured-style paint and a measured-style metal, two real measurements of the RGL
// database (data/rgl: a glossy vinyl film and a felt), and a subsurface material.
//
// The two measured-style tables are synthesised (materials/measured/measurement_synthesis.h)
// from the published Ngan et al. 2005 Cook-Torrance fits of MERL's gold-metallic-paint and
// alum-bronze (compiled in: app/measured_bundle.h), with a measurement's imperfections: 5%
// log-normal noise, a noise floor of 1e-4 sr^-1 and no measurements beyond 85 degrees (no gain
// error, so that the published fit is the ground truth the fits are compared with). They are kept in the
// cache directory (lab-showcase/, with a manifest, so a second run reads them in a fraction of a second), or,
// when no cache directory is known, in a scratch directory the caller removes.
#pragma once

#include <filesystem>
#include <vector>

#include "app/lab/lab_material.h"
#include "app/lab/phase_timer.h"
#include "validation/bsdf_check.h"

namespace scatterlab {

// `scratch`: where the tables go without a cache directory. Synthesis is timed as phase "synth".
std::vector<LabMaterial> showcaseLabMaterials(const std::filesystem::path& scratch, PhaseTimer& timer,
                                              const ProgressCallback& progress);

// Where the showcase's tables are cached: lab-showcase in defaultCacheDirectory().
std::optional<std::filesystem::path> showcaseCacheDirectory();

}  // namespace scatterlab
