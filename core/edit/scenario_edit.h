#pragma once
// Edit: a reversible change to a scenario document (STYLE.md §5), the one way editors and
// scripts change a Scenario. An edit is a list of changes, each inserting, removing or replacing
// one element of one of the scenario's lists (a character, an action of a layer, a layer, a mask,
// a marker, a gesture, a clip) or replacing a character's segment tags, bake file or BML lexicon,
// the light, the scripts or the AR section. Each change keeps the value before
// and after, so an edit is undone by applying its inverse, and a drag's many small edits of the
// same elements merge into one.
//
// Rules of apply(): changes run in order; an index must be in range (one past the end for an
// insert); a change whose `before` does not equal what the document holds is refused (the edit
// was made for another state of the document); on any failure the changes already applied are
// undone, so the scenario is left exactly as it was.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::edit {

struct LayerPath {
    int character = 0;
    int layer = 0;
    auto operator<=>(const LayerPath&) const = default;
};

struct ActionPath {
    int character = 0;
    int layer = 0;
    int action = 0;
    LayerPath layerPath() const { return {character, layer}; }
    auto operator<=>(const ActionPath&) const = default;
};

/// An element of a character's list (gestures, clips).
struct CharacterItemPath {
    int character = 0;
    int index = 0;
    auto operator<=>(const CharacterItemPath&) const = default;
};

/// Inserts (`before` empty), removes (`after` empty) or replaces the element at `at`.
template <class T, class Where>
struct ListChange {
    Where at{};
    std::optional<T> before;
    std::optional<T> after;
    bool operator==(const ListChange&) const = default;
};

using ActionChange = ListChange<scenario::ActionSpec, ActionPath>;
using LayerChange = ListChange<scenario::Layer, LayerPath>;
using MaskChange = ListChange<scenario::NamedMask, int>;
using MarkerChange = ListChange<scenario::Marker, int>;
using GestureChange = ListChange<scenario::Gesture, CharacterItemPath>;
using ClipChange = ListChange<scenario::ClipAsset, CharacterItemPath>;

struct SegmentTagsChange {
    int character = 0;
    std::vector<scene::SegmentTag> before, after;
    bool operator==(const SegmentTagsChange&) const = default;
};

/// Replaces a character's bake file (Character::bake; empty: none). Never merges: each bake is
/// its own undo step.
struct CharacterBakeChange {
    int character = 0;
    std::string before, after;
    bool operator==(const CharacterBakeChange&) const = default;
};

/// Replaces a character's BML lexicon (Character::bmlLexicon; nullopt: the defaults). Never
/// merges: each change of the table is its own undo step.
struct BmlLexiconChange {
    int character = 0;
    std::optional<std::map<std::string, std::string>> before, after;
    bool operator==(const BmlLexiconChange&) const = default;
};

/// Inserts, removes or replaces a whole character (format 3: its body, placement and the rest).
using CharacterChange = ListChange<scenario::Character, int>;

/// Replaces the scenario's light (probe, layout, rotation, intensity).
struct LightingChange {
    scenario::LightingSpec before, after;
    bool operator==(const LightingChange&) const = default;
};

/// Replaces the scenario's scripts (one added, changed or removed).
struct ScriptsChange {
    std::vector<scenario::ScriptSpec> before, after;
    bool operator==(const ScriptsChange&) const = default;
};

/// Replaces how the scenario plays over tracked video (its ArSpec: where the world sits on the
/// target, the phantom occluders, the shadow catcher). Merges like the light: a drag of the
/// placement is one step.
struct ArChange {
    scenario::ArSpec before, after;
    bool operator==(const ArChange&) const = default;
};

using Change = std::variant<ActionChange, LayerChange, MaskChange, MarkerChange, GestureChange, ClipChange,
                            SegmentTagsChange, CharacterBakeChange, CharacterChange, LightingChange, ScriptsChange,
                            ArChange, BmlLexiconChange>;

/// What an edit changes of a scenario's runtime (its schedules): nothing (the light, markers,
/// scripts, segment tags, bakes, the AR placement), some characters' (their actions, layers, clips, gestures, BML
/// lexicons, or the
/// character replaced under the same name), or everything (characters added, removed or renamed,
/// the masks every character may use).
struct RuntimeScope {
    bool everything = false;
    std::vector<int> characters; ///< sorted, without repeats; when not everything
    bool empty() const { return !everything && characters.empty(); }
};

class Edit {
public:
    Edit() = default;
    explicit Edit(Change change) { m_changes.push_back(std::move(change)); }

    void add(Change change) { m_changes.push_back(std::move(change)); }
    /// Appends every change of `other` (it runs after this edit's changes).
    void append(Edit other);
    const std::vector<Change>& changes() const { return m_changes; }
    bool empty() const { return m_changes.empty(); }

    /// The edit that takes the document back: changes in reverse order, before and after swapped.
    Edit inverse() const;
    /// See the rules at the top of this file.
    Result<void> apply(scenario::Scenario& scenario) const;

    /// True when `later` is a drag's next step after this edit: either it replaces the same elements
    /// in the same order (no inserts or removes), or it starts by taking this whole edit back (its
    /// first changes are inverse(): a step re-based on the drag's start, see stepTo()). Bake changes
    /// never merge.
    bool canMergeWith(const Edit& later) const;
    /// Makes this edit do what it did followed by `later`: for replaces, keeps this edit's `before`
    /// and takes later's `after`; for a step that starts by taking this edit back, becomes the rest
    /// of that step. Only after canMergeWith(later).
    void mergeWith(const Edit& later);
    /// The step from the document this edit leads to, to the document `wanted` leads to, when both
    /// were made for the same document (a drag re-made from its start at every mouse move): one
    /// replace per element when both replace the same elements in the same order, else this edit's
    /// inverse followed by `wanted`. Applied after this edit it gives what `wanted` gives, and
    /// mergeWith() of it turns this edit into `wanted`.
    Edit stepTo(const Edit& wanted) const;
    /// True when applying the edit changes nothing (every change replaces a value by an equal one).
    bool changesNothing() const;
    /// What the edit changes of the runtime, so that only that is rebuilt.
    RuntimeScope runtimeScope() const;
    /// Rewrites the file paths the edit carries (clips, bakes) as scenario::rebasePaths() does the
    /// document's, so that it still fits the document after a save to another folder.
    void rebasePaths(const std::filesystem::path& from, const std::filesystem::path& to, const scenario::KeptNames& keep = {});

    bool operator==(const Edit&) const = default;

private:
    bool replacesLike(const Edit& later) const; // same elements replaced in the same order
    bool takenBackBy(const Edit& later) const;  // later starts with inverse()

    std::vector<Change> m_changes;
};

} // namespace thespis::core::edit
