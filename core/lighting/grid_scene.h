#pragma once
// The uniform-grid backend of lighting/occlusion.h, the paper's reference ray tracer (internal:
// use buildOcclusionScene).

#include <memory>

#include "lighting/occlusion.h"

namespace thespis::core::lighting {

/// Builds a uniform grid over the proxy (indices already checked against positions).
Result<std::unique_ptr<OcclusionScene>> buildGridScene(const ProxyMeshView& proxy);

} // namespace thespis::core::lighting
