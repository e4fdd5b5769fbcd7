// A test hook, and nothing else: with the environment variable SCATTERLAB_TEST_FAULT set to
// "non-finite" or "negative", every BSDF the renderer is given (makeRenderableMaterial) draws
// half of its samples (those with uLobe < 1/2) with that kind of weight. The CLI tests set it
// to prove, through the real executable, that such samples never reach an image unseen: the
// film drops and counts them (render.h), `scatterlab render` reports the count and exits 1,
// and the lab report shows it in a red box. Unset (normal use) it changes nothing, and no
// material description can ask for it: the registry and `scatterlab models` know nothing of it.
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

inline constexpr const char* TestFaultVariable = "SCATTERLAB_TEST_FAULT";

// `model` as it is, or wrapped in the fault SCATTERLAB_TEST_FAULT names.
std::unique_ptr<BsdfModel> withTestFault(std::unique_ptr<BsdfModel> model);

}  // namespace scatterlab
