// The skin's picture of the default humanoid's head: skin, the lips' red, the brows' hair. It is
// laid over the face by a projection from the front (x → u, y → v); the back of the head and the
// face's far sides sample the picture's skin-only edges, so no feature can smear round the head.

#include <algorithm>
#include <cmath>

#include "scene/humanoid_face.h"
#include "scene/humanoid_face_layout.h"

namespace thespis::core::scene::humanoid {

namespace {

using namespace face;

constexpr int kTextureSize = 512;
constexpr double kLeft = -0.09, kWidth = 0.18, kTop = 1.80, kHeight = 0.26;
constexpr double kFront = 0.03; ///< z beyond which a skin point takes the projection

std::uint8_t toSrgb(double linear)
{
    linear = std::clamp(linear, 0.0, 1.0);
    const double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    return std::uint8_t(std::lround(255 * s));
}

double edge(double distance, double softness) { return smoothstep(0.5 - distance / softness); }

} // namespace

std::array<float, 2> faceTexcoord(Vec3d p)
{
    if (p.z < kFront) // the picture's top corner on this side: skin, reached from the side's edge
        return {p.x < 0 ? 0.0f : 1.0f, 0.0f};
    return {float(std::clamp((p.x - kLeft) / kWidth, 0.0, 1.0)), float(std::clamp((kTop - p.y) / kHeight, 0.0, 1.0))};
}

TextureImage makeFaceTexture(const std::array<float, 3>& skin)
{
    TextureImage image;
    image.name = "face";
    image.width = image.height = kTextureSize;
    image.rgba.resize(std::size_t(kTextureSize * kTextureSize * 4));
    const std::array<double, 3> lips{0.55, 0.17, 0.16}, brows{0.09, 0.05, 0.03};
    for (int row = 0; row < kTextureSize; ++row)
        for (int column = 0; column < kTextureSize; ++column) {
            const double x = kLeft + kWidth * (column + 0.5) / kTextureSize, y = kTop - kHeight * (row + 0.5) / kTextureSize;
            std::array<double, 3> colour{skin[0], skin[1], skin[2]};
            // The lips: between their outer borders, fading over half a millimetre.
            const double above = y - mouthLineY(x), inside = std::abs(x) < kMouthCorner + 0.002 ? 1.0 : 0.0;
            double lip = 0;
            if (above >= 0)
                lip = edge(above - upperLipHeight(x), 0.0008);
            else
                lip = edge(-above - lowerLipHeight(x), 0.0008);
            lip *= inside * edge(std::abs(x) - kMouthCorner, 0.0015);
            // The brows: a band over each eye, thickest at the middle, thinning outwards.
            double brow = 0;
            const double ax = std::abs(x);
            if (ax > kBrowInner - 0.003 && ax < kBrowOuter + 0.003) {
                const double t = std::clamp((ax - kBrowInner) / (kBrowOuter - kBrowInner), 0.0, 1.0);
                const double half = 0.0032 * (1 - 0.55 * t) + 0.0008;
                brow = edge(std::abs(y - browY(x)) - half, 0.0012) * edge(kBrowInner - 0.001 - ax, 0.003) *
                       edge(ax - kBrowOuter, 0.003) * 0.9;
            }
            for (int c = 0; c < 3; ++c) {
                colour[std::size_t(c)] += (lips[std::size_t(c)] - colour[std::size_t(c)]) * lip;
                colour[std::size_t(c)] += (brows[std::size_t(c)] - colour[std::size_t(c)]) * brow;
            }
            std::uint8_t* texel = &image.rgba[std::size_t((row * kTextureSize + column) * 4)];
            for (int c = 0; c < 3; ++c)
                texel[c] = toSrgb(colour[std::size_t(c)]);
            texel[3] = 255;
        }
    return image;
}

} // namespace thespis::core::scene::humanoid
