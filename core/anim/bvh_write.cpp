// Writing BVH (bvh::write and save): the hierarchy with each joint's source name, rotation
// order and End Site, and the motion as Euler angles kept continuous from frame to frame.

#include "anim/bvh.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <set>

#include "anim/bvh_euler.h"
#include "anim/bvh_text.h"
#include "util/file_io.h"

namespace thespis::core::anim::bvh {
namespace {

void appendNumber(std::string& out, double value)
{
    if (value == 0)
        value = 0; // no "-0"
    char buffer[32];
    const int n = std::snprintf(buffer, sizeof buffer, "%.9g", value);
    out.append(buffer, std::size_t(std::max(0, n)));
}

/// The shortest decimal frame time whose reciprocal is exactly `rate`, so that the file reads
/// back with the same frame rate, bit for bit ("0.0083333", not "0.0083333000000000001").
std::string frameTimeText(double rate)
{
    const double seconds = 1.0 / rate;
    char buffer[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, seconds);
        double back = 0;
        std::from_chars(buffer, buffer + std::char_traits<char>::length(buffer), back);
        if (back > 0 && 1.0 / back == rate)
            return buffer;
    }
    std::snprintf(buffer, sizeof buffer, "%.17g", seconds);
    return buffer;
}

/// The axes of a rotation order ("ZXY" → 2 0 1); letters other than X Y Z, or repeated ones,
/// fall back to ZXY (the common BVH order).
std::vector<int> orderAxes(const std::string& order)
{
    std::vector<int> axes;
    for (char c : order) {
        const int axis = c == 'X' || c == 'x' ? 0 : c == 'Y' || c == 'y' ? 1 : c == 'Z' || c == 'z' ? 2 : -1;
        if (axis < 0 || std::find(axes.begin(), axes.end(), axis) != axes.end() || axes.size() == 3)
            return {2, 0, 1};
        axes.push_back(axis);
    }
    return axes;
}

std::string writableName(const Joint& joint, int index)
{
    std::string name = joint.sourceName.empty() ? joint.name : joint.sourceName;
    for (char& c : name)
        if (isSpace(c) || c == '{' || c == '}')
            c = '_';
    return name.empty() ? "joint" + std::to_string(index) : name;
}

} // namespace

