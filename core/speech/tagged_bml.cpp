#include "speech/tagged_bml.h"

#include <algorithm>

namespace thespis::core::speech {
namespace {

// An id for the speech that no tag has taken.
std::string speechId(const TaggedText& text)
{
    std::string id = "speech";
    for (int n = 2; std::any_of(text.gestures.begin(), text.gestures.end(),
                                [&](const TaggedGesture& g) { return g.id == id; });
         ++n)
        id = "speech" + std::to_string(n);
    return id;
}

} // namespace

TaggedBml taggedBml(const TaggedText& text, const SpeechTiming& timing)
{
    TaggedBml out;
    out.block.id = "tags";
    BmlBehavior said;
    said.kind = BmlBehaviorKind::Speech;
    said.id = speechId(text);
    said.text = text.text;
    out.speech[said.id] = timing;
    std::vector<BmlBehavior> gestures;
    for (const TaggedGesture& g : text.gestures) {
        // Marks in the text: right after a word for its end, at a word's first letter for its start.
        std::size_t from = 0, to = text.text.size(), stroke = std::string::npos;
        const WordTiming *first = nullptr, *last = nullptr;
        for (const WordTiming& w : timing.words) {
            if (w.textBegin < g.end && w.textEnd > g.begin) {
                first = first ? first : &w;
                last = &w;
                if (w.stressed && stroke == std::string::npos)
                    stroke = w.textBegin;
            } else if (w.textEnd <= g.begin) {
                from = w.textEnd;
            } else if (w.textBegin >= g.end && to == text.text.size()) {
                to = w.textBegin;
            }
        }
        if (first) {
            from = first->textBegin;
            to = last->textEnd;
        }
        if (stroke == std::string::npos)
            stroke = from;
        BmlBehavior gesture;
        gesture.kind = BmlBehaviorKind::Gesture;
        gesture.id = g.id;
        gesture.lexeme = g.animation;
        gesture.byName = true;
        gesture.line = g.line;
        gesture.column = g.column;
        const auto mark = [&](BmlPoint point, const char* what, std::size_t offset) {
            const std::string id = g.id + "." + what;
            said.syncMarks.emplace_back(id, offset);
            gesture.sync[point] = {said.id, id, 0};
        };
        mark(BmlPoint::Ready, "from", from);
        mark(BmlPoint::Stroke, "stroke", stroke);
        mark(BmlPoint::Relax, "to", std::max(from, to));
        gestures.push_back(std::move(gesture));
    }
    std::stable_sort(said.syncMarks.begin(), said.syncMarks.end(),
                     [](const auto& a, const auto& b) { return a.second < b.second; });
    out.block.behaviors.push_back(std::move(said));
    for (BmlBehavior& g : gestures)
        out.block.behaviors.push_back(std::move(g));
    return out;
}

} // namespace thespis::core::speech
