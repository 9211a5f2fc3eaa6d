// Naming a humanoid rig by its rest shape, for rigs whose joint names no convention knows (the
// Khronos sample rigs have unnamed joints): see rig_naming.h and gltf_character.h.

#include "scene/rig_naming.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "anim/hanim.h"

namespace thespis::core::scene::rig_naming {
namespace {

/// A skeleton's rest pose seen from above: children, and per joint the lowest and highest point
/// and the centre of the joints below it (itself included). +Y is up.
class RestShape {
public:
    RestShape(const std::vector<int>& parents, const std::vector<Vec3d>& positions)
        : m_positions(positions), m_children(parents.size()), m_low(parents.size()), m_high(parents.size()),
          m_centre(parents.size()), m_count(parents.size(), 1)
    {
        for (std::size_t j = 0; j < parents.size(); ++j) {
            m_low[j] = m_high[j] = positions[j].y;
            m_centre[j] = positions[j];
            if (parents[j] >= 0)
                m_children[std::size_t(parents[j])].push_back(int(j));
        }
        for (std::size_t j = parents.size(); j-- > 1;) { // parents come first: children are done
            const auto p = std::size_t(parents[j]);
            m_low[p] = std::min(m_low[p], m_low[j]);
            m_high[p] = std::max(m_high[p], m_high[j]);
            m_centre[p] = m_centre[p] + m_centre[j];
            m_count[p] += m_count[j];
        }
        for (std::size_t j = 0; j < parents.size(); ++j)
            m_centre[j] = m_centre[j] * (1.0 / m_count[j]);
    }

    const Vec3d& position(int j) const { return m_positions[std::size_t(j)]; }
    const std::vector<int>& children(int j) const { return m_children[std::size_t(j)]; }
    double low(int j) const { return m_low[std::size_t(j)]; }
    double high(int j) const { return m_high[std::size_t(j)]; }
    const Vec3d& centre(int j) const { return m_centre[std::size_t(j)]; }

