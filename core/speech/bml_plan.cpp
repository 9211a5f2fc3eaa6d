#include "speech/bml_plan.h"

#include <algorithm>

#include "speech/face_lexemes.h"
#include "util/text.h"

namespace thespis::core::speech {

namespace {

constexpr std::size_t kStart = std::size_t(BmlPoint::Start), kReady = std::size_t(BmlPoint::Ready),
                      kRelax = std::size_t(BmlPoint::Relax), kEnd = std::size_t(BmlPoint::End);
using Points = std::array<double, kBmlPointCount>;

// Ready … relax inside [start, end] as a curve's fades, in seconds.
anim::Curve fades(const Points& at)
{
    return anim::Curve::cubicFade(std::max(0.0, at[kReady] - at[kStart]), std::max(0.0, at[kEnd] - at[kRelax]));
}

// The points of a motion of `seconds` with `fadeIn`/`fadeOut`: its stroke at `stroke` seconds
// when that falls in the held part, else in the middle of it.
Points phases(double seconds, double fadeIn, double fadeOut, double stroke = -1)
{
    fadeIn = std::min(fadeIn, seconds / 2);
    fadeOut = std::min(fadeOut, seconds - fadeIn);
    const double ready = fadeIn, relax = seconds - fadeOut;
    if (!(stroke >= ready && stroke <= relax))
        stroke = (ready + relax) / 2;
    return {0, ready, stroke, stroke, stroke, relax, seconds};
}

// A gesture's times: not before its block (its fade-in then its own, over its first words), its
// clip fitted to them.
void placeGesture(BmlPlanned& p)
{
    Points& at = p.times.at;
    double fadeIn = at[kReady] - at[kStart];
    if (at[kStart] < 0) {
        for (double& t : at)
            t = std::max(t, 0.0);
        fadeIn = std::min(std::min(p.entry.fadeIn, p.entry.seconds / 2), at[kEnd]);
    }
    p.weight = anim::Curve::cubicFade(std::max(0.0, fadeIn), std::max(0.0, at[kEnd] - at[kRelax]));
    const double stroke = p.entry.shape.stroke >= 0 ? at[std::size_t(BmlPoint::Stroke)] : -1;
    p.fit = fitGesture({at[kStart], at[kEnd], stroke}, p.entry.seconds, p.entry.shape);
}

// Checks what `b` needs and fills what its playing takes, but its times.
Result<void> prepare(const BmlBehavior& b, const std::map<std::string, SpeechTiming>& speech,
                     const BmlGesticon& gesticon, const BmlLexicon& lexicon, const motion::GazeSettings& gazeDefaults,
                     BmlPlanned& planned)
{
    switch (b.kind) {
    case BmlBehaviorKind::Speech:
        if (!speech.contains(b.id))
            return bmlBehaviorError(ErrorCode::InvalidArgument, b, "it has not been spoken (no timing).");
        return {};
    case BmlBehaviorKind::Gesture:
    case BmlBehaviorKind::Pointing: {
        const std::string lexeme = b.kind == BmlBehaviorKind::Pointing ? std::string("POINT") : b.lexeme;
        const std::string name = b.byName ? b.lexeme : lexicon.entryFor(lexeme, gesticon.names);
        const auto entry = name.empty() || !gesticon.entry ? std::nullopt : gesticon.entry(name);
        if (!entry && b.byName)
            return bmlBehaviorError(ErrorCode::NotFound, b,
                                    "the gesticon has no gesture \"" + name + "\" the character can play (it has: " +
                                        (gesticon.names.empty() ? std::string("none") : joined(gesticon.names, ", ")) + ").");
        if (!entry)
            return bmlBehaviorError(ErrorCode::NotFound, b,
                                    "no gesture for \"" + lexeme + "\" (the lexicon and the gesticon name none "
                                    "the character can play).");
        planned.gesture = name;
        planned.entry = *entry;
        if (b.kind == BmlBehaviorKind::Pointing) {
            auto target = motion::parseGazeTarget(b.target);
            if (!target)
                return bmlBehaviorError(target.error().code, b, target.error().message);
            auto hand = motion::parsePointingHand(b.mode);
            if (!hand)
                return bmlBehaviorError(hand.error().code, b, hand.error().message);
            planned.target = *target;
            planned.hand = *hand;
        }
        return {};
    }
    case BmlBehaviorKind::FaceLexeme: {
        auto faps = faceLexemeFaps(b.lexeme);
        if (!faps)
            return bmlBehaviorError(faps.error().code, b, faps.error().message);
        for (auto& [fap, value] : *faps)
            value *= b.amount;
        planned.faps = std::move(faps).value();
        return {};
    }
    case BmlBehaviorKind::Head: {
        const auto lexeme = motion::headLexemeNamed(b.lexeme);
        if (!lexeme)
            return bmlBehaviorError(ErrorCode::NotFound, b, "\"" + b.lexeme + "\" is no head lexeme (NOD, SHAKE, TILT).");
        planned.head = {*lexeme, b.repetition, b.amount, 0};
        return {};
    }
    case BmlBehaviorKind::Gaze: {
        auto target = motion::parseGazeTarget(b.target);
        if (!target)
            return bmlBehaviorError(target.error().code, b, target.error().message);
        planned.target = *target;
        planned.gaze = gazeDefaults;
        if (!b.influence.empty()) {
            auto influence = motion::parseGazeInfluence(b.influence);
            if (!influence)
                return bmlBehaviorError(influence.error().code, b, influence.error().message);
            planned.gaze.influence = *influence;
        }
        if (auto offset = motion::setGazeOffset(planned.gaze, b.offsetAngle, b.offsetDirection); !offset)
            return bmlBehaviorError(offset.error().code, b, offset.error().message);
        planned.gazeLetsGo = b.sync.contains(BmlPoint::End) || b.sync.contains(BmlPoint::Relax);
        return {};
    }
    case BmlBehaviorKind::Wait: break;
    }
    return {};
}

} // namespace

Error bmlBehaviorError(ErrorCode code, const BmlBehavior& behavior, const std::string& what)
{
    return makeError(code, "line " + std::to_string(behavior.line) + ", column " + std::to_string(behavior.column) +
                               ": " + std::string(bmlKindName(behavior.kind)) + " \"" + behavior.id + "\": " + what);
}

Result<BmlPlan> planBml(const BmlBlock& block, const std::map<std::string, SpeechTiming>& speech,
                        const BmlGesticon& gesticon, const BmlLexicon& lexicon,
                        const motion::GazeSettings& gazeDefaults)
{
    BmlPlan plan;
    plan.behaviors.resize(block.behaviors.size());
    std::map<std::string, const BmlPlanned*> byId;
    for (std::size_t i = 0; i < block.behaviors.size(); ++i) {
        plan.behaviors[i].behavior = i;
        if (auto ok = prepare(block.behaviors[i], speech, gesticon, lexicon, gazeDefaults, plan.behaviors[i]); !ok)
            return ok.error();
        byId[block.behaviors[i].id] = &plan.behaviors[i];
    }
    const BmlNaturalTiming natural = [&](const BmlBehavior& b) -> Points {
        const BmlPlanned& p = *byId.at(b.id);
        switch (b.kind) {
        case BmlBehaviorKind::Gesture:
        case BmlBehaviorKind::Pointing:
            return phases(p.entry.seconds, p.entry.fadeIn, p.entry.fadeOut, p.entry.shape.stroke);
        case BmlBehaviorKind::Head: return phases(motion::naturalHeadGestureSeconds(p.head), 0, 0);
        case BmlBehaviorKind::FaceLexeme: return phases(kBmlFaceLexemeSeconds, 0.2, 0.3);
        case BmlBehaviorKind::Gaze: {
            Points at;
            at.fill(kBmlGazeShiftSeconds);
            at[kStart] = 0;
            return at;
        }
        case BmlBehaviorKind::Speech:
        case BmlBehaviorKind::Wait: break;
        }
        return {};
    };
    auto resolved = resolveBml(block, speech, natural);
    if (!resolved)
        return resolved.error();
    for (std::size_t i = 0; i < plan.behaviors.size(); ++i) {
        BmlPlanned& p = plan.behaviors[i];
        p.times = (*resolved)[i];
        const BmlBehaviorKind kind = block.behaviors[i].kind;
        if (kind == BmlBehaviorKind::Gesture || kind == BmlBehaviorKind::Pointing)
            placeGesture(p);
        if (kind == BmlBehaviorKind::FaceLexeme)
            p.weight = fades(p.times.at);
        if (kind == BmlBehaviorKind::Head)
            p.head.duration = std::max(p.length(), 0.05);
        if (kind == BmlBehaviorKind::Gaze && p.gazeLetsGo)
            p.gazeLetGo = block.behaviors[i].sync.contains(BmlPoint::Relax) ? p.times.at[kRelax] : p.times.at[kEnd];
        plan.end = std::max(plan.end, p.times.at[kEnd]);
    }
    return plan;
}

} // namespace thespis::core::speech
