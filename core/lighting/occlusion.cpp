#include "lighting/occlusion.h"

#include "lighting/embree_scene.h"
#include "lighting/grid_scene.h"

namespace thespis::core::lighting {

const char* occlusionBackendName(OcclusionBackendKind kind)
{
    return kind == OcclusionBackendKind::Embree ? "embree" : "grid";
}

Result<OcclusionBackendKind> parseOcclusionBackend(std::string_view name)
{
    for (OcclusionBackendKind kind : {OcclusionBackendKind::Embree, OcclusionBackendKind::Grid})
        if (name == occlusionBackendName(kind))
            return kind;
    return makeError(ErrorCode::InvalidArgument,
                     "Unknown ray backend \"" + std::string(name) + "\": use embree or grid.");
}

Result<std::unique_ptr<OcclusionScene>> buildOcclusionScene(OcclusionBackendKind kind, const ProxyMeshView& proxy)
{
    if (proxy.indices.size() % 3 != 0)
        return makeError(ErrorCode::InvalidArgument, "The proxy mesh's index count is not a multiple of 3.",
                         std::to_string(proxy.indices.size()) + " indices");
    for (std::uint32_t index : proxy.indices)
        if (index >= proxy.positions.size())
            return makeError(ErrorCode::InvalidArgument, "The proxy mesh uses a vertex that does not exist.",
                             "vertex " + std::to_string(index) + " of " + std::to_string(proxy.positions.size()));
    return kind == OcclusionBackendKind::Embree ? buildEmbreeScene(proxy) : buildGridScene(proxy);
}

} // namespace thespis::core::lighting
