#include "app/lab/embedded_assets.h"

#include <stdexcept>
#include <string>

namespace scatterlab {

const EmbeddedAsset& embeddedAsset(std::string_view name) {
  for (const EmbeddedAsset& asset : embeddedAssets())
    if (asset.name == name) return asset;
  throw std::logic_error("no embedded asset \"" + std::string(name) + "\"");
}

std::string_view chartJsVersion() { return SCATTERLAB_CHART_JS_VERSION; }

}  // namespace scatterlab
