// libFuzzer target for the glTF character reader (core/scene/gltf_mesh.h, over tinygltf). The
// reader takes files, so each input is written to a .glb or .gltf file (by its first bytes)
// in the temporary folder. It must return a mesh that validates, or an error with a message;
// never crash or read out of bounds (accessors, buffer views, sparse indices, skins).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "scene/gltf_mesh.h"

namespace scene = thespis::core::scene;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::filesystem::path path = std::filesystem::temp_directory_path()
                                       / ("fuzz_gltf_" + std::to_string(getpid()) + (binary ? ".glb" : ".gltf"));
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    for (bool split : {true, false}) {
        scene::GltfMeshOptions options;
        options.splitSkinnedByJoint = split;
        auto mesh = scene::loadGltfMesh(path, options);
        if (!mesh) {
            if (mesh.error().message.empty()) {
                std::fprintf(stderr, "fuzz_gltf: an error without a message\n");
                std::abort();
            }
            continue;
        }
        if (auto valid = mesh->validate(); !valid) {
            std::fprintf(stderr, "fuzz_gltf: an accepted mesh does not validate: %s\n", valid.error().message.c_str());
            std::abort();
        }
    }
    return 0;
}
