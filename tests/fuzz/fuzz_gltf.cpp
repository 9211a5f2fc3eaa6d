// libFuzzer target for the glTF readers (core/scene/gltf_mesh.h and gltf_character.h, over
// tinygltf). The readers take files, so each input is written to a .glb or .gltf file (by its
// first bytes) in the temporary folder. They must return a mesh / character that validates, or an
// error with a message; never crash or read out of bounds (accessors, buffer views, sparse
// indices, skins, animation samplers). Textures are not decoded: that is stb_image's code.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "scene/gltf_character.h"
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
    scene::GltfCharacterOptions options;
    options.loadTextures = false;
    auto character = scene::loadGltfCharacter(path, options);
    if (!character) {
        if (character.error().message.empty() || character.error().code == thespis::core::ErrorCode::Internal) {
            std::fprintf(stderr, "fuzz_gltf: a character error without a message, or an internal one: %s\n",
                         character.error().message.c_str());
            std::abort();
        }
    } else if (auto valid = character->validate(); !valid) {
        std::fprintf(stderr, "fuzz_gltf: an accepted character does not validate: %s\n", valid.error().message.c_str());
        std::abort();
    }
    return 0;
}
