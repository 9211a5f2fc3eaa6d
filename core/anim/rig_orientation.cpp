#include "anim/rig_orientation.h"

#include <cmath>

namespace thespis::core::anim {

namespace {

// The principal axis nearest to v: index 0..2 and sign; -1 when v is zero.
std::pair<int, int> nearestAxis(const Vec3d& v)
{
    const double a[3] = {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
    const double s[3] = {v.x, v.y, v.z};
    int best = 0;
    for (int i = 1; i < 3; ++i)
        if (a[i] > a[best])
            best = i;
    if (!(a[best] > 0))
        return {-1, 0};
    return {best, s[best] > 0 ? 1 : -1};
}

std::string axisName(int axis, int sign)
{
    return std::string(sign > 0 ? "+" : "−") + char('X' + axis);
}

} // namespace

bool AxisTurn::isIdentity() const
{
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (matrix[r][c] != (r == c ? 1 : 0))
                return false;
    return true;
}

Vec3d AxisTurn::apply(const Vec3d& v) const
{
    const double in[3] = {v.x, v.y, v.z};
    double out[3];
    for (int r = 0; r < 3; ++r)
        out[r] = matrix[r][0] * in[0] + matrix[r][1] * in[1] + matrix[r][2] * in[2];
    return {out[0], out[1], out[2]};
}

AxisTurn uprightTurn(const Skeleton& skeleton)
{
    AxisTurn turn;
    const std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
    const auto at = [&](const char* name) -> const Vec3d* {
        const int j = skeleton.find(name);
        return j >= 0 ? &rest[std::size_t(j)] : nullptr;
    };
    const Vec3d* root = at("humanoid_root");
    const Vec3d* top = nullptr;
    for (const char* name : {"skullbase", "vc2", "vc4", "vt1", "vt6", "vl1"})
        if ((top = at(name)))
            break;
    Vec3d left{};
    int pairs = 0;
    for (const auto& [l, r] : {std::pair{"l_hip", "r_hip"}, std::pair{"l_shoulder", "r_shoulder"}})
        if (const Vec3d *a = at(l), *b = at(r); a && b) {
            left = left + (*a - *b);
            ++pairs;
        }
    if (!root || !top || pairs == 0)
        return turn;
    const auto [upAxis, upSign] = nearestAxis(*top - *root);
    const auto [leftAxis, leftSign] = nearestAxis(left);
    if (upAxis < 0 || leftAxis < 0 || upAxis == leftAxis)
        return turn;
    // Rows: new X = the rig's left, new Y = its up, new Z = X × Y (its facing).
    int m[3][3] = {};
    m[0][leftAxis] = leftSign;
    m[1][upAxis] = upSign;
    const int x[3] = {m[0][0], m[0][1], m[0][2]}, y[3] = {m[1][0], m[1][1], m[1][2]};
    m[2][0] = x[1] * y[2] - x[2] * y[1];
    m[2][1] = x[2] * y[0] - x[0] * y[2];
    m[2][2] = x[0] * y[1] - x[1] * y[0];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            turn.matrix[r][c] = m[r][c];
    if (!turn.isIdentity()) {
        int faceAxis = 0;
        for (int c = 0; c < 3; ++c)
            if (m[2][c] != 0)
                faceAxis = c;
        turn.description = axisName(upAxis, upSign) + " up, facing " + axisName(faceAxis, m[2][faceAxis]);
    }
    return turn;
}

void applyTurn(const AxisTurn& turn, std::vector<Joint>& joints)
{
    for (Joint& joint : joints) {
        joint.offset = turn.apply(joint.offset);
        if (joint.endSite)
            joint.endSite = turn.apply(*joint.endSite);
    }
}

void applyTurn(const AxisTurn& turn, const FrameLayout& layout, std::span<float> frames)
{
    if (turn.isIdentity())
        return;
    // A proper rotation R turns a quaternion's vector part by R and keeps its scalar part.
    const std::size_t width = layout.floatCount();
    const std::size_t translations = layout.translationOffset();
    for (std::size_t frame = 0; frame + width <= frames.size(); frame += width) {
        for (std::size_t r = 0; r < std::size_t(layout.rotationCount()); ++r) {
            float* q = &frames[frame + 4 * r];
            const Vec3d v = turn.apply(Vec3d{q[0], q[1], q[2]});
            q[0] = float(v.x), q[1] = float(v.y), q[2] = float(v.z);
        }
        for (std::size_t t = 0; t < std::size_t(layout.translationCount()); ++t) {
            float* p = &frames[frame + translations + 3 * t];
            const Vec3d v = turn.apply(Vec3d{p[0], p[1], p[2]});
            p[0] = float(v.x), p[1] = float(v.y), p[2] = float(v.z);
        }
    }
}

Quatd turnRotation(const AxisTurn& turn)
{
    // Shepperd's method on a signed permutation matrix (entries 0 / ±1).
    const auto& m = turn.matrix;
    const double trace = m[0][0] + m[1][1] + m[2][2];
    Quatd q;
    if (trace > 0) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        q = {(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s};
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        q = {0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s};
    } else if (m[1][1] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        q = {(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        q = {(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s};
    }
    return normalize(q);
}

} // namespace thespis::core::anim
