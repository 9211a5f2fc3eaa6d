#pragma once
// Private to core/scene's glTF writers (gltf_motion_export.cpp, gltf_character_export.cpp): adding
// bytes, accessors and LINEAR animation channels to a tinygltf model with one buffer, dropping
// what nothing uses any more, and writing the model as one .glb, atomically.

#include <cstddef>
#include <filesystem>
#include <vector>

#include <tiny_gltf.h>

#include "anim/quat.h"
#include "util/error.h"

namespace thespis::core::scene::gltf {

/// Appends bytes to buffer 0 as a bufferView of their own (4-byte aligned); returns its index.
/// `target`: TINYGLTF_TARGET_ARRAY_BUFFER / _ELEMENT_ARRAY_BUFFER for vertex data, 0 for none.
int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target = 0);

/// A float accessor of `count` elements of `type` (TINYGLTF_TYPE_*), `components` floats each;
/// `withBounds` writes min / max (required for positions and animation times).
int addAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, int components, bool withBounds,
                int target = 0);

/// An accessor of `count` elements of `type` over `bytes` of integers (componentType
/// TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT / _INT …): joint indices, triangle indices.
int addIntegerAccessor(tinygltf::Model& model, const void* bytes, std::size_t size, int componentType, int type,
                       std::size_t count, int target);

/// The times of `frames` frames at `fps` (frame i at i / fps seconds), with their bounds.
int addFrameTimes(tinygltf::Model& model, std::size_t frames, double fps);

/// A LINEAR sampler over `times` and a channel driving `path` ("rotation", "translation",
/// "weights") of `node` with `values`.
void addChannel(tinygltf::Model& model, tinygltf::Animation& animation, int times, int node, const char* path,
                const std::vector<float>& values, int type, int components);

/// Appends a rotation to a rotation channel's values, negated when that is nearer the previous
/// one: the same rotation, on the path LINEAR interpolation takes.
void appendRotation(std::vector<float>& values, anim::Quatd rotation);

/// Drops the accessors, buffer views and bytes nothing refers to (meshes, skins, animations,
/// images, sparse data), renumbering the references. The model must have one buffer.
void dropUnused(tinygltf::Model& model);

/// Writes the model as a binary .glb at `output`, atomically.
Result<void> writeGlb(const tinygltf::Model& model, const std::filesystem::path& output);

} // namespace thespis::core::scene::gltf
