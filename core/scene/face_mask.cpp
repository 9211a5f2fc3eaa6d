#include "scene/face_mask.h"

#include <algorithm>
#include <map>

#include "scene/default_humanoid.h"
#include "scene/fap.h"

namespace thespis::core::scene {

namespace {

// The feature point a FAP without one of its own is shown at.
std::string_view shownAt(int fap)
{
    switch (fap) {
    case 1: return "2.1";
    case 2: return "4.1";
    case 23: case 25: case 27: return "3.5";
    case 24: case 26: case 28: return "3.6";
    default: return fapInfo(fap).featurePoint;
    }
}

std::string swapSides(std::string name)
{
    const std::pair<std::string_view, std::string_view> swaps[] = {{"_l_", "_r_"}, {"_lm", "_rm"}};
    for (const auto& [a, b] : swaps) {
        if (const auto at = name.find(a); at != std::string::npos)
            return name.replace(at, a.size(), b);
        if (const auto at = name.find(b); at != std::string::npos)
            return name.replace(at, b.size(), a);
    }
    return name;
}

std::vector<FaceMaskElement> layOut()
{
    auto humanoid = makeDefaultHumanoid({.detail = 0.5});
    std::map<std::string, anim::Vec3, std::less<>> points;
    if (humanoid)
        for (const FeaturePoint& point : humanoid->face.featurePoints)
            points[point.name] = humanoid->mesh.positions[point.vertex];
    const auto at = [&](std::string_view name) {
        const auto it = points.find(name);
        return it == points.end() ? anim::Vec3{0, 1.65f, 0.1f} : it->second;
    };
    const anim::FrameLayout& layout = *anim::FrameLayout::mpeg4Face();
    const float chinY = at("2.1").y, sideX = at("10.1").x + 0.04f;

    std::vector<FaceMaskElement> elements;
    for (std::string_view region : kFaceRegions) {
        const int parent = int(elements.size());
        elements.push_back({std::string(region), std::string(region), -1, {}});
        int visemes = 0, expressions = 0;
        for (int e = 0; e < layout.elementCount(); ++e) {
            if (layout.group(e) != region)
                continue;
            const int channel = e - layout.rotationCount() - layout.translationCount();
            FaceMaskElement element{layout.name(e), {}, parent, {}};
            if (channel < kFapCount) {
                element.label = std::string(fapInfo(channel + 1).name);
                element.position = at(shownAt(channel + 1));
                if (channel + 1 >= 48 && channel + 1 <= 50) // the head turns: above the brows
                    element.position = at("4.1") + anim::Vec3{(channel - 48) * 0.02f, 0.05f, 0};
            } else if (channel < kFapCount + kVisemeCount) {
                element.label = "viseme " + std::string(visemeName(channel - kFapCount + 1));
                element.position = {(float(visemes++) - 6.5f) * 0.011f, chinY - 0.04f, 0};
            } else {
                element.label = std::string(expressionName(channel - kFapCount - kVisemeCount + 1));
                element.position = {sideX, at("4.1").y - float(expressions++) * 0.018f, 0};
            }
            elements.push_back(std::move(element));
        }
        // A region's dot at the middle of its channels.
        anim::Vec3 sum{};
        int count = 0;
        for (std::size_t i = std::size_t(parent) + 1; i < elements.size(); ++i, ++count)
            sum = sum + elements[i].position;
        if (count > 0)
            elements[std::size_t(parent)].position = sum * (1.0f / float(count));
    }
    return elements;
}

} // namespace

anim::JointMask faceMaskPreset(FaceMaskPreset preset)
{
    switch (preset) {
    case FaceMaskPreset::WholeFace:
        return anim::JointMask({}, 1.0f);
    case FaceMaskPreset::Speech:
        return anim::JointMask({{"mouth", 1.0f}, {"tongue", 1.0f}, {"cheeks", 0.5f}}, 0.0f);
    case FaceMaskPreset::Expression:
        return anim::JointMask({{"eyes", 1.0f}, {"brows", 1.0f}, {"cheeks", 1.0f}, {"nose", 1.0f},
                                {"expressions", 1.0f}, {"mouth", 1.0f / 3.0f}},
                               0.0f);
    case FaceMaskPreset::Eyes:
        return anim::JointMask({{"eyes", 1.0f}}, 0.0f);
    }
    return {};
}

bool isFaceMask(const anim::JointMask& mask)
{
    const anim::FrameLayout& layout = *anim::FrameLayout::mpeg4Face();
    return std::any_of(mask.weights().begin(), mask.weights().end(), [&](const auto& entry) {
        return std::find(kFaceRegions.begin(), kFaceRegions.end(), entry.first) != kFaceRegions.end()
               || layout.find(entry.first, anim::ElementKind::Scalar) >= 0;
    });
}

int mirroredFap(int fap)
{
    const std::optional<int> other = findFap(swapSides(std::string(fapInfo(fap).name)));
    return other ? *other : fap;
}

anim::JointMask mirroredFaceMask(const anim::JointMask& mask)
{
    std::map<std::string, float> weights;
    for (const auto& [name, weight] : mask.weights()) {
        const std::optional<int> fap = name.starts_with("fap") ? findFap(name) : std::nullopt;
        weights[fap ? "fap" + std::to_string(mirroredFap(*fap)) : name] = weight;
    }
    return anim::JointMask(std::move(weights), mask.defaultWeight());
}

const std::vector<FaceMaskElement>& faceMaskElements()
{
    static const std::vector<FaceMaskElement> elements = layOut();
    return elements;
}

} // namespace thespis::core::scene