    /// From `j` down the child that reaches lowest, `length` joints at most.
    std::vector<int> chainDown(int j, std::size_t length) const
    {
        std::vector<int> chain{j};
        while (chain.size() < length && !children(chain.back()).empty()) {
            const auto& next = children(chain.back());
            chain.push_back(*std::min_element(next.begin(), next.end(), [&](int a, int b) { return low(a) < low(b); }));
        }
        return chain;
    }
    /// From `j` down through single children, up to the first joint that branches (a hand into
    /// fingers) or ends.
    std::vector<int> limb(int j) const
    {
        std::vector<int> chain{j};
        while (children(chain.back()).size() == 1)
            chain.push_back(children(chain.back()).front());
        return chain;
    }

private:
    const std::vector<Vec3d>& m_positions;
    std::vector<std::vector<int>> m_children;
    std::vector<double> m_low, m_high;
    std::vector<Vec3d> m_centre;
    std::vector<int> m_count;
};

} // namespace

std::vector<std::string> namesByShape(const std::vector<int>& parents, const std::vector<Vec3d>& positions)
{
    std::vector<std::string> names(parents.size());
    if (parents.empty())
        return names;
    const RestShape shape(parents, positions);
    const double height = shape.high(0) - shape.low(0);
    if (!(height > 0))
        return names;

    // The pelvis: the first joint with two children reaching well down (legs) and one reaching
    // well up (spine).
    int pelvis = -1;
    std::vector<int> legs, spines;
    for (int j = 0; j < int(parents.size()) && pelvis < 0; ++j) {
        const double y = shape.position(j).y;
        legs.clear();
        spines.clear();
        for (int c : shape.children(j)) {
            if (y - shape.low(c) > 0.2 * height && shape.high(c) - y < 0.1 * height)
                legs.push_back(c);
            else if (shape.high(c) - y > 0.2 * height && y - shape.low(c) < 0.1 * height)
                spines.push_back(c);
        }
        if (legs.size() >= 2 && !spines.empty())
            pelvis = j;
    }
    if (pelvis < 0)
        return names;
    std::sort(legs.begin(), legs.end(), [&](int a, int b) { return shape.low(a) < shape.low(b); });
    legs.resize(2);
    const int spineStart =
        *std::max_element(spines.begin(), spines.end(), [&](int a, int b) { return shape.high(a) < shape.high(b); });

    // Facing: where the toes point (glTF's +Z when the legs end at the ankles); left = up × forward.
    std::vector<int> legChains[2] = {shape.chainDown(legs[0], 4), shape.chainDown(legs[1], 4)};
    Vec3d forward{0, 0, 0};
    for (const auto& chain : legChains)
        if (chain.size() == 4)
            forward = forward + (shape.position(chain[3]) - shape.position(chain[2]));
    forward.y = 0;
    if (std::hypot(forward.x, forward.z) < 1e-3 * height)
        forward = {0, 0, 1};
    const Vec3d left{forward.z, 0, -forward.x};
    auto sideOf = [&](int first, int second, int from) {
        const Vec3d origin = shape.position(from);
        const bool firstIsLeft = anim::dot(shape.centre(first) - origin, left) >= anim::dot(shape.centre(second) - origin, left);
        return firstIsLeft ? std::pair{first, second} : std::pair{second, first};
    };

    names[std::size_t(pelvis)] = "humanoid_root";
    const auto [leftLeg, rightLeg] = sideOf(legs[0], legs[1], pelvis);
    for (const auto& [leg, side] : {std::pair{leftLeg, "l_"}, std::pair{rightLeg, "r_"}}) {
        const char* const kLeg[] = {"hip", "knee", "talocrural", "metatarsophalangeal"};
        const std::vector<int> chain = shape.chainDown(leg, 4);
        for (std::size_t i = 0; i < chain.size(); ++i)
            names[std::size_t(chain[i])] = std::string(side) + kLeg[i];
    }

    // The spine up to the joint where the arms and the neck branch.
    std::vector<int> spine{spineStart};
    while (shape.children(spine.back()).size() < 3) {
        const auto& next = shape.children(spine.back());
        if (next.empty())
            return names; // no arms: legs only
        spine.push_back(
            *std::max_element(next.begin(), next.end(), [&](int a, int b) { return shape.high(a) < shape.high(b); }));
    }
    const int chest = spine.back();
    std::vector<int> branches = shape.children(chest);
    auto lateral = [&](int c) { return std::abs(anim::dot(shape.centre(c) - shape.position(chest), left)); };
    std::sort(branches.begin(), branches.end(), [&](int a, int b) { return lateral(a) > lateral(b); });
    const auto [leftArm, rightArm] = sideOf(branches[0], branches[1], chest);
    const int neck = *std::max_element(branches.begin() + 2, branches.end(),
                                       [&](int a, int b) { return shape.high(a) < shape.high(b); });

    // Vertebrae of the paper's joint set, chosen by height between the root and the neck as in
    // the H-Anim rest pose, in order.
    const anim::Skeleton& standard = anim::hanim::skeleton(anim::hanim::Level::Subset25);
    const std::vector<Vec3d> standardPositions = standard.worldPositions(standard.restFrame());
    auto standardHeight = [&](const char* joint) { return standardPositions[std::size_t(standard.find(joint))].y; };
    const double rootY = standardHeight("humanoid_root"), neckY = standardHeight("vc4");
    const char* const kVertebrae[] = {"vl5", "vl1", "vt10", "vt6", "vt1"};
    const double pelvisY = shape.position(pelvis).y, spineTop = shape.position(neck).y - pelvisY;
    auto standardFraction = [&](std::size_t v) { return (standardHeight(kVertebrae[v]) - rootY) / (neckY - rootY); };
    std::size_t nextVertebra = 0;
    for (std::size_t i = 0; i < spine.size() && spineTop > 0 && nextVertebra < std::size(kVertebrae); ++i) {
        const double fraction = (shape.position(spine[i]).y - pelvisY) / spineTop;
        std::size_t best = nextVertebra;
        for (std::size_t v = nextVertebra; v < std::size(kVertebrae); ++v)
            if (std::abs(standardFraction(v) - fraction) < std::abs(standardFraction(best) - fraction))
                best = v;
        names[std::size_t(spine[i])] = kVertebrae[best];
        nextVertebra = best + 1;
    }

    const std::vector<int> neckChain = shape.limb(neck);
    if (neckChain.size() == 1)
        names[std::size_t(neckChain[0])] = "skullbase";
    else if (neckChain.size() >= 2) {
        names[std::size_t(neckChain[0])] = "vc4";
        names[std::size_t(neckChain[1])] = "skullbase";
    }
    for (const auto& [arm, side] : {std::pair{leftArm, "l_"}, std::pair{rightArm, "r_"}}) {
        const std::vector<int> chain = shape.limb(arm);
        const bool clavicle = chain.size() >= 4;
        const char* const kArm[] = {"sternoclavicular", "shoulder", "elbow", "radiocarpal"};
        for (std::size_t i = 0; i < chain.size() && i + (clavicle ? 0 : 1) < 4; ++i)
            names[std::size_t(chain[i])] = std::string(side) + kArm[i + (clavicle ? 0 : 1)];
    }
    return names;
}

} // namespace thespis::core::scene::rig_naming
