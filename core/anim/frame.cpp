#include "anim/frame.h"

#include <cassert>

namespace thespis::core::anim {

std::shared_ptr<const FrameLayout> FrameLayout::create(std::vector<std::string> rotations,
                                                      std::vector<std::string> translations,
                                                      std::vector<std::string> scalars)
{
    auto layout = std::make_shared<FrameLayout>();
    layout->m_rotations = std::move(rotations);
    layout->m_translations = std::move(translations);
    layout->m_scalars = std::move(scalars);
    layout->m_floatCount = 4 * layout->m_rotations.size() + 3 * layout->m_translations.size()
                           + layout->m_scalars.size();
    return layout;
}

std::shared_ptr<const FrameLayout> FrameLayout::mpeg4Face()
{
    static const auto face = [] {
        std::vector<std::string> names;
        for (int i = 1; i <= 68; ++i)
            names.push_back("fap" + std::to_string(i));
        for (int i = 1; i <= 14; ++i)
            names.push_back("viseme" + std::to_string(i));
        for (int i = 1; i <= 6; ++i)
            names.push_back("expression" + std::to_string(i));
        auto layout = std::const_pointer_cast<FrameLayout>(create({}, {}, std::move(names)));
        // MPEG-4's FAP groups 2 … 10 (FAP 1 selects a viseme, FAP 2 an expression).
        const std::pair<int, const char*> regions[] = {
            {1, "mouth"},  {2, "expressions"}, {18, "mouth"}, {30, "eyes"},  {38, "brows"},
            {42, "cheeks"}, {47, "tongue"},     {50, "head"},  {60, "mouth"}, {64, "nose"}, {68, "ears"}};
        for (int fap = 1; fap <= 68; ++fap)
            for (const auto& [last, region] : regions)
                if (fap <= last) {
                    layout->m_scalarGroups.emplace_back(region);
                    break;
                }
        layout->m_scalarGroups.insert(layout->m_scalarGroups.end(), 14, "mouth");
        layout->m_scalarGroups.insert(layout->m_scalarGroups.end(), 6, "expressions");
        return std::shared_ptr<const FrameLayout>(std::move(layout));
    }();
    return face;
}

ElementKind FrameLayout::kind(int element) const
{
    assert(element >= 0 && element < elementCount());
    if (element < rotationCount())
        return ElementKind::Rotation;
    if (element < rotationCount() + translationCount())
        return ElementKind::Translation;
    return ElementKind::Scalar;
}

const std::string& FrameLayout::name(int element) const
{
    assert(element >= 0 && element < elementCount());
    if (element < rotationCount())
        return m_rotations[std::size_t(element)];
    element -= rotationCount();
    if (element < translationCount())
        return m_translations[std::size_t(element)];
    return m_scalars[std::size_t(element - translationCount())];
}

std::size_t FrameLayout::floatOffset(int element) const
{
    assert(element >= 0 && element < elementCount());
    if (element < rotationCount())
        return 4 * std::size_t(element);
    element -= rotationCount();
    if (element < translationCount())
        return translationOffset() + 3 * std::size_t(element);
    return scalarOffset() + std::size_t(element - translationCount());
}

int FrameLayout::find(std::string_view name, ElementKind kind) const
{
    const auto& names = kind == ElementKind::Rotation      ? m_rotations
                        : kind == ElementKind::Translation ? m_translations
                                                           : m_scalars;
    const int base = kind == ElementKind::Rotation      ? 0
                     : kind == ElementKind::Translation ? rotationCount()
                                                        : rotationCount() + translationCount();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return base + int(i);
    return -1;
}

const std::string& FrameLayout::group(int element) const
{
    static const std::string none;
    const int scalar = element - rotationCount() - translationCount();
    return scalar >= 0 && std::size_t(scalar) < m_scalarGroups.size() ? m_scalarGroups[std::size_t(scalar)] : none;
}

bool FrameLayout::operator==(const FrameLayout& other) const
{
    return m_rotations == other.m_rotations && m_translations == other.m_translations
           && m_scalars == other.m_scalars;
}

std::vector<float> neutralFrame(const FrameLayout& layout)
{
    std::vector<float> frame(layout.floatCount(), 0.0f);
    for (int r = 0; r < layout.rotationCount(); ++r)
        frame[4 * std::size_t(r) + 3] = 1.0f;
    return frame;
}

} // namespace thespis::core::anim
