#include "anim/retarget.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <new>
#include <string_view>

#include "anim/body_measure.h"

namespace thespis::core::anim {

namespace {

Vec3 toFloat(const Vec3d& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}

double length(const Vec3d& v)
{
    return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

// The smallest rotation taking unit direction a onto unit direction b.
Quatd rotationBetween(const Vec3d& a, const Vec3d& b)
{
    const double d = a.x * b.x + a.y * b.y + a.z * b.z;
    if (d < -1.0 + 1e-12) { // opposite: half a turn about any axis normal to a
        Vec3d axis = std::abs(a.x) < 0.9 ? Vec3d{0, -a.z, a.y} : Vec3d{a.z, 0, -a.x};
        const double n = length(axis);
        return {axis.x / n, axis.y / n, axis.z / n, 0.0};
    }
    return normalize(Quatd{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x, 1.0 + d});
}

bool isIdentity(const Quatd& q)
{
    return std::abs(q.x) < 1e-9 && std::abs(q.y) < 1e-9 && std::abs(q.z) < 1e-9;
}

// Source joints from the root down to `joint` (both included).
std::vector<int> chainFromRoot(const Skeleton& skeleton, int joint)
{
    std::vector<int> chain;
    for (int j = joint; j >= 0; j = skeleton.joint(j).parent)
        chain.push_back(j);
    std::reverse(chain.begin(), chain.end());
    return chain;
}

// How a target joint's rest is aligned with the source's. Rest poses differ in how the limbs are
// held (a T-pose, legs apart, arms at the sides): limb bones are turned onto the source's. The
// trunk, the head and the feet stand upright and flat in every rest pose, and their bones differ
// by build, not by pose (the curve of a spine, how high the ankle is over the ball of the foot):
// they keep the source's rotations as they are. Everything else (hands, fingers, joints outside
// H-Anim) follows its mapped ancestor.
enum class RestAlignment { Limb, Upright, Inherit };

RestAlignment restAlignment(std::string_view name)
{
    std::string_view base = name;
    if (base.starts_with("l_") || base.starts_with("r_"))
        base.remove_prefix(2);
    for (std::string_view limb : {"hip", "knee", "sternoclavicular", "acromioclavicular", "shoulder", "elbow"})
        if (base == limb)
            return RestAlignment::Limb;
    if (base == "humanoid_root" || base == "sacroiliac" || base == "skullbase" || base == "talocrural"
        || base.starts_with("tarso") || base.starts_with("metatarso") || base.starts_with("tarsal_")
        || ((base.starts_with("vl") || base.starts_with("vt") || base.starts_with("vc")) && base.size() <= 4))
        return RestAlignment::Upright;
    return RestAlignment::Inherit;
}

// A body with soles known better than measureBody()'s guess (none given: as it is).
BodyMeasure withSoles(BodyMeasure body, const std::vector<BodyMeasure::SolePoint>& soles)
{
    if (soles.empty())
        return body;
    body.soles = soles;
    std::vector<double> heights;
    for (const BodyMeasure::SolePoint& sole : body.soles)
        heights.push_back(body.restPositions[std::size_t(sole.joint)].y + sole.offset.y);
    body.footRestHeight = footHeight<double>(heights, body.footSoftness);
    return body;
}

// Uninitialized room for a tree's values (an array of bytes holds them: they are trivially
// copyable and destructible).
template <class T, std::size_t N>
struct Room {
    alignas(T) unsigned char bytes[sizeof(T) * N];
    T* get() { return std::launder(reinterpret_cast<T*>(bytes)); }
};

} // namespace

FrameRetarget::ChainStep FrameRetarget::chainStep(const Skeleton& skeleton, int joint)
{
    ChainStep step;
    step.rotation = skeleton.frameLayout()->floatOffset(joint);
    const int element = skeleton.translationElement(joint);
    step.translation = element >= 0 ? int(skeleton.frameLayout()->floatOffset(element)) : -1;
    step.offset = toFloat(skeleton.joint(joint).offset);
    return step;
}

std::uint32_t FrameRetarget::addChain(const Skeleton& skeleton, std::span<const int> chain, Tree& tree,
                                      std::map<int, std::uint32_t>& places)
{
    int parent = -1;
    for (int joint : chain) {
        auto [at, added] = places.try_emplace(joint, std::uint32_t(tree.size()));
        if (added)
            tree.push_back({chainStep(skeleton, joint), parent});
        parent = int(at->second);
    }
    return std::uint32_t(parent);
}

void FrameRetarget::treePoses(const Tree& tree, std::size_t count, std::span<const float> frame, bool fromOrigin,
                              Vec3* positions, Quat* orientations)
{
    const auto offsetOf = [&](const ChainStep& step) {
        if (step.translation < 0)
            return step.offset;
        const float* t = &frame[std::size_t(step.translation)];
        return Vec3{t[0], t[1], t[2]};
    };
    for (std::size_t k = 0; k < count; ++k) {
        const ChainStep& step = tree[k].step;
        const float* q = &frame[step.rotation];
        const Quat rotation{q[0], q[1], q[2], q[3]};
        if (const int parent = tree[k].parent; parent < 0) {
            positions[k] = fromOrigin ? offsetOf(step) : Vec3{};
            orientations[k] = rotation;
        } else {
            positions[k] = positions[parent] + rotate(orientations[parent], offsetOf(step));
            orientations[k] = orientations[parent] * rotation;
        }
    }
}

FrameRetarget::FrameRetarget(const Skeleton& from, const Skeleton& to, const RetargetOptions& options)
{
    const FrameLayout& fromLayout = *from.frameLayout();
    const FrameLayout& toLayout = *to.frameLayout();
    const BodyMeasure fromBody = withSoles(measureBody(from), options.sourceSoles);
    const BodyMeasure toBody = withSoles(measureBody(to), options.targetSoles);
    const std::size_t count = std::size_t(to.jointCount());

    if (options.scale > 0) {
        m_scale = options.scale;
        m_scaleSource = ScaleSource::Given;
    } else if (fromBody.hasLegs() && toBody.hasLegs()) {
        m_scale = toBody.legLength / fromBody.legLength;
        m_scaleSource = ScaleSource::Legs;
    } else if (options.sourceUnit > 0) {
        m_scale = options.sourceUnit;
        m_scaleSource = ScaleSource::Unit;
    } else if (const double fromHeight = fromBody.restPositions[0].y, toHeight = toBody.restPositions[0].y;
               fromHeight > 0 && toHeight > 0 && from.joint(0).name == to.joint(0).name) {
        // Two roots of the same name standing over the floor: their heights are the bodies' sizes.
        m_scale = toHeight / fromHeight;
        m_scaleSource = ScaleSource::RootHeight;
    }
    m_scaleF = float(m_scale);

    std::vector<int> source(count, -1);
    for (std::size_t j = 0; j < count; ++j)
        source[j] = from.find(to.joint(int(j)).name);

    // Which target joints have a mapped joint at or below them (children come after parents).
    std::vector<bool> mappedBelow(count, false);
    for (std::size_t j = count; j-- > 0;) {
        mappedBelow[j] = mappedBelow[j] || source[j] >= 0;
        if (const int parent = to.joint(int(j)).parent; parent >= 0 && mappedBelow[j])
            mappedBelow[std::size_t(parent)] = true;
    }
    std::vector<std::vector<int>> children(count);
    for (std::size_t j = 1; j < count; ++j)
        if (const int parent = to.joint(int(j)).parent; parent >= 0)
            children[std::size_t(parent)].push_back(int(j));

    // Rest alignment of each mapped limb joint: along its one chain of mapped joints below, the
    // first whose bone has a length in both rigs. Upright joints have none; the rest, and a limb
    // joint whose bone is not defined, keep their mapped ancestor's.
    const double fromTiny = 1e-4 * std::max(fromBody.legLength, 1e-6);
    const double toTiny = 1e-4 * std::max(toBody.legLength, 1e-6);
    std::vector<Quatd> align(count);
    std::vector<int> mappedAncestor(count, -1);
    for (std::size_t j = 0; j < count; ++j) {
        const int parent = to.joint(int(j)).parent;
        if (parent >= 0)
            mappedAncestor[j] = source[std::size_t(parent)] >= 0 ? parent : mappedAncestor[std::size_t(parent)];
        const RestAlignment alignment = restAlignment(to.joint(int(j)).name);
        if (alignment == RestAlignment::Upright) {
            // A foot the source does not hold flat when it stands (CMU's rest foot points up
            // from where it stands): turned so that it is flat then.
            if (const auto flat = options.flatFeet.find(to.joint(int(j)).name); flat != options.flatFeet.end())
                align[j] = Quatd{flat->second.x, flat->second.y, flat->second.z, flat->second.w};
            continue;
        }
        align[j] = mappedAncestor[j] >= 0 ? align[std::size_t(mappedAncestor[j])] : Quatd{};
        if (source[j] < 0 || alignment != RestAlignment::Limb)
            continue;
        int at = int(j);
        while (true) {
            std::vector<int> next;
            for (int c : children[std::size_t(at)])
                if (mappedBelow[std::size_t(c)])
                    next.push_back(c);
            if (next.size() != 1)
                break;
            at = next.front();
            if (source[std::size_t(at)] < 0)
                continue;
            const Vec3d toDir = toBody.restPositions[std::size_t(at)] - toBody.restPositions[j];
            const Vec3d fromDir = fromBody.restPositions[std::size_t(source[std::size_t(at)])]
                                  - fromBody.restPositions[std::size_t(source[j])];
            const double toLength = length(toDir), fromLength = length(fromDir);
            if (toLength > toTiny && fromLength > fromTiny) {
                align[j] = rotationBetween(toDir * (1.0 / toLength), fromDir * (1.0 / fromLength));
                break;
            }
        }
    }

    // Rotations.
    for (std::size_t j = 0; j < count; ++j) {
        const std::size_t toRotation = toLayout.floatOffset(int(j));
        if (source[j] < 0) {
            m_restRotations.push_back(toRotation);
            continue;
        }
        ++m_mappedJoints;
        RotationMap map;
        map.to = toRotation;
        const int ancestor = mappedAncestor[j];
        if (ancestor >= 0 && !isIdentity(align[std::size_t(ancestor)])) {
            const Quatd& a = align[std::size_t(ancestor)];
            map.before = Quat{float(-a.x), float(-a.y), float(-a.z), float(a.w)};
            map.hasBefore = true;
        }
        if (!isIdentity(align[j])) {
            map.after = Quat{float(align[j].x), float(align[j].y), float(align[j].z), float(align[j].w)};
            map.hasAfter = true;
        }
        // Source chains below the common ancestor of the two source joints.
        const std::vector<int> down = chainFromRoot(from, source[j]);
        const std::vector<int> up = ancestor >= 0 ? chainFromRoot(from, source[std::size_t(ancestor)]) : std::vector<int>{};
        std::size_t common = 0;
        while (common < up.size() && common < down.size() && up[common] == down[common])
            ++common;
        map.upBegin = std::uint32_t(m_path.size());
        for (std::size_t k = common; k < up.size(); ++k)
            m_path.push_back(fromLayout.floatOffset(up[k]));
        map.upEnd = map.downBegin = std::uint32_t(m_path.size());
        for (std::size_t k = common; k < down.size(); ++k)
            m_path.push_back(fromLayout.floatOffset(down[k]));
        map.downEnd = std::uint32_t(m_path.size());
        m_rotations.push_back(map);
    }

    // Placing the body. The anchor is the first mapped joint (parents come first, so none of its
    // ancestors maps and they all rest). Its position, or better the middle of the hips when both
    // rigs have them (the legs hang from there, whatever the pelvis between is like), follows the
    // source's scaled; the translation written is the anchor's own when it has one, else the root's.
    const auto anchorIt = std::find_if(source.begin(), source.end(), [](int s) { return s >= 0; });
    const int anchor = anchorIt == source.end() ? -1 : int(anchorIt - source.begin());
    int placedElement = -1;
    if (anchor >= 0) {
        const int placed = to.translationElement(anchor) >= 0 ? anchor : 0;
        placedElement = to.translationElement(placed);
        std::vector<int> points;
        for (const char* hip : {"l_hip", "r_hip"}) {
            const int j = to.find(hip);
            if (j < 0 || source[std::size_t(j)] < 0)
                break;
            const std::vector<int> chain = chainFromRoot(to, j);
            if (std::find(chain.begin(), chain.end(), placed) == chain.end())
                break;
            points.push_back(j);
        }
        if (points.size() != 2)
            points = {anchor};
        Vec3d fromMean{}, toMean{};
        std::map<int, std::uint32_t> sourcePlaces, targetPlaces;
        for (int point : points) {
            const int fromPoint = source[std::size_t(point)];
            fromMean = fromMean + fromBody.restPositions[std::size_t(fromPoint)] * (1.0 / double(points.size()));
            toMean = toMean + toBody.restPositions[std::size_t(point)] * (1.0 / double(points.size()));
            m_sourcePoints.push_back(addChain(from, chainFromRoot(from, fromPoint), m_sourceTree, sourcePlaces));
            const std::vector<int> chain = chainFromRoot(to, point);
            const auto first = std::find(chain.begin(), chain.end(), placed);
            m_targetPoints.push_back(addChain(to, std::span(first, chain.end()), m_targetTree, targetPlaces));
        }
        m_sourcePlacementJoints = m_sourceTree.size();
        // Where the source stands at rest: its rest pose, or, for a rig hanging from y = 0, that
        // pose lifted until its lowest foot joint is as high as the target's (scaled back).
        if (!fromBody.standsOnGround() && fromBody.hasFeet())
            fromMean.y += -fromBody.footRestHeight + (toBody.hasFeet() ? toBody.footRestHeight : 0.0) / m_scale;
        const int parent = to.joint(placed).parent;
        const Vec3d base = parent >= 0 ? toBody.restPositions[std::size_t(parent)] : Vec3d{};
        m_placedTranslation = toLayout.floatOffset(placedElement);
        m_placeAdd = toFloat(toMean - fromMean * m_scale - base);
        m_placedBaseY = float(base.y);

        // Feet, when both bodies have them below the placed joint and the source's floor is known.
        std::optional<double> planted = options.sourcePlantedFeet;
        if (!planted && fromBody.standsOnGround())
            planted = fromBody.footRestHeight;
        // Chains to every foot joint (source from its root, target from the placed joint), and
        // the sole points on them.
        const auto reachable = [&](int joint) {
            const std::vector<int> chain = chainFromRoot(to, joint);
            return std::find(chain.begin(), chain.end(), placed) != chain.end();
        };
        const bool feetBelow = std::all_of(toBody.footJoints.begin(), toBody.footJoints.end(), reachable);
        if (planted && fromBody.hasFeet() && toBody.hasFeet() && feetBelow && fromBody.soles.size() <= kMaxSoles
            && toBody.soles.size() <= kMaxSoles) {
            m_matchFeet = true;
            m_sourcePlanted = float(*planted);
            m_targetFeetRest = float(toBody.footRestHeight);
            m_sourceSoftness = float(fromBody.footSoftness);
            m_targetSoftness = float(toBody.footSoftness);
            const auto addSoles = [&](const BodyMeasure& body, const Skeleton& skeleton, int firstJoint, Tree& tree,
                                      std::map<int, std::uint32_t>& places, std::vector<Sole>& soles) {
                for (const BodyMeasure::SolePoint& sole : body.soles) {
                    const std::vector<int> chain = chainFromRoot(skeleton, sole.joint);
                    const auto first = std::find(chain.begin(), chain.end(), firstJoint);
                    soles.push_back({addChain(skeleton, std::span(first, chain.end()), tree, places), toFloat(sole.offset)});
                }
            };
            addSoles(fromBody, from, 0, m_sourceTree, sourcePlaces, m_sourceSoles);
            addSoles(toBody, to, placed, m_targetTree, targetPlaces, m_targetSoles);
            if (m_sourceTree.size() > kMaxTree || m_targetTree.size() > kMaxTree) { // not a body's legs
                m_matchFeet = false;
                m_sourceSoles.clear();
                m_targetSoles.clear();
                m_sourceTree.resize(m_sourcePlacementJoints);
                m_targetTree.resize(m_targetPoints.empty() ? 0 : *std::max_element(m_targetPoints.begin(), m_targetPoints.end()) + 1);
            }
        }
    }

    // Other translating joints: mapped ones follow their source relative to its rest offset.
    for (std::size_t j = 0; j < count; ++j) {
        const int toElement = to.translationElement(int(j));
        if (toElement < 0 || toElement == placedElement)
            continue;
        const Vec3d toRest = to.joint(int(j)).offset;
        const int fromElement = source[j] >= 0 ? from.translationElement(source[j]) : -1;
        if (fromElement >= 0)
            m_translations.push_back({fromLayout.floatOffset(fromElement), toLayout.floatOffset(toElement),
                                      toFloat(toRest - from.joint(source[j]).offset * m_scale)});
        else
            m_restTranslations.emplace_back(toLayout.floatOffset(toElement), toFloat(toRest));
    }
}

void FrameRetarget::apply(std::span<const float> fromFrame, std::span<float> toFrame) const
{
    apply(fromFrame, toFrame, m_sourcePlanted);
}

void FrameRetarget::apply(std::span<const float> fromFrame, std::span<float> toFrame, float sourcePlantedFeet) const
{
    const auto sourceRotation = [&](std::size_t offset) {
        return Quat{fromFrame[offset], fromFrame[offset + 1], fromFrame[offset + 2], fromFrame[offset + 3]};
    };
    for (const RotationMap& map : m_rotations) {
        const std::uint32_t factors = (map.upEnd - map.upBegin) + (map.downEnd - map.downBegin);
        Quat q;
        bool started = false;
        const auto multiply = [&](const Quat& factor) {
            q = started ? q * factor : factor;
            started = true;
        };
        if (map.hasBefore)
            multiply(map.before);
        for (std::uint32_t k = map.upEnd; k-- > map.upBegin;)
            multiply(conjugate(sourceRotation(m_path[k])));
        for (std::uint32_t k = map.downBegin; k < map.downEnd; ++k)
            multiply(sourceRotation(m_path[k]));
        if (map.hasAfter)
            multiply(map.after);
        if (factors + map.hasBefore + map.hasAfter > 1)
            q = normalize(q);
        float* out = &toFrame[map.to];
        out[0] = q.x;
        out[1] = q.y;
        out[2] = q.z;
        out[3] = q.w;
    }
    for (std::size_t offset : m_restRotations) {
        toFrame[offset] = toFrame[offset + 1] = toFrame[offset + 2] = 0.0f;
        toFrame[offset + 3] = 1.0f;
    }

    // Other translations first: the placed joint's chains below read them.
    for (const TranslationCopy& copy : m_translations) {
        const float* source = &fromFrame[copy.from];
        toFrame[copy.to] = source[0] * m_scaleF + copy.add.x;
        toFrame[copy.to + 1] = source[1] * m_scaleF + copy.add.y;
        toFrame[copy.to + 2] = source[2] * m_scaleF + copy.add.z;
    }
    for (const auto& [offset, rest] : m_restTranslations) {
        toFrame[offset] = rest.x;
        toFrame[offset + 1] = rest.y;
        toFrame[offset + 2] = rest.z;
    }
    if (!m_sourcePoints.empty()) {
        // The placed joint's translation puts the target's points (hips) where the source's are,
        // scaled: forward kinematics down to those points (and the feet) only.
        // The trees' poses, written before they are read: room left uninitialized (Vec3 and Quat
        // have default values, which would be filled in every frame).
        Room<Vec3, kMaxTree> fromPositionRoom, toPositionRoom;
        Room<Quat, kMaxTree> fromOrientationRoom, toOrientationRoom;
        Vec3* fromPositions = fromPositionRoom.get();
        Vec3* toPositions = toPositionRoom.get();
        Quat* fromOrientations = fromOrientationRoom.get();
        Quat* toOrientations = toOrientationRoom.get();
        // Standing (an infinite planted height): the source's feet need not be measured.
        const bool sourceFeet = m_matchFeet && !std::isinf(sourcePlantedFeet);
        treePoses(m_sourceTree, sourceFeet ? m_sourceTree.size() : m_sourcePlacementJoints, fromFrame, true,
                  fromPositions, fromOrientations);
        treePoses(m_targetTree, m_targetTree.size(), toFrame, false, toPositions, toOrientations);
        Vec3 fromMean, toMean;
        const float share = 1.0f / float(m_sourcePoints.size());
        for (std::size_t p = 0; p < m_sourcePoints.size(); ++p) {
            fromMean = fromMean + fromPositions[m_sourcePoints[p]] * share;
            toMean = toMean + toPositions[m_targetPoints[p]] * share;
        }
        float* out = &toFrame[m_placedTranslation];
        out[0] = fromMean.x * m_scaleF + m_placeAdd.x - toMean.x;
        out[1] = fromMean.y * m_scaleF + m_placeAdd.y - toMean.y;
        out[2] = fromMean.z * m_scaleF + m_placeAdd.z - toMean.z;
        if (m_matchFeet) {
            // The soles as high over the floor as the source's, scaled (few points: no allocation).
            const auto soleHeights = [](const std::vector<Sole>& soles, const Vec3* positions, const Quat* orientations,
                                        float* heights) {
                for (std::size_t k = 0; k < soles.size(); ++k)
                    heights[k] = (positions[soles[k].joint] + rotate(orientations[soles[k].joint], soles[k].offset)).y;
            };
            float fromHeights[kMaxSoles], toHeights[kMaxSoles];
            float lift = 0;
            if (sourceFeet) {
                soleHeights(m_sourceSoles, fromPositions, fromOrientations, fromHeights);
                lift = std::max(0.0f, footHeight<float>(std::span(fromHeights, m_sourceSoles.size()), m_sourceSoftness) -
                                          sourcePlantedFeet);
            }
            soleHeights(m_targetSoles, toPositions, toOrientations, toHeights);
            const float toFeet = footHeight<float>(std::span(toHeights, m_targetSoles.size()), m_targetSoftness);
            // Never below the floor: where the performer's feet sink into it (a capture's floor is
            // rarely level), the body is lifted instead.
            const float wanted = m_targetFeetRest + lift * m_scaleF;
            out[1] = wanted - toFeet - m_placedBaseY;
        }
    }
}

} // namespace thespis::core::anim
