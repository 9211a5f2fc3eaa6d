#pragma once
// BML 1.0, the subset real agents use (SmartBody, Greta, AsapRealizer): one <bml> block of
// behaviours whose sync points refer to each other and to the words of a speech —
//   <bml id="bml1" composition="merge">
//     <speech id="s1"><text>Hello <sync id="t1"/>there, how are you?</text></speech>
//     <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
//     <head id="h1" lexeme="NOD" start="g1:stroke + 0.3" repetition="2"/>
//     <gaze id="z1" target="camera" influence="HEAD" start="s1:start"/>
//   </bml>
// Read with expat (line and column of every element); errors read "line L, column C: …".
// resolveBml() turns the sync constraints into times, given the speech's word timing and each
// behaviour's natural timing; the planner (speech/speech_plan.h) makes Stage actions of them.

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "speech/speech_timing.h"
#include "util/error.h"

namespace thespis::core::speech {

/// The standard sync points of every behaviour, in the order their times must keep.
enum class BmlPoint { Start, Ready, StrokeStart, Stroke, StrokeEnd, Relax, End };
inline constexpr int kBmlPointCount = 7;
/// "start", "ready", "strokeStart", "stroke", "strokeEnd", "relax", "end".
std::string_view bmlPointName(BmlPoint point);
std::optional<BmlPoint> bmlPointNamed(std::string_view name);

/// A time a sync attribute names: "s1:t1", "g1:stroke + 0.3", "bml1:s1:start - 0.5" (the block's
/// own id may prefix it), or a number of seconds from the block's start ("1.5").
struct BmlSyncRef {
    std::string behavior;   ///< empty: `offset` seconds from the block's start
    std::string point;      ///< a standard point's name, or the id of a speech's <sync>
    double offset = 0;      ///< seconds added (negative for " - ")
    bool operator==(const BmlSyncRef&) const = default;
};
/// Reads a sync attribute's value; InvalidArgument naming what is wrong.
Result<BmlSyncRef> parseBmlSyncRef(std::string_view text);
/// The reference as BML writes it ("g1:stroke + 0.3", "1.5").
std::string bmlSyncRefString(const BmlSyncRef& ref);

enum class BmlBehaviorKind { Speech, Gesture, FaceLexeme, Head, Gaze, Pointing, Wait };
/// The element's name: "speech", "gesture", "faceLexeme", "head", "gaze", "pointing", "wait".
std::string_view bmlKindName(BmlBehaviorKind kind);

struct BmlBehavior {
    BmlBehaviorKind kind = BmlBehaviorKind::Speech;
    std::string id;                         ///< required, unique in the block
    int line = 0, column = 0;               ///< where its element starts, for messages
    /// The sync attributes it has, by point (start="…", stroke="…" …).
    std::map<BmlPoint, BmlSyncRef> sync;

    // speech: its <text>, markup taken out, and where each <sync id/> stands in it (byte offset).
    std::string text;
    std::vector<std::pair<std::string, std::size_t>> syncMarks;

    std::string lexeme;     ///< gesture (or its `name`), faceLexeme, head (NOD, SHAKE, TILT …)
    bool byName = false;    ///< gesture: `name` names a gesticon entry rather than a lexeme
    double amount = 1;      ///< faceLexeme, head (0 … 1)
    int repetition = 1;     ///< head
    std::string target;     ///< gaze, pointing: "camera", "Antigone", "Antigone:HumanoidRoot", "x y z"
    std::string influence;  ///< gaze: EYES, HEAD, SHOULDER, WAIST (empty: EYES … HEAD)
    double offsetAngle = 0; ///< gaze: degrees away from the target
    std::string offsetDirection; ///< gaze: RIGHT, LEFT, UP, DOWN, UPRIGHT, UPLEFT, DOWNRIGHT, DOWNLEFT
    std::string mode;       ///< pointing: LEFT_HAND, RIGHT_HAND, BOTH_HANDS
    double duration = 0;    ///< wait: seconds
    bool operator==(const BmlBehavior&) const = default;
};

enum class BmlComposition { Merge, Append, Replace };

struct BmlBlock {
    std::string id;
    std::string character;  ///< the `characterId` attribute (empty: the one it is sent to)
    BmlComposition composition = BmlComposition::Merge;
    std::vector<BmlBehavior> behaviors; ///< in document order
    bool operator==(const BmlBlock&) const = default;
};

/// Reads one <bml> block (namespaced or not). CorruptData "line L, column C: …" for malformed
/// XML, an unknown element or attribute value, a behaviour without id or with an id used twice,
/// a sync attribute that does not read, a <sync> outside a speech's <text>.
Result<BmlBlock> parseBml(std::string_view xml);
/// The block written back as BML that parseBml() reads equal (up to line and column).
std::string bmlString(const BmlBlock& block);

/// A behaviour's own timing when nothing constrains it: seconds from its start to each standard
/// point (non-decreasing; Start is 0). A speech's comes from its word timing.
using BmlNaturalTiming = std::function<std::array<double, kBmlPointCount>(const BmlBehavior&)>;

struct BmlTimes {
    std::string behavior;                    ///< its id
    std::array<double, kBmlPointCount> at{}; ///< seconds from the block's start, by BmlPoint
    std::vector<double> marks;               ///< a speech's <sync> points, in its syncMarks' order
    bool operator==(const BmlTimes&) const = default;
};

/// When each behaviour's points fall, in document order: the constrained points where their
/// references say, the others by the behaviour's natural timing — shifted when one point is
/// constrained, stretched piecewise between two or more. A behaviour constrained by nothing
/// starts with the block. A speech's own points are its start and end, and each <sync id> is
/// the end of the word it directly follows ("word<sync/>"), else the start of the word after it
/// (the end of the last word when none follows); `speech` holds
/// the timing of each speech's text by the speech's id. A speech ends at the later of its audio's
/// duration and its last word's end, a wait after its duration; both have ready … stroke at their
/// start and strokeEnd … relax at their end. `natural` is asked for the other kinds only (when it
/// is empty, they take no time). Pinned points with equal natural offsets spread evenly between.
/// Errors (InvalidArgument, naming the behaviour with its line and column): a reference to a
/// behaviour or point that does not exist; references that form a cycle (the cycle named:
/// "g1:start → h1:end → g1:start"); constrained points out of order.
Result<std::vector<BmlTimes>> resolveBml(const BmlBlock& block, const std::map<std::string, SpeechTiming>& speech,
                                         const BmlNaturalTiming& natural);

} // namespace thespis::core::speech
