// libFuzzer target for the face mapping table reader (core/scene/face_mapping.h).
//
// Any bytes: parseFaceMapping must return a table or an error with a message, never crash, hang
// or throw. A table it accepts must write and read back equal and write the same text again, and
// applying it to a small character must leave a face that validates, with one warning per name
// the character lacks.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

#include "scene/character.h"
#include "scene/face_mapping.h"

namespace scene = thespis::core::scene;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_face_mapping: %s\n%s\n", what, detail.c_str());
    std::abort();
}

// A triangle with targets "a" and "b" and one joint "j" (source name "s").
const scene::Character& smallCharacter()
{
    static const scene::Character character = [] {
        scene::Character c;
        c.name = "fuzz";
        thespis::core::anim::Joint joint;
        joint.name = "j";
        joint.sourceName = "s";
        c.skeleton = std::move(thespis::core::anim::Skeleton::create({joint})).value();
        c.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        c.mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        c.mesh.indices = {0, 1, 2};
        scene::Segment segment;
        segment.name = "s";
        segment.vertexCount = 3;
        segment.triangleCount = 1;
        c.mesh.segments = {segment};
        c.face.targets = {{"a", {0}, {{0, 1, 0}}}, {"b", {1, 2}, {{1, 0, 0}, {0, 0, 1}}}};
        c.face.visemes[0] = {{3, 100}};
        return c;
    }();
    return character;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto first = scene::parseFaceMapping(text);
    if (!first) {
        if (first.error().message.empty() || first.error().code == thespis::core::ErrorCode::Internal)
            failure("an error without a message, or an internal one", first.error().message);
        return 0;
    }
    const std::string written = scene::serializeFaceMapping(*first);
    auto second = scene::parseFaceMapping(written);
    if (!second)
        failure("the writer's output does not read back", second.error().message + "\n" + written);
    if (!(*second == *first))
        failure("the table changed in a write/read round trip", written);
    if (scene::serializeFaceMapping(*second) != written)
        failure("writing is not stable", written);

    scene::Character character = smallCharacter();
    const std::vector<std::string> warnings = scene::applyFaceMapping(*first, character);
    std::set<std::string> missing;
    for (const scene::FaceMappingDrive& drive : first->drives)
        if (drive.target != "a" && drive.target != "b")
            missing.insert(drive.target);
    for (const scene::FaceMappingJoint& joint : first->joints)
        if (joint.joint != "j" && joint.joint != "s")
            missing.insert(joint.joint);
    if (warnings.size() != missing.size())
        failure("not one warning per missing name", written);
    if (auto valid = character.validateFace(); !valid)
        failure("an applied table leaves a face that does not validate", valid.error().message);
    return 0;
}
