#include "edit/scenario_edit.h"

#include <algorithm>
#include <cstddef>
#include <string>

namespace thespis::core::edit {

namespace {

using namespace scenario;

std::string where(const ActionPath& p)
{
    return "character " + std::to_string(p.character) + ", layer " + std::to_string(p.layer) + ", action "
           + std::to_string(p.action);
}
std::string where(const LayerPath& p)
{
    return "character " + std::to_string(p.character) + ", layer " + std::to_string(p.layer);
}
std::string where(const CharacterItemPath& p)
{
    return "character " + std::to_string(p.character) + ", item " + std::to_string(p.index);
}
std::string where(int index) { return "item " + std::to_string(index); }

bool inRange(int index, std::size_t size) { return index >= 0 && std::size_t(index) < size; }

Character* characterAt(Scenario& s, int index)
{
    return inRange(index, s.characters.size()) ? &s.characters[std::size_t(index)] : nullptr;
}

// The list a change's index points into, and the index in it; null when the path leads nowhere.
std::pair<std::vector<ActionSpec>*, int> listOf(Scenario& s, const ActionPath& p)
{
    Character* c = characterAt(s, p.character);
    if (!c || !inRange(p.layer, c->layers.size()))
        return {nullptr, 0};
    return {&c->layers[std::size_t(p.layer)].actions, p.action};
}
std::pair<std::vector<Layer>*, int> listOf(Scenario& s, const LayerPath& p)
{
    Character* c = characterAt(s, p.character);
    return {c ? &c->layers : nullptr, p.layer};
}
std::pair<std::vector<NamedMask>*, int> listOf(Scenario& s, const MaskChange&) { return {&s.masks, 0}; }
std::pair<std::vector<Character>*, int> listOf(Scenario& s, const CharacterChange&) { return {&s.characters, 0}; }
std::pair<std::vector<Marker>*, int> listOf(Scenario& s, const MarkerChange&) { return {&s.markers, 0}; }

template <class T>
std::pair<std::vector<T>*, int> itemListOf(Scenario& s, const CharacterItemPath& p, std::vector<T> Character::*member)
{
    Character* c = characterAt(s, p.character);
    return {c ? &(c->*member) : nullptr, p.index};
}

template <class T>
Result<void> applyTo(std::vector<T>* list, int index, const std::optional<T>& before, const std::optional<T>& after,
                     const std::string& at)
{
    const auto refuse = [&](const std::string& why) {
        return makeError(ErrorCode::InvalidArgument, "The edit does not fit the document (" + at + "): " + why + ".");
    };
    if (!list)
        return refuse("no such character or layer");
    if (!before && !after)
        return refuse("a change must insert, remove or replace something");
    if (!before) {
        if (index < 0 || std::size_t(index) > list->size())
            return refuse("insert position out of range");
        list->insert(list->begin() + index, *after);
        return {};
    }
    if (!inRange(index, list->size()))
        return refuse("index out of range");
    T& current = (*list)[std::size_t(index)];
    if (!(current == *before))
        return refuse("the element is not what the edit expects");
    if (after)
        current = *after;
    else
        list->erase(list->begin() + index);
    return {};
}

Result<void> applyChange(Scenario& s, const Change& change)
{
    return std::visit(
        [&](const auto& c) -> Result<void> {
            using C = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<C, ActionChange> || std::is_same_v<C, LayerChange>) {
                auto [list, index] = listOf(s, c.at);
                return applyTo(list, index, c.before, c.after, where(c.at));
            } else if constexpr (std::is_same_v<C, MaskChange> || std::is_same_v<C, MarkerChange>
                                 || std::is_same_v<C, CharacterChange>) {
                auto [list, unused] = listOf(s, c);
                return applyTo(list, c.at, c.before, c.after, where(c.at));
            } else if constexpr (std::is_same_v<C, GestureChange>) {
                auto [list, index] = itemListOf(s, c.at, &Character::gestures);
                return applyTo(list, index, c.before, c.after, "gestures, " + where(c.at));
            } else if constexpr (std::is_same_v<C, ClipChange>) {
                auto [list, index] = itemListOf(s, c.at, &Character::clips);
                return applyTo(list, index, c.before, c.after, "clips, " + where(c.at));
            } else if constexpr (std::is_same_v<C, LightingChange>) {
                if (s.lighting != c.before)
                    return makeError(ErrorCode::InvalidArgument, "The edit does not fit the document (the light).");
                s.lighting = c.after;
                return {};
            } else if constexpr (std::is_same_v<C, ScriptsChange>) {
                if (s.scripts != c.before)
                    return makeError(ErrorCode::InvalidArgument, "The edit does not fit the document (the scripts).");
                s.scripts = c.after;
                return {};
            } else if constexpr (std::is_same_v<C, ArChange>) {
                if (s.ar != c.before)
                    return makeError(ErrorCode::InvalidArgument, "The edit does not fit the document (the AR section).");
                s.ar = c.after;
                return {};
            } else if constexpr (std::is_same_v<C, CharacterBakeChange>) {
                Character* character = characterAt(s, c.character);
                if (!character || character->bake != c.before)
                    return makeError(ErrorCode::InvalidArgument,
                                     "The edit does not fit the document (bake of character "
                                         + std::to_string(c.character) + ").");
                character->bake = c.after;
                return {};
            } else if constexpr (std::is_same_v<C, BmlLexiconChange>) {
                Character* character = characterAt(s, c.character);
                if (!character || character->bmlLexicon != c.before)
                    return makeError(ErrorCode::InvalidArgument,
                                     "The edit does not fit the document (BML lexicon of character "
                                         + std::to_string(c.character) + ").");
                character->bmlLexicon = c.after;
                return {};
            } else {
                static_assert(std::is_same_v<C, SegmentTagsChange>);
                Character* character = characterAt(s, c.character);
                if (!character || character->segmentTags != c.before)
                    return makeError(ErrorCode::InvalidArgument,
                                     "The edit does not fit the document (segment tags of character "
                                         + std::to_string(c.character) + ").");
                character->segmentTags = c.after;
                return {};
            }
        },
        change);
}

Change inverted(const Change& change)
{
    return std::visit(
        [](auto c) -> Change {
            std::swap(c.before, c.after);
            return c;
        },
        change);
}

// Where a change acts, and whether it replaces in place: two such changes at the same place of
// the same kind can merge.
bool samePlaceReplace(const Change& a, const Change& b)
{
    if (a.index() != b.index())
        return false;
    return std::visit(
        [&](const auto& first) {
            using C = std::decay_t<decltype(first)>;
            const auto& second = std::get<C>(b);
            if constexpr (std::is_same_v<C, SegmentTagsChange>)
                return first.character == second.character;
            else if constexpr (std::is_same_v<C, LightingChange> || std::is_same_v<C, ArChange>)
                return true;
            else if constexpr (std::is_same_v<C, ScriptsChange>)
                return false; // each save of a script is a step of its own
            else if constexpr (std::is_same_v<C, CharacterBakeChange> || std::is_same_v<C, BmlLexiconChange>)
                return false; // a bake, a change of the lexicon: one step of its own, whatever follows it
            else
                return first.at == second.at && first.before && first.after && second.before && second.after;
        },
        a);
}

} // namespace

