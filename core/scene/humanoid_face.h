#pragma once
// Private to the default humanoid (default_humanoid.cpp): its face (issue 31; paper §4.2, §5.2).
// The head's skin with a mouth that opens (the lips meet along a seam and turn into the mouth),
// eyeballs with iris and pupil that turn, upper and lower lids that close over them, lashes,
// upper and lower teeth, a tongue and the inside of the mouth; all follow the skull's joint.
// makeFaceRig() then places the MPEG-4 feature points on the assembled mesh, takes the FAP units
// from them and builds each FAP's influence (face_rig.h). Positions: humanoid_face_layout.h.

#include <array>
#include <span>
#include <vector>

#include "scene/character.h"
#include "scene/humanoid_parts.h"

namespace thespis::core::scene::humanoid {

/// The materials the face's segments use (indices into the character's materials).
struct FaceMaterials {
    int face = -1; ///< the skin of the head, textured (lips, brows)
    int skin = -1; ///< the lids
    int hair = -1; ///< the lashes
    int sclera = -1, iris = -1, pupil = -1, teeth = -1, tongue = -1, mouth = -1;
};

/// The face's pieces, on `joint` (the skull's). `spacing` is the body's tessellation; the face is
/// finer where its features are.
void addFace(int joint, double spacing, const FaceMaterials& materials, std::vector<Piece>& pieces);

/// The face rig of the assembled mesh; `tags` holds each vertex's FaceTag (None off the face).
FaceRig makeFaceRig(const CharacterMesh& mesh, std::span<const FaceTag> tags, const anim::Skeleton& skeleton);

/// The skin's picture (lips and brows painted on `skin`, a linear RGB colour), and where a point
/// of the head's skin (rest pose) samples it.
TextureImage makeFaceTexture(const std::array<float, 3>& skin);
std::array<float, 2> faceTexcoord(Vec3d position);

} // namespace thespis::core::scene::humanoid
