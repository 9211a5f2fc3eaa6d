#pragma once
// AbstractFrame (paper §4.2): a frame is a list of AbstractFrameElements, each a small float
// vector of one kind. FrameLayout names the elements; the values of one frame live in one flat
// float array grouped by kind: every rotation quaternion (4 floats, x y z w), then every
// translation (3 floats), then every scalar (1 float, e.g. an MPEG-4 FAP). Blending loops
// therefore run over contiguous memory of a single kind.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "anim/quat.h"

namespace thespis::core::anim {

enum class ElementKind : unsigned char { Rotation, Translation, Scalar };

/// Floats per element of a kind: 4, 3 or 1.
constexpr int floatsPerElement(ElementKind kind)
{
    return kind == ElementKind::Rotation ? 4 : kind == ElementKind::Translation ? 3 : 1;
}

/// Names and kinds of a frame's elements; immutable and shared by every frame, clip and schedule
/// built on it. A body layout names a rotation per joint and a translation for the root joint
/// (same name, other kind); a face layout names 68 FAP scalars and the high-level FAPs' weights.
class FrameLayout {
public:
    static std::shared_ptr<const FrameLayout> create(std::vector<std::string> rotations,
                                                     std::vector<std::string> translations = {},
                                                     std::vector<std::string> scalars = {});
    /// The 68 MPEG-4 facial animation parameters as scalars named fap1 … fap68, then the weights
    /// of the 14 visemes (viseme1 … viseme14) and the 6 expressions (expression1 … expression6)
    /// that FAPs 1 and 2 select (scene/fap.h). Each scalar is in its face region (MPEG-4's FAP
    /// groups): "mouth" (jaw, chin, lips and the visemes), "eyes", "brows", "cheeks", "tongue",
    /// "head", "nose", "ears", and "expressions" (the expression weights).
    static std::shared_ptr<const FrameLayout> mpeg4Face();

    int rotationCount() const { return int(m_rotations.size()); }
    int translationCount() const { return int(m_translations.size()); }
    int scalarCount() const { return int(m_scalars.size()); }
    int elementCount() const { return rotationCount() + translationCount() + scalarCount(); }
    std::size_t floatCount() const { return m_floatCount; }

    /// Offsets (in floats) of each kind's block in a frame.
    std::size_t translationOffset() const { return 4 * m_rotations.size(); }
    std::size_t scalarOffset() const { return translationOffset() + 3 * m_translations.size(); }

    /// Element index: rotations are 0…R-1, translations R…R+T-1, scalars after.
    ElementKind kind(int element) const;
    const std::string& name(int element) const;
    std::size_t floatOffset(int element) const;

    const std::vector<std::string>& rotationNames() const { return m_rotations; }
    const std::vector<std::string>& translationNames() const { return m_translations; }
    const std::vector<std::string>& scalarNames() const { return m_scalars; }

    /// The group a scalar element belongs to ("" for none): the face layout's FAP regions
    /// ("mouth", "eyes", "brows" …), which a mask weighs when it does not name the element.
    const std::string& group(int element) const;

    /// Element index of `name` among elements of `kind`, or -1.
    int find(std::string_view name, ElementKind kind) const;

    bool operator==(const FrameLayout& other) const;

private:
    std::vector<std::string> m_rotations, m_translations, m_scalars;
    std::vector<std::string> m_scalarGroups; ///< empty, or one per scalar
    std::size_t m_floatCount = 0;
};

using FrameLayoutPtr = std::shared_ptr<const FrameLayout>;

/// Identity rotations, zero translations and scalars: the neutral frame of a layout.
std::vector<float> neutralFrame(const FrameLayout& layout);

/// Views one frame's rotation / translation block.
inline Quat& rotationAt(std::span<float> frame, int rotation)
{
    return *reinterpret_cast<Quat*>(frame.data() + 4 * std::size_t(rotation));
}
inline const Quat& rotationAt(std::span<const float> frame, int rotation)
{
    return *reinterpret_cast<const Quat*>(frame.data() + 4 * std::size_t(rotation));
}

} // namespace thespis::core::anim