void Edit::append(Edit other)
{
    for (Change& change : other.m_changes)
        m_changes.push_back(std::move(change));
}

Edit Edit::inverse() const
{
    Edit result;
    for (auto it = m_changes.rbegin(); it != m_changes.rend(); ++it)
        result.m_changes.push_back(inverted(*it));
    return result;
}

Result<void> Edit::apply(scenario::Scenario& scenario) const
{
    for (std::size_t i = 0; i < m_changes.size(); ++i) {
        if (auto ok = applyChange(scenario, m_changes[i]); !ok) {
            // Take back what was applied, newest first: each of those fitted, so its inverse fits.
            for (std::size_t k = i; k-- > 0;)
                (void)applyChange(scenario, inverted(m_changes[k]));
            return ok;
        }
    }
    return {};
}

bool Edit::replacesLike(const Edit& later) const
{
    if (m_changes.size() != later.m_changes.size() || m_changes.empty())
        return false;
    for (std::size_t i = 0; i < m_changes.size(); ++i)
        if (!samePlaceReplace(m_changes[i], later.m_changes[i]))
            return false;
    return true;
}

bool Edit::takenBackBy(const Edit& later) const
{
    if (m_changes.empty() || later.m_changes.size() < m_changes.size())
        return false;
    for (std::size_t i = 0; i < m_changes.size(); ++i) {
        const Change& mine = m_changes[m_changes.size() - 1 - i];
        if (std::holds_alternative<CharacterBakeChange>(mine) || !(later.m_changes[i] == inverted(mine)))
            return false;
    }
    return true;
}

bool Edit::canMergeWith(const Edit& later) const
{
    return replacesLike(later) || takenBackBy(later);
}