std::string write(const Skeleton& skeleton, const KeyframeClip& clip)
{
    const int jointCount = skeleton.jointCount();
    const FrameLayout& layout = *clip.layout();

    // Children and depth-first order (parents come before children in a Skeleton).
    std::vector<std::vector<int>> children(static_cast<std::size_t>(jointCount));
    for (int j = 1; j < jointCount; ++j)
        children[std::size_t(skeleton.joint(j).parent)].push_back(j);

    // File names: source names where known, unique.
    std::vector<std::string> names;
    std::set<std::string> taken;
    for (int j = 0; j < jointCount; ++j) {
        std::string name = writableName(skeleton.joint(j), j);
        for (int n = 2; taken.count(name); ++n)
            name = writableName(skeleton.joint(j), j) + "_" + std::to_string(n);
        taken.insert(name);
        names.push_back(std::move(name));
    }

    struct Plan {
        int joint;
        std::vector<int> axes; // rotation channels
        int rotation;          // rotation element in the clip's layout, or -1
        int translation;       // translation element in the clip's layout, or -1
    };
    std::vector<Plan> plans;

    std::string out = "HIERARCHY\n";
    // Iterative depth-first walk: (joint, next child index).
    std::vector<std::pair<int, std::size_t>> stack{{0, 0}};
    auto indent = [&](std::size_t depth) { out.append(depth, '\t'); };
    auto openJoint = [&](int j, std::size_t depth) {
        const Joint& joint = skeleton.joint(j);
        indent(depth);
        out += (j == 0 ? "ROOT " : "JOINT ") + names[std::size_t(j)] + "\n";
        indent(depth);
        out += "{\n";
        indent(depth + 1);
        out += "OFFSET ";
        appendNumber(out, joint.offset.x);
        out += ' ';
        appendNumber(out, joint.offset.y);
        out += ' ';
        appendNumber(out, joint.offset.z);
        out += '\n';
        Plan plan{j, joint.rotationOrder.empty() ? std::vector<int>{} : orderAxes(joint.rotationOrder),
                  layout.find(joint.name, ElementKind::Rotation), layout.find(joint.name, ElementKind::Translation)};
        const bool translates = j == 0 || joint.translates;
        indent(depth + 1);
        out += "CHANNELS " + std::to_string((translates ? 3 : 0) + plan.axes.size());
        if (translates)
            out += " Xposition Yposition Zposition";
        for (int axis : plan.axes)
            out += std::string(" ") + char('X' + axis) + "rotation";
        out += '\n';
        if (!translates)
            plan.translation = -2; // no position channels
        plans.push_back(std::move(plan));
    };
    auto closeJoint = [&](int j, std::size_t depth) {
        const Joint& joint = skeleton.joint(j);
        std::optional<Vec3d> endSite = joint.endSite;
        if (!endSite && children[std::size_t(j)].empty())
            endSite = joint.offset * 0.5; // a leaf needs an end for its bone; continue its direction
        if (endSite) {
            indent(depth + 1);
            out += "End Site\n";
            indent(depth + 1);
            out += "{\n";
            indent(depth + 2);
            out += "OFFSET ";
            appendNumber(out, endSite->x);
            out += ' ';
            appendNumber(out, endSite->y);
            out += ' ';
            appendNumber(out, endSite->z);
            out += '\n';
            indent(depth + 1);
            out += "}\n";
        }
        indent(depth);
        out += "}\n";
    };

    openJoint(0, 0);
    while (!stack.empty()) {
        auto& [j, next] = stack.back();
        const std::size_t depth = stack.size() - 1;
        if (next < children[std::size_t(j)].size()) {
            const int child = children[std::size_t(j)][next++];
            openJoint(child, depth + 1);
            stack.emplace_back(child, 0);
        } else {
            closeJoint(j, depth);
            stack.pop_back();
        }
    }

    out += "MOTION\nFrames: " + std::to_string(clip.frameCount()) + "\nFrame Time: " + frameTimeText(clip.frameRate())
           + "\n";

    // Per joint, the previous frame's Euler angles: each frame picks, of the two Euler
    // solutions and their 360° turns, the one nearest to it, so curves in an animation tool
    // stay continuous.
    std::vector<std::array<double, 3>> previous(plans.size(), {0, 0, 0});
    for (int f = 0; f < clip.frameCount(); ++f) {
        const std::span<const float> frame = clip.frame(f);
        bool firstValue = true;
        auto value = [&](double v) {
            if (!firstValue)
                out += ' ';
            firstValue = false;
            appendNumber(out, v);
        };
        for (std::size_t p = 0; p < plans.size(); ++p) {
            const Plan& plan = plans[p];
            const Joint& joint = skeleton.joint(plan.joint);
            if (plan.translation != -2) {
                if (plan.translation >= 0) {
                    const std::size_t t = layout.floatOffset(plan.translation);
                    value(frame[t]);
                    value(frame[t + 1]);
                    value(frame[t + 2]);
                } else {
                    value(joint.offset.x);
                    value(joint.offset.y);
                    value(joint.offset.z);
                }
            }
            if (plan.axes.empty())
                continue;
            Quatd q = Quatd::identity();
            if (plan.rotation >= 0) {
                const Quat& r = rotationAt(frame, plan.rotation);
                q = {r.x, r.y, r.z, r.w};
            }
            // Complete a partial order (a joint with fewer than three rotation channels) with the
            // missing axes; the angles of those come out zero for motion such a joint can make.
            std::array<int, 3> axes{};
            std::size_t n = 0;
            for (int axis : plan.axes)
                axes[n++] = axis;
            for (int axis = 0; axis < 3 && n < 3; ++axis)
                if (std::find(plan.axes.begin(), plan.axes.end(), axis) == plan.axes.end())
                    axes[n++] = axis;
            const Matrix3 m = toMatrix(q);
            std::array<double, 3>& prev = previous[p];
            const std::array<double, 3> primary = decompose(m, axes[0], axes[1], axes[2], prev[2]);
            const double pi = std::numbers::pi;
            const std::array<double, 3> alternative = {primary[0] + pi, pi - primary[1], primary[2] + pi};
            std::array<double, 3> best{};
            double bestCost = std::numeric_limits<double>::infinity();
            for (const auto& candidate : {primary, alternative}) {
                std::array<double, 3> c = candidate;
                double cost = 0;
                for (int k = 0; k < 3; ++k) {
                    c[std::size_t(k)] = unwrapNear(c[std::size_t(k)], f == 0 ? 0.0 : prev[std::size_t(k)]);
                    const bool written = std::size_t(k) < plan.axes.size();
                    const double d = c[std::size_t(k)] - (f == 0 || !written ? 0.0 : prev[std::size_t(k)]);
                    // Angles of axes that are not written must be (near) zero; first frames
                    // prefer small angles.
                    cost += written ? d * d : 1e6 * d * d;
                }
                if (cost < bestCost) {
                    bestCost = cost;
                    best = c;
                }
            }
            // Continuity lets angles grow past ±180° on a spinning joint; beyond five turns they
            // are brought back near zero, so that 9 significant digits keep 1e-5° resolution.
            for (double& a : best)
                if (std::abs(a) > 10 * pi)
                    a = std::remainder(a, 2 * pi);
            prev = best;
            for (std::size_t k = 0; k < plan.axes.size(); ++k)
                value(best[k] * (180.0 / pi));
        }
        out += '\n';
    }
    return out;
}

Result<void> save(const std::filesystem::path& path, const Skeleton& skeleton, const KeyframeClip& clip)
{
    return writeFileAtomically(path, write(skeleton, clip));
}

} // namespace thespis::core::anim::bvh
