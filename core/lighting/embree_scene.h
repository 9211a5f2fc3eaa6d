#pragma once
// The Embree 3 backend of lighting/occlusion.h (internal: use buildOcclusionScene).

#include <memory>

#include "lighting/occlusion.h"

namespace thespis::core::lighting {

/// Builds a robust Embree scene over the proxy (indices already checked against positions).
Result<std::unique_ptr<OcclusionScene>> buildEmbreeScene(const ProxyMeshView& proxy);

} // namespace thespis::core::lighting
