#include "speech/speech_plan.h"

#include <algorithm>

namespace thespis::core::speech {

std::vector<VisemeCue> visemeCues(const SpeechTiming& timing, const VisemeSet& set)
{
    std::vector<VisemeCue> cues;
    // Cues stay inside the utterance: the face speaks while the audio does.
    const double end = std::max(timing.duration, timing.phonemes.empty() ? 0.0 : timing.phonemes.back().end);
    for (std::size_t i = 0; i < timing.phonemes.size(); ++i) {
        const PhonemeTiming& p = timing.phonemes[i];
        if (isPause(p.phoneme) || !(p.end > p.start))
            continue;
        const std::vector<int> ids = set.visemesOf(p.phoneme);
        const double part = (p.end - p.start) / double(ids.size());
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const Viseme* viseme = set.find(ids[k]);
            if (!viseme || viseme->id == 0)
                continue;
            const double from = p.start + part * double(k), to = from + part;
            // Widened by the spread on each side; kept symmetric about the centre, so the peak of
            // the dominance curve stays on the phoneme even where the utterance's start or end
            // clamps it.
            const double reach = std::min({part * viseme->spread, from, std::max(0.0, end - to)});
            VisemeCue cue;
            cue.viseme = viseme->id;
            cue.mpeg4 = viseme->mpeg4;
            cue.name = viseme->name;
            cue.phoneme = p.phoneme;
            cue.phonemeIndex = int(i);
            cue.start = from - reach;
            cue.duration = (to - from) + 2 * reach;
            cue.centre = (from + to) / 2;
            cue.weight = anim::Curve::dominance(viseme->alpha, viseme->weight);
            cues.push_back(std::move(cue));
        }
    }
    std::stable_sort(cues.begin(), cues.end(), [](const VisemeCue& a, const VisemeCue& b) { return a.start < b.start; });
    return cues;
}

std::vector<GestureCue> gestureCues(const TaggedText& text, const SpeechTiming& timing)
{
    std::vector<GestureCue> cues;
    for (const TaggedGesture& g : text.gestures) {
        GestureCue cue{g.id, g.animation, 0, 0, g.line, g.column};
        bool any = false;
        double before = 0, after = timing.duration;
        for (const WordTiming& w : timing.words) {
            const bool inside = w.textBegin < g.end && w.textEnd > g.begin;
            if (inside) {
                cue.start = any ? std::min(cue.start, w.start) : w.start;
                cue.end = any ? std::max(cue.end, w.end) : w.end;
                any = true;
            } else if (w.textEnd <= g.begin) {
                before = std::max(before, w.end);
            } else if (w.textBegin >= g.end) {
                after = std::min(after, w.start);
            }
        }
        if (!any) {
            cue.start = before;
            cue.end = std::max(before, after);
        }
        cues.push_back(std::move(cue));
    }
    return cues;
}

GestureFit fitGesture(const GestureSpan& span, double clipSeconds, const GestureShape& shape)
{
    GestureFit fit;
    fit.start = span.start;
    fit.duration = std::max(span.end - span.start, 1e-3);
    fit.stretch = clipSeconds > 0 ? fit.duration / clipSeconds : 1;
    const bool stroke = shape.stroke >= 0 && shape.stroke <= clipSeconds;
    constexpr double kRoom = 1e-3; // keys stay strictly in order
    if (clipSeconds <= 0 || (!stroke && !shape.hold) || fit.duration <= 4 * kRoom)
        return fit;
    // The pose the gesture is about (its stroke, else its middle) and when it shows, in local seconds.
    const double pose = stroke ? shape.stroke : clipSeconds / 2, length = fit.duration;
    double at = pose * fit.stretch;
    if (stroke && span.stroke >= 0)
        at = span.stroke - fit.start;
    else if (shape.hold)
        at = std::min(pose, length);
    at = std::clamp(at, kRoom, length - kRoom);
    const auto key = [](double time, double value) { return anim::CurveKey{time, value, anim::TangentMode::AutoClamped}; };
    fit.warp.push_back(key(0, 0));
    if (shape.hold) {
        // Its own speed into the pose and out of it, the pose held between; squeezed where short.
        const double into = at - pose, outOf = length - (clipSeconds - pose);
        if (into > kRoom && at - into > kRoom)
            fit.warp.push_back(key(into, 0));
        fit.warp.push_back(key(at, pose));
        if (outOf > at + kRoom && length - outOf > kRoom)
            fit.warp.push_back(key(outOf, pose));
    } else {
        fit.warp.push_back(key(at, pose));
    }
    fit.warp.push_back(key(length, clipSeconds));
    return fit;
}

} // namespace thespis::core::speech