void Edit::mergeWith(const Edit& later)
{
    if (replacesLike(later)) {
        for (std::size_t i = 0; i < m_changes.size(); ++i)
            std::visit(
                [&](auto& mine) {
                    using C = std::decay_t<decltype(mine)>;
                    mine.after = std::get<C>(later.m_changes[i]).after;
                },
                m_changes[i]);
        return;
    }
    // A re-based step: this edit, then its own inverse, then the rest; the first two cancel.
    m_changes.assign(later.m_changes.begin() + std::ptrdiff_t(m_changes.size()), later.m_changes.end());
}

Edit Edit::stepTo(const Edit& wanted) const
{
    bool sameBefore = replacesLike(wanted);
    for (std::size_t i = 0; sameBefore && i < m_changes.size(); ++i)
        sameBefore = std::visit(
            [&](const auto& mine) {
                using C = std::decay_t<decltype(mine)>;
                return mine.before == std::get<C>(wanted.m_changes[i]).before;
            },
            m_changes[i]);
    if (sameBefore) {
        Edit step = *this;
        for (std::size_t i = 0; i < m_changes.size(); ++i)
            std::visit(
                [&](auto& change) {
                    using C = std::decay_t<decltype(change)>;
                    change.before = change.after;
                    change.after = std::get<C>(wanted.m_changes[i]).after;
                },
                step.m_changes[i]);
        return step;
    }
    Edit step = inverse();
    step.append(wanted);
    return step;
}

bool Edit::changesNothing() const
{
    for (const Change& change : m_changes) {
        const bool same = std::visit([](const auto& c) { return c.before == c.after; }, change);
        if (!same)
            return false;
    }
    return true;
}

RuntimeScope Edit::runtimeScope() const
{
    RuntimeScope scope;
    for (const Change& change : m_changes) {
        std::optional<int> character;
        if (const auto* action = std::get_if<ActionChange>(&change))
            character = action->at.character;
        else if (const auto* layer = std::get_if<LayerChange>(&change))
            character = layer->at.character;
        else if (const auto* gesture = std::get_if<GestureChange>(&change))
            character = gesture->at.character;
        else if (const auto* clip = std::get_if<ClipChange>(&change))
            character = clip->at.character;
        else if (const auto* lexicon = std::get_if<BmlLexiconChange>(&change))
            character = lexicon->character; // its runtime's table, and the warnings about it
        else if (const auto* whole = std::get_if<CharacterChange>(&change)) {
            if (!whole->before || !whole->after || whole->before->name != whole->after->name) {
                scope.everything = true;
                break;
            }
            character = whole->at;
        } else if (std::holds_alternative<MaskChange>(change)) {
            scope.everything = true;
            break;
        }
        if (character)
            scope.characters.push_back(*character);
    }
    if (scope.everything) {
        scope.characters.clear();
        return scope;
    }
    std::sort(scope.characters.begin(), scope.characters.end());
    scope.characters.erase(std::unique(scope.characters.begin(), scope.characters.end()), scope.characters.end());
    return scope;
}

void Edit::rebasePaths(const std::filesystem::path& from, const std::filesystem::path& to, const scenario::KeptNames& keep)
{
    const auto rebaseClip = [&](std::optional<scenario::ClipAsset>& clip) {
        if (clip)
            scenario::rebaseClip(*clip, from, to, keep);
    };
    const auto rebaseCharacter = [&](std::optional<scenario::Character>& character) {
        if (!character)
            return;
        scenario::Scenario holder;
        holder.characters.push_back(std::move(*character));
        scenario::rebasePaths(holder, from, to, keep);
        character = std::move(holder.characters.front());
    };
    for (Change& change : m_changes) {
        if (auto* clip = std::get_if<ClipChange>(&change)) {
            rebaseClip(clip->before);
            rebaseClip(clip->after);
        } else if (auto* character = std::get_if<CharacterChange>(&change)) {
            rebaseCharacter(character->before);
            rebaseCharacter(character->after);
        } else if (auto* light = std::get_if<LightingChange>(&change)) {
            light->before.probe = scenario::rebasedPath(light->before.probe, from, to, keep);
            light->after.probe = scenario::rebasedPath(light->after.probe, from, to, keep);
        } else if (auto* bake = std::get_if<CharacterBakeChange>(&change)) {
            bake->before = scenario::rebasedPath(bake->before, from, to, keep);
            bake->after = scenario::rebasedPath(bake->after, from, to, keep);
        } else if (auto* ar = std::get_if<ArChange>(&change)) {
            for (scenario::ArSpec* spec : {&ar->before, &ar->after})
                for (scenario::PhantomOccluder& occluder : spec->occluders)
                    occluder.model = scenario::rebasedPath(occluder.model, from, to, keep);
        }
    }
}

} // namespace thespis::core::edit
