// The named set of measured-style materials that `scatterlab synth --bundle` generates: MERL
// materials spanning diffuse, glossy plastic, paint and metal, each from its published Ngan et
// al. 2005 Cook-Torrance fit. The fit lines are compiled in (verbatim copies of lines of
// data/published-fits/ngan_cooktorrance.fit, checked by a test), so the executable needs no
// data directory at run time.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace scatterlab {

struct BundleMaterial {
  const char* name;      // the MERL material; the file is <name>.binary
  const char* category;  // "diffuse", "plastic", "paint", "metal"
  const char* fitLine;   // its line of ngan_cooktorrance.fit
};

inline constexpr const char* BundleFitFile = "ngan_cooktorrance.fit";

std::span<const BundleMaterial> measuredBundle();

// scatterlab's cache directory: $SCATTERLAB_CACHE_DIR, else $XDG_CACHE_HOME/scatterlab, else
// $HOME/.cache/scatterlab; nothing when none of these is set.
std::optional<std::filesystem::path> defaultCacheDirectory();

// Where the bundle goes without --bundle DIR: merl-bundle in the cache directory.
std::optional<std::filesystem::path> defaultBundleDirectory();

}  // namespace scatterlab
