#pragma once
// Private to the glTF character import: the file's animations, read as translation and rotation
// channels on skeleton joints and sampled into clips (the rules of gltf_character.h).

#include <array>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "scene/character.h"
#include "scene/gltf_reader.h"

namespace thespis::core::scene::gltf {

enum class Interpolation { Linear, Step, CubicSpline };
enum class Path { Translation, Rotation };

/// One imported channel: a joint's translation or rotation keys.
struct Track {
    int joint = 0;
    Path path = Path::Rotation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times;
    AccessorData values; ///< per key (×3 for CUBICSPLINE: in-tangent, value, out-tangent)

    int components() const { return values.components; }
    /// The value of key k (its middle element for CUBICSPLINE), component c.
    double key(std::size_t k, int c) const
    {
        return interpolation == Interpolation::CubicSpline ? values(3 * k + 1, c) : values(k, c);
    }

    /// The channel's value at time t (glTF's interpolation; held before the first and after the
    /// last key).
    std::array<double, 4> sample(double t) const;
};

struct Animation {
    std::string name;
    double duration = 0;
    std::vector<Track> tracks;
};

/// Nodes whose channels are not imported, by reason, for one warning each.
struct IgnoredChannels {
    std::set<std::string> scale, weights, outsideSkeleton;
};

/// Reads every animation's channels on skeleton joints (`jointOfNode`: node → joint, -1 for
/// other nodes). Structural errors (missing samplers, accessors of the wrong shape, times out of
/// order) refuse the file.
Result<std::vector<Animation>> readAnimations(const tinygltf::Model& model, const AccessorReader& reader,
                                              std::span<const int> jointOfNode, IgnoredChannels& ignored);

/// True when a translation track moves its joint off the rest offset by more than `tolerance`
/// (in world units, through the parent's rest transform).
bool movesJoint(const Track& track, const Vec3d& rest, const Mat4& parent, double tolerance);

/// One clip per animation, sampled at `rate` on the frame layout of `character`'s skeleton,
/// whose joints are the nodes `jointNodes`.
Result<void> buildClips(const File& file, const NodeTree& tree, std::span<const int> jointNodes, double rate,
                        const std::vector<Animation>& animations, Character& character);

} // namespace thespis::core::scene::gltf
