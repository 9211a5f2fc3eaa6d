// Light probe layouts (pixel ↔ direction, see probe.h for the conventions) and radiance lookup.
// The SH projector, with exact per-pixel solid angles, is probe_projector.cpp's.

#include <algorithm>
#include <cmath>

#include "lighting/probe.h"
#include "lighting/probe_layout.h"

namespace thespis::core::lighting {

namespace {

Vec3d unit(Vec3d v)
{
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / n, v.y / n, v.z / n};
}

// ---- Disc layouts: unit-disc coordinates u (right), v (up) --------------------------------------

/// Direction at disc point (u, v) whose angle from the centre direction −z is θ; right is −x.
Vec3d discDirection(double u, double v, double theta)
{
    const double r = std::hypot(u, v);
    if (r < 1e-300)
        return {0.0, 0.0, -1.0};
    const double s = std::sin(theta) / r;
    return {-u * s, v * s, -std::cos(theta)};
}
double discTheta(ProbeLayout layout, double r)
{
    return layout == ProbeLayout::Angular ? kPi * r : 2.0 * std::asin(std::min(r, 1.0));
}

constexpr CrossFace kCrossFaces[6] = {
    {1, 0, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  // +y, top
    {0, 1, {-1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, // −x, left
    {1, 1, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}},  // −z, front (centre of the cross)
    {2, 1, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // +x, right
    {1, 2, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}},   // −y, below the front
    {1, 3, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    // +z, bottom: stored upside down
};

} // namespace

const CrossFace* crossFaceAt(int cellX, int cellY)
{
    for (const CrossFace& face : kCrossFaces)
        if (face.cellX == cellX && face.cellY == cellY)
            return &face;
    return nullptr;
}

Result<void> checkSize(ProbeLayout layout, int width, int height)
{
    const std::string size = std::to_string(width) + "×" + std::to_string(height);
    switch (layout) {
    case ProbeLayout::Angular:
    case ProbeLayout::MirrorBall:
        if (width != height || width < 8)
            return makeError(ErrorCode::InvalidArgument, std::string("An ") + (layout == ProbeLayout::Angular ? "angular map" : "mirror-ball image")
                                                             + " must be square and at least 8 pixels wide; this image is " + size + ".");
        break;
    case ProbeLayout::LatLong:
        if (width != 2 * height || height < 8)
            return makeError(ErrorCode::InvalidArgument,
                             "A latitude–longitude map must be twice as wide as it is high (2:1) and at least 16×8; this image is " + size + ".");
        break;
    case ProbeLayout::VerticalCross:
        if (width % 3 != 0 || 4 * width != 3 * height || width < 24)
            return makeError(ErrorCode::InvalidArgument,
                             "A vertical cross must be 3 faces wide and 4 high (width a multiple of 3, width:height = 3:4, "
                             "faces of at least 8 pixels); this image is " + size + ".");
        break;
    }
    return {};
}

namespace {

// ---- Direction of a continuous image point ------------------------------------------------------

/// Direction of the image point (px, py) in pixel units (0 … width, 0 … height).
bool pointDirection(ProbeLayout layout, int width, int height, double px, double py, Vec3d& direction)
{
    switch (layout) {
    case ProbeLayout::LatLong: {
        const double phi = 2.0 * kPi * (px / width - 0.5);
        const double theta = kPi * py / height;
        direction = {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
        return py >= 0.0 && py <= height;
    }
    case ProbeLayout::Angular:
    case ProbeLayout::MirrorBall: {
        const double u = (px - 0.5 * width) / (0.5 * width);
        const double v = (0.5 * height - py) / (0.5 * height);
        const double r = std::hypot(u, v);
        if (r > 1.0)
            return false;
        direction = discDirection(u, v, discTheta(layout, r));
        return true;
    }
    case ProbeLayout::VerticalCross: {
        const double faceSize = width / 3.0;
        const int cellX = int(std::floor(px / faceSize)), cellY = int(std::floor(py / faceSize));
        const CrossFace* face = crossFaceAt(cellX, cellY);
        if (!face)
            return false;
        const double a = 2.0 * (px / faceSize - cellX) - 1.0, b = 2.0 * (py / faceSize - cellY) - 1.0;
        direction = unit(face->centre + face->aAxis * a + face->bAxis * b);
        return true;
    }
    }
    return false;
}

/// Inverse of pointDirection: the image point (pixel units) that sees direction d (unit).
/// For the cross, also the pixel range of the face, so lookups stay on that face.
struct ImagePoint {
    double x = 0, y = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0; ///< pixels that a lookup may read, inclusive
};
ImagePoint imagePointOf(ProbeLayout layout, int width, int height, const Vec3d& d)
{
    ImagePoint p{0, 0, 0, 0, width - 1, height - 1};
    switch (layout) {
    case ProbeLayout::LatLong:
        p.x = (std::atan2(d.x, -d.z) / (2.0 * kPi) + 0.5) * width;
        p.y = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi * height;
        break;
    case ProbeLayout::Angular:
    case ProbeLayout::MirrorBall: {
        const double theta = std::acos(std::clamp(-d.z, -1.0, 1.0));
        const double r = layout == ProbeLayout::Angular ? theta / kPi : std::sin(0.5 * theta);
        const double s = std::hypot(d.x, d.y);
        const double u = s > 1e-300 ? -d.x / s * r : r, v = s > 1e-300 ? d.y / s * r : 0.0;
        p.x = 0.5 * width * (1.0 + u);
        p.y = 0.5 * height * (1.0 - v);
        break;
    }
    case ProbeLayout::VerticalCross: {
        const CrossFace* best = &kCrossFaces[0];
        for (const CrossFace& face : kCrossFaces)
            if (anim::dot(d, face.centre) > anim::dot(d, best->centre))
                best = &face;
        const double t = anim::dot(d, best->centre);
        const double a = anim::dot(d, best->aAxis) / t, b = anim::dot(d, best->bAxis) / t;
        const int faceSize = width / 3;
        p.x = (best->cellX + 0.5 * (a + 1.0)) * faceSize;
        p.y = (best->cellY + 0.5 * (b + 1.0)) * faceSize;
        p.x0 = best->cellX * faceSize;
        p.y0 = best->cellY * faceSize;
        p.x1 = p.x0 + faceSize - 1;
        p.y1 = p.y0 + faceSize - 1;
        break;
    }
    }
    return p;
}

} // namespace

const char* probeLayoutName(ProbeLayout layout)
{
    switch (layout) {
    case ProbeLayout::Angular: return "angular";
    case ProbeLayout::LatLong: return "latlong";
    case ProbeLayout::MirrorBall: return "mirrorball";
    case ProbeLayout::VerticalCross: return "cross";
    }
    return "";
}

Result<ProbeLayout> parseProbeLayout(std::string_view name)
{
    for (ProbeLayout layout : {ProbeLayout::Angular, ProbeLayout::LatLong, ProbeLayout::MirrorBall, ProbeLayout::VerticalCross})
        if (name == probeLayoutName(layout))
            return layout;
    return makeError(ErrorCode::InvalidArgument,
                     "Unknown probe layout '" + std::string(name) + "'; use angular, latlong, mirrorball or cross.");
}

Result<void> checkProbeSize(const HdrImage& image, ProbeLayout layout)
{
    return checkSize(layout, image.width, image.height);
}

bool directionOfPixel(ProbeLayout layout, int width, int height, double x, double y, Vec3d& direction)
{
    return pointDirection(layout, width, height, x + 0.5, y + 0.5, direction);
}

// ---- LightProbe ---------------------------------------------------------------------------------

Result<LightProbe> LightProbe::fromImage(HdrImage image, ProbeLayout layout)
{
    if (auto sized = checkProbeSize(image, layout); !sized)
        return sized.error();
    LightProbe probe;
    probe.m_layout = layout;
    probe.m_image = std::move(image);
    return probe;
}

Result<LightProbe> LightProbe::load(const std::filesystem::path& path, ProbeLayout layout)
{
    auto image = readHdrImage(path);
    if (!image)
        return image.error();
    auto probe = fromImage(std::move(*image), layout);
    if (!probe)
        return makeError(probe.error().code, path.string() + ": " + probe.error().message);
    return probe;
}

std::array<float, 3> LightProbe::radiance(const Vec3d& d) const
{
    const int w = m_image.width, h = m_image.height;
    const ImagePoint p = imagePointOf(m_layout, w, h, d);
    // Bilinear between pixel centres; lat-long wraps around in x, the others clamp (the cross to
    // the face that sees d).
    const double fx = p.x - 0.5, fy = p.y - 0.5;
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const double tx = fx - x0f, ty = fy - y0f;
    const auto column = [&](double x) {
        if (m_layout == ProbeLayout::LatLong)
            return int(((long long)x % w + w) % w);
        return int(std::clamp(x, double(p.x0), double(p.x1)));
    };
    const auto row = [&](double y) { return int(std::clamp(y, double(p.y0), double(p.y1))); };
    const int xa = column(x0f), xb = column(x0f + 1), ya = row(y0f), yb = row(y0f + 1);
    std::array<float, 3> out{};
    for (int c = 0; c < 3; ++c) {
        const double top = (1 - tx) * m_image.pixel(xa, ya)[c] + tx * m_image.pixel(xb, ya)[c];
        const double bottom = (1 - tx) * m_image.pixel(xa, yb)[c] + tx * m_image.pixel(xb, yb)[c];
        out[size_t(c)] = float((1 - ty) * top + ty * bottom);
    }
    return out;
}

} // namespace thespis::core::lighting
