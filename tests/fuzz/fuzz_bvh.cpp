// libFuzzer target for the BVH reader (core/anim/bvh.cpp) and the joint mapping file reader.
//
// Any bytes must give a clip or an error, never a crash, undefined behaviour or a leak. Beyond
// not crashing, it checks the contracts of the reader:
//   - an error is NotOurFormat, or CorruptData whose message starts with "line N: ";
//   - whatever the reader accepts, the writer writes and the reader reads back, with the same
//     joints, frames, frame rate, and every rotation within 1e-4 rad and translation exact
//     (this fuzzes the Euler decomposition of every rotation order, gimbal lock included).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "anim/bvh.h"

namespace {

using namespace thespis::core;
using namespace thespis::core::anim;

[[noreturn]] void fail(const char* what, const std::string& detail = {})
{
    std::fprintf(stderr, "fuzz_bvh: %s %s\n", what, detail.c_str());
    std::abort();
}

void checkError(const Error& error)
{
    if (error.code == ErrorCode::NotOurFormat)
        return;
    if (error.code != ErrorCode::CorruptData)
        fail("unexpected error code:", describe(error));
    if (error.message.rfind("line ", 0) != 0)
        fail("an error that does not name its line:", error.message);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);

    if (auto mapping = bvh::parseMapping(text); !mapping)
        checkError(mapping.error());

    auto imported = bvh::parse(text);
    if (!imported) {
        checkError(imported.error());
        return 0;
    }
    const bvh::ImportedClip& a = *imported;
    const std::string written = bvh::write(a.skeleton, *a.clip);
    auto back = bvh::parse(written);
    if (!back)
        fail("the writer's output does not read back:", describe(back.error()) + "\n" + written);
    const bvh::ImportedClip& b = *back;
    if (b.skeleton.jointCount() != a.skeleton.jointCount() || b.clip->frameCount() != a.clip->frameCount()
        || b.clip->layout()->floatCount() != a.clip->layout()->floatCount())
        fail("the round trip changed the joints or frames");
    if (std::abs(b.clip->frameRate() - a.clip->frameRate()) > 1e-12 * a.clip->frameRate())
        fail("the round trip changed the frame rate");
    // Joints keep their order when the skeleton is in depth-first order, as a parsed one is.
    const FrameLayout& layout = *a.clip->layout();
    for (int f = 0; f < a.clip->frameCount(); ++f) {
        const auto fa = a.clip->frame(f), fb = b.clip->frame(f);
        for (int r = 0; r < layout.rotationCount(); ++r) {
            const Quat& qa = rotationAt(fa, r);
            const Quat& qb = rotationAt(fb, r);
            // Angle of qa⁻¹·qb in double, from its vector part: accurate for small angles.
            const Quatd da = normalize(Quatd{qa.x, qa.y, qa.z, qa.w});
            const Quatd db = normalize(Quatd{qb.x, qb.y, qb.z, qb.w});
            const Quatd delta = conjugate(da) * db;
            const double angle = 2 * std::atan2(std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z),
                                                std::abs(delta.w));
            if (!(angle <= 1e-4))
                fail("a rotation changed in the round trip, joint:", layout.name(r));
        }
        for (std::size_t k = layout.translationOffset(); k < layout.floatCount(); ++k)
            if (fa[k] != fb[k])
                fail("a translation changed in the round trip");
    }
    return 0;
}
