// Reading BVH (bvh::parse and load): the hierarchy, the motion as quaternion frames, the
// calibration frame check and the clip. Joint naming is bvh_naming.cpp's, writing bvh_write.cpp's.

#include "anim/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "anim/bvh_euler.h"
#include "anim/bvh_naming.h"
#include "anim/bvh_text.h"
#include "anim/rig_orientation.h"
#include "util/file_io.h"

namespace thespis::core::anim::bvh {
namespace {

// Limits checked before anything is allocated, so that a hostile header cannot ask for
// gigabytes: more joints or frames than any capture has, and at most 2^28 floats (1 GiB) of
// clip data.
constexpr int kMaxJoints = 10000;
// Positions and offsets end up in float frames (and rest poses): magnitudes that would round to
// a float infinity are refused. Below 2^128 − 2^103 a double rounds to a finite float; the cast
// clamps to FLT_MAX first so that it stays defined behaviour (and "3.40282347e+38", FLT_MAX as
// written with 9 digits, reads back).
constexpr double kFloatMax = std::numeric_limits<float>::max();
const double kFloatLimit = std::ldexp(1.0, 128) - std::ldexp(1.0, 103);

bool fitsFloat(double v) { return std::abs(v) < kFloatLimit; }
float toFloat(double v) { return float(std::clamp(v, -kFloatMax, kFloatMax)); }
constexpr long long kMaxFrames = 1000000;
constexpr long long kMaxClipFloats = 1LL << 28;

// ---------------------------------------------------------------------------------------------
// The hierarchy as read from the file.

enum class Channel : unsigned char { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

constexpr std::string_view kChannelNames[] = {"Xposition", "Yposition", "Zposition",
                                              "Xrotation", "Yrotation", "Zrotation"};

bool isRotation(Channel c) { return c >= Channel::Xrotation; }
int axisOf(Channel c) { return int(c) % 3; }

struct FileJoint {
    std::string name;
    int line = 0; // of its ROOT / JOINT keyword
    int parent = -1;
    Vec3d offset;
    bool hasOffset = false;
    bool hasChannels = false;
    std::vector<Channel> channels;
    int firstChannel = 0; // index of its first value on a frame line
    std::optional<Vec3d> endSite;
};

struct Hierarchy {
    std::vector<FileJoint> joints;
    int channelCount = 0;
};

Result<Vec3d> readOffset(Scanner& scanner, int keywordLine, const std::string& owner)
{
    Vec3d v;
    double* parts[3] = {&v.x, &v.y, &v.z};
    // The three numbers share the keyword's line, as every BVH writer puts them.
    for (double* part : parts) {
        const Token token = scanner.nextOnLine();
        if (token.text.empty())
            return corrupt(keywordLine, "expected OFFSET x y z for " + owner + ", found the end of the line");
        if (!parseNumber(token.text, *part))
            return corrupt(token.line, "expected OFFSET x y z for " + owner + ", found " + quote(token.text));
        if (!fitsFloat(*part))
            return corrupt(token.line, "the OFFSET of " + owner + " is out of range: " + quote(token.text));
        *part = std::clamp(*part, -kFloatMax, kFloatMax); // rest poses are floats
    }
    return v;
}

Result<void> readChannels(Scanner& scanner, int keywordLine, FileJoint& joint)
{
    // The count and the names share the keyword's line.
    const Token countToken = scanner.nextOnLine();
    long long count = 0;
    if (!parseInteger(countToken.text, count) || count < 0 || count > 6)
        return corrupt(countToken.text.empty() ? keywordLine : countToken.line,
                       "expected a channel count from 0 to 6 after CHANNELS for '" + joint.name + "', found "
                           + quote(countToken.text));
    for (long long i = 0; i < count; ++i) {
        const Token token = scanner.nextOnLine();
        const auto known = std::find_if(std::begin(kChannelNames), std::end(kChannelNames),
                                        [&](std::string_view name) { return equalsNoCase(name, token.text); });
        if (known == std::end(kChannelNames))
            return corrupt(token.text.empty() ? keywordLine : token.line,
                           "expected " + std::to_string(count) + " channel names (Xposition … Zrotation) for '"
                               + joint.name + "', found " + quote(token.text));
        const auto channel = Channel(known - std::begin(kChannelNames));
        if (std::find(joint.channels.begin(), joint.channels.end(), channel) != joint.channels.end())
            return corrupt(token.line, "joint '" + joint.name + "' lists channel " + quote(token.text) + " twice");
        joint.channels.push_back(channel);
    }
    return {};
}

/// Name after ROOT / JOINT: the rest of the line, words joined by one space, up to an optional
/// '{' on the same line (then `brace` is set).
std::string readName(Scanner& scanner, bool& brace)
{
    std::string name;
    brace = false;
    for (Token token = scanner.nextOnLine(); !token.text.empty(); token = scanner.nextOnLine()) {
        if (token.text == "{") {
            brace = true;
            break;
        }
        if (!name.empty())
            name += ' ';
        name += token.text;
    }
    return name;
}

/// Parses from after HIERARCHY up to and including the root's closing brace. Iterative (an
/// explicit stack), so that deeply nested input cannot overflow the call stack.
Result<Hierarchy> parseHierarchy(Scanner& scanner)
{
    Hierarchy h;
    std::map<std::string, int, std::less<>> lineOfName;
    std::vector<int> stack;

    auto openJoint = [&](const Token& keyword, int parent) -> Result<void> {
        if (int(h.joints.size()) >= kMaxJoints)
            return corrupt(keyword.line, "more than " + std::to_string(kMaxJoints) + " joints");
        FileJoint joint;
        bool brace = false;
        joint.name = readName(scanner, brace);
        joint.line = keyword.line;
        joint.parent = parent;
        if (joint.name.empty())
            return corrupt(keyword.line, "expected a joint name after " + std::string(keyword.text));
        if (const auto it = lineOfName.find(joint.name); it != lineOfName.end())
            return corrupt(keyword.line, "a second joint named " + quote(joint.name) + " (the first is on line "
                                             + std::to_string(it->second) + ")");
        lineOfName.emplace(joint.name, keyword.line);
        if (!brace) {
            const Token open = scanner.next();
            if (open.text != "{")
                return corrupt(open.text.empty() ? keyword.line : open.line,
                               "expected '{' after " + std::string(keyword.text) + " " + joint.name + ", found "
                                   + quote(open.text));
        }
        stack.push_back(int(h.joints.size()));
        h.joints.push_back(std::move(joint));
        return {};
    };

    const Token root = scanner.next();
    if (!equalsNoCase(root.text, "ROOT"))
        return corrupt(root.line,
                       "expected ROOT after HIERARCHY, found " + quote(root.text));
    if (auto ok = openJoint(root, -1); !ok)
        return ok.error();

    while (!stack.empty()) {
        FileJoint& current = h.joints[std::size_t(stack.back())];
        const Token token = scanner.next();
        if (token.text.empty())
            return corrupt(token.line, "the file ends inside joint '" + current.name + "' (opened on line "
                                               + std::to_string(current.line) + "): missing '}'");
        if (equalsNoCase(token.text, "OFFSET")) {
            if (current.hasOffset)
                return corrupt(token.line, "joint '" + current.name + "' has a second OFFSET");
            auto offset = readOffset(scanner, token.line, "joint '" + current.name + "'");
            if (!offset)
                return offset.error();
            current.offset = *offset;
            current.hasOffset = true;
        } else if (equalsNoCase(token.text, "CHANNELS")) {
            if (current.hasChannels)
                return corrupt(token.line, "joint '" + current.name + "' has a second CHANNELS line");
            current.hasChannels = true;
            if (auto ok = readChannels(scanner, token.line, current); !ok)
                return ok.error();
        } else if (equalsNoCase(token.text, "JOINT")) {
            if (!current.hasOffset || !current.hasChannels)
                return corrupt(token.line, "joint '" + current.name + "' needs its OFFSET and CHANNELS before JOINT");
            if (auto ok = openJoint(token, stack.back()); !ok)
                return ok.error();
        } else if (equalsNoCase(token.text, "End") || equalsNoCase(token.text, "EndSite")) {
            if (equalsNoCase(token.text, "End")) {
                const Token site = scanner.next();
                if (!equalsNoCase(site.text, "Site"))
                    return corrupt(site.text.empty() ? token.line : site.line,
                                   "expected 'End Site', found 'End " + quote(site.text).substr(1));
            }
            if (current.endSite)
                return corrupt(token.line, "joint '" + current.name + "' has a second End Site");
            const Token open = scanner.next();
            if (open.text != "{")
                return corrupt(open.text.empty() ? token.line : open.line,
                               "expected '{' after End Site, found " + quote(open.text));
            const Token keyword = scanner.next();
            if (!equalsNoCase(keyword.text, "OFFSET"))
                return corrupt(keyword.text.empty() ? open.line : keyword.line,
                               "expected OFFSET x y z in the End Site of '" + current.name + "', found "
                                   + quote(keyword.text));
            auto offset = readOffset(scanner, keyword.line, "the End Site of '" + current.name + "'");
            if (!offset)
                return offset.error();
            current.endSite = *offset;
            const Token close = scanner.next();
            if (close.text != "}")
                return corrupt(close.text.empty() ? keyword.line : close.line,
                               "expected '}' to close the End Site of '" + current.name + "', found "
                                   + quote(close.text));
        } else if (token.text == "}") {
            if (!current.hasOffset)
                return corrupt(token.line, "joint '" + current.name + "' (line " + std::to_string(current.line)
                                               + ") has no OFFSET");
            if (!current.hasChannels)
                return corrupt(token.line, "joint '" + current.name + "' (line " + std::to_string(current.line)
                                               + ") has no CHANNELS");
            stack.pop_back();
        } else {
            return corrupt(token.line, "expected OFFSET, CHANNELS, JOINT, End Site or '}' in joint '"
                                           + current.name + "', found " + quote(token.text));
        }
    }

    for (FileJoint& joint : h.joints) {
        joint.firstChannel = h.channelCount;
        h.channelCount += int(joint.channels.size());
    }
    return h;
}

// ---------------------------------------------------------------------------------------------
// Parsing the motion and building the clip.

struct Motion {
    int frameCount = 0;
    int extraFrameLines = 0; // well-formed frame lines past the announced count, skipped
    double frameTime = 0;
    std::vector<float> frames; // frameCount × floatCount, rotations of every joint then translations
};

/// "Frames:" / "Frame Time:" with the tolerated spellings: "Frames: 3069", "Frames:3069",
/// "Frames :  3069", tabs or runs of spaces between.
Result<std::string_view> readHeaderValue(Scanner& scanner, std::string_view label, const Token& first)
{
    // `first` starts with the label's last word ("Frames" or "Time"); the value may be glued to it.
    std::string_view rest = first.text.substr(label.size());
    Token token = first;
    if (rest.empty()) {
        token = scanner.nextOnLine();
        rest = token.text;
    }
    if (rest.starts_with(':')) {
        rest.remove_prefix(1);
        if (rest.empty()) {
            token = scanner.nextOnLine();
            rest = token.text;
        }
    } else {
        return Result<std::string_view>(corrupt(first.line, "expected ':' after '" + std::string(label) + "', found "
                                                                + quote(rest)));
    }
    if (rest.empty())
        return Result<std::string_view>(corrupt(first.line, "expected a value after '" + std::string(label) + ":'"));
    return rest;
}

Result<Motion> parseMotion(Scanner& scanner, const Hierarchy& h, int motionLine, std::size_t floatCount,
                           const std::vector<int>& translationOffset)
{
    Motion motion;
    if (h.channelCount == 0)
        return corrupt(motionLine, "the hierarchy declares no channels, so there is no motion to read");

    const Token framesToken = scanner.next();
    if (!startsWithNoCase(framesToken.text, "Frames"))
        return corrupt(framesToken.text.empty() ? motionLine : framesToken.line,
                       "expected 'Frames:' after MOTION, found " + quote(framesToken.text));
    auto framesText = readHeaderValue(scanner, "Frames", framesToken);
    if (!framesText)
        return framesText.error();
    long long frames = 0;
    if (!parseInteger(*framesText, frames))
        return corrupt(framesToken.line, "expected a whole number of frames after 'Frames:', found " + quote(*framesText));
    if (frames < 1)
        return corrupt(framesToken.line, "'Frames: " + std::to_string(frames) + "': a clip needs at least one frame");
    if (frames > kMaxFrames)
        return corrupt(framesToken.line, "'Frames: " + std::to_string(frames) + "' is more than the "
                                             + std::to_string(kMaxFrames) + " frames Thespis reads");
    if (Token extra; !scanner.restOfLineIsEmpty(extra))
        return corrupt(extra.line, "unexpected " + quote(extra.text) + " after the frame count");

    const Token frameToken = scanner.next();
    Token timeToken;
    if (equalsNoCase(frameToken.text, "Frame"))
        timeToken = scanner.nextOnLine();
    else if (startsWithNoCase(frameToken.text, "FrameTime")) // "FrameTime:" written as one word
        timeToken = {frameToken.text.substr(5), frameToken.line};
    else
        return corrupt(frameToken.text.empty() ? framesToken.line : frameToken.line,
                       "expected 'Frame Time:' after the frame count, found " + quote(frameToken.text));
    if (!startsWithNoCase(timeToken.text, "Time"))
        return corrupt(frameToken.line, "expected 'Frame Time:', found 'Frame " + quote(timeToken.text).substr(1));
    auto timeText = readHeaderValue(scanner, "Time", timeToken);
    if (!timeText)
        return timeText.error();
    double frameTime = 0;
    if (!parseNumber(*timeText, frameTime))
        return corrupt(frameToken.line, "expected a number of seconds after 'Frame Time:', found " + quote(*timeText));
    if (!(frameTime > 0) || !std::isfinite(1.0 / frameTime))
        return corrupt(frameToken.line, "'Frame Time: " + std::string(*timeText) + "' must be a positive number of seconds");
    if (Token extra; !scanner.restOfLineIsEmpty(extra))
        return corrupt(extra.line, "unexpected " + quote(extra.text) + " after the frame time");

    // The clip is refused beyond 1 GiB before anything is allocated. Below that, memory grows
    // with the frames actually read, so a header announcing more frames than the file holds
    // costs nothing (and is reported where the file ends): every value takes at least two
    // characters, which bounds the first reservation by the size of the text.
    const auto channels = std::size_t(h.channelCount);
    if (double(frames) * double(floatCount) > double(kMaxClipFloats))
        return corrupt(framesToken.line, "'Frames: " + std::to_string(frames) + "' with " + std::to_string(floatCount)
                                             + " values per frame would need more than 1 GiB of memory");

    motion.frameCount = int(frames);
    motion.frameTime = frameTime;
    const std::size_t possibleFrames = scanner.remaining() / (2 * channels) + 1;
    motion.frames.reserve(std::min(std::size_t(frames), possibleFrames) * floatCount);
    std::vector<double> values(channels);

    int frame = 0;
    std::string_view lineText;
    int lineNumber = 0;
    int lastLine = frameToken.line;
    while (scanner.nextLine(lineText, lineNumber)) {
        lastLine = lineNumber;
        // Split the line into values.
        std::size_t count = 0, pos = 0;
        bool any = false;
        for (std::string_view token = nextWord(lineText, pos); !token.empty(); token = nextWord(lineText, pos)) {
            any = true;
            if (count >= channels)
                return corrupt(lineNumber, "frame " + std::to_string(frame + 1) + " has more than the "
                                               + std::to_string(channels) + " values the hierarchy declares");
            if (!parseNumber(token, values[count]))
                return corrupt(lineNumber, "value " + std::to_string(count + 1) + " of frame " + std::to_string(frame + 1)
                                               + " is not a finite number: " + quote(token));
            ++count;
        }
        if (!any)
            continue; // blank lines between or after frames are harmless
        if (count != channels)
            return corrupt(lineNumber, "frame " + std::to_string(frame + 1) + " has " + std::to_string(count)
                                           + " values; the hierarchy declares " + std::to_string(channels));
        if (frame >= motion.frameCount) {
            // More frame lines than "Frames:" announces (Boxing_Toes.bvh has 3070 for 3069).
            // The header is the contract, as for assimp, which ships that file: the clip has
            // the announced frames; the extra lines must still be well-formed frames.
            ++frame;
            ++motion.extraFrameLines;
            continue;
        }

        motion.frames.resize(motion.frames.size() + floatCount);
        float* out = motion.frames.data() + std::size_t(frame) * floatCount;
        for (std::size_t j = 0; j < h.joints.size(); ++j) {
            const FileJoint& joint = h.joints[j];
            Quatd q = Quatd::identity();
            Vec3d t = joint.offset;
            for (std::size_t c = 0; c < joint.channels.size(); ++c) {
                const Channel channel = joint.channels[c];
                const double v = values[std::size_t(joint.firstChannel) + c];
                if (isRotation(channel))
                    q = q * axisRotation(axisOf(channel), v);
                else
                    (axisOf(channel) == 0 ? t.x : axisOf(channel) == 1 ? t.y : t.z) = v;
            }
            q = normalize(q);
            out[4 * j + 0] = float(q.x);
            out[4 * j + 1] = float(q.y);
            out[4 * j + 2] = float(q.z);
            out[4 * j + 3] = float(q.w);
            if (const int offset = translationOffset[j]; offset >= 0) {
                if (!fitsFloat(t.x) || !fitsFloat(t.y) || !fitsFloat(t.z))
                    return corrupt(lineNumber, "a position of joint '" + joint.name + "' in frame "
                                                   + std::to_string(frame + 1) + " is out of range");
                out[std::size_t(offset) + 0] = toFloat(t.x);
                out[std::size_t(offset) + 1] = toFloat(t.y);
                out[std::size_t(offset) + 2] = toFloat(t.z);
            }
        }
        ++frame;
    }
    // `frame` counts the extra lines too; fewer than announced is an error.
    if (frame < motion.frameCount)
        return corrupt(lastLine, "the file ends after " + std::to_string(frame) + " frames, but 'Frames:' announces "
                                     + std::to_string(motion.frameCount));
    return motion;
}

/// Largest rotation of each joint away from its first frame, over the clip.
std::vector<double> rotationRanges(const Motion& motion, std::size_t jointCount, std::size_t floatCount)
{
    std::vector<double> range(jointCount, 0.0);
    for (int f = 1; f < motion.frameCount; ++f) {
        const float* frame = motion.frames.data() + std::size_t(f) * floatCount;
        for (std::size_t j = 0; j < jointCount; ++j) {
            const float* a = motion.frames.data() + 4 * j;
            const float* b = frame + 4 * j;
            const Quatd qa{a[0], a[1], a[2], a[3]}, qb{b[0], b[1], b[2], b[3]};
            range[j] = std::max(range[j], angleBetween(qa, qb));
        }
    }
    return range;
}

/// Largest rotation of any joint between two frames.
double largestChange(const Motion& motion, std::size_t jointCount, std::size_t floatCount, int a, int b)
{
    double change = 0;
    for (std::size_t j = 0; j < jointCount; ++j) {
        const float* p = motion.frames.data() + std::size_t(a) * floatCount + 4 * j;
        const float* q = motion.frames.data() + std::size_t(b) * floatCount + 4 * j;
        change = std::max(change, angleBetween(Quatd{p[0], p[1], p[2], p[3]}, Quatd{q[0], q[1], q[2], q[3]}));
    }
    return change;
}

/// True when the first frame is a calibration pose the file opens with (the T-pose of CMU's MB2
/// releases) rather than motion: from it to the second frame some joint turns by more than 20°,
/// and by more than four times what any joint turns between the next frames.
bool firstFrameIsCalibration(const Motion& motion, std::size_t jointCount, std::size_t floatCount)
{
    if (motion.frameCount < 3)
        return false;
    const double jump = largestChange(motion, jointCount, floatCount, 0, 1);
    double usual = 0;
    for (int f = 1; f + 1 < std::min(motion.frameCount, 12); ++f)
        usual = std::max(usual, largestChange(motion, jointCount, floatCount, f, f + 1));
    return jump > 20.0 * std::numbers::pi / 180.0 && jump > 4.0 * usual;
}

} // namespace

// ---------------------------------------------------------------------------------------------

Result<ImportedClip> parse(std::string_view text, const ImportOptions& options, std::string_view clipName)
{
    if (options.frameRate && (!(*options.frameRate > 0) || !std::isfinite(*options.frameRate)))
        return makeError(ErrorCode::InvalidArgument, "The frame rate override must be a positive number of frames per second.");

    Scanner scanner(text);
    const Token first = scanner.next();
    if (!equalsNoCase(first.text, "HIERARCHY"))
        return makeError(ErrorCode::NotOurFormat, "Not a BVH file: it does not start with HIERARCHY.");

    auto hierarchy = parseHierarchy(scanner);
    if (!hierarchy)
        return hierarchy.error();
    const Hierarchy& h = *hierarchy;

    const Token motionToken = scanner.next();
    if (equalsNoCase(motionToken.text, "ROOT"))
        return corrupt(motionToken.line, "a second ROOT; Thespis reads BVH files with one skeleton");
    if (!equalsNoCase(motionToken.text, "MOTION"))
        return corrupt(motionToken.line,
                       "expected MOTION after the hierarchy, found " + quote(motionToken.text));

    // Frame layout: a rotation per joint, then a translation per translating joint (the root,
    // and every joint with position channels), in joint order, as Skeleton builds it.
    const std::size_t jointCount = h.joints.size();
    std::vector<int> translationOffset(jointCount, -1);
    std::size_t floatCount = 4 * jointCount;
    for (std::size_t j = 0; j < jointCount; ++j) {
        const auto& channels = h.joints[j].channels;
        const bool translates = j == 0 || std::any_of(channels.begin(), channels.end(),
                                                      [](Channel c) { return !isRotation(c); });
        if (translates) {
            translationOffset[j] = int(floatCount);
            floatCount += 3;
        }
    }

    auto motion = parseMotion(scanner, h, motionToken.line, floatCount, translationOffset);
    if (!motion)
        return motion.error();

    std::vector<std::string> fileNames;
    for (const FileJoint& joint : h.joints)
        fileNames.push_back(joint.name);
    naming::Naming naming =
        naming::nameJoints(fileNames, rotationRanges(*motion, jointCount, floatCount), options);
    naming.report.frameCount = motion->frameCount;
    naming.report.calibrationFrame = firstFrameIsCalibration(*motion, jointCount, floatCount);
    if (naming.report.calibrationFrame && options.dropCalibrationFrame) {
        motion->frames.erase(motion->frames.begin(), motion->frames.begin() + std::ptrdiff_t(floatCount));
        --motion->frameCount;
    }

    std::vector<Joint> joints;
    joints.reserve(jointCount);
    for (std::size_t j = 0; j < jointCount; ++j) {
        const FileJoint& fileJoint = h.joints[j];
        Joint joint;
        joint.name = naming.names[j];
        joint.sourceName = fileJoint.name;
        joint.parent = fileJoint.parent;
        joint.offset = fileJoint.offset;
        joint.endSite = fileJoint.endSite;
        joint.translates = translationOffset[j] >= 0;
        joint.rotationOrder.clear();
        for (Channel c : fileJoint.channels)
            if (isRotation(c))
                joint.rotationOrder += char('X' + axisOf(c));
        joints.push_back(std::move(joint));
    }
    auto skeleton = Skeleton::create(joints);
    if (!skeleton)
        return makeError(ErrorCode::CorruptData, "The BVH skeleton is not valid: " + skeleton.error().message);
    // A body lying down or facing away (a Z-up export) is stood up in H-Anim's axes.
    if (options.upright && naming.report.isBody) {
        const AxisTurn turn = uprightTurn(*skeleton);
        if (!turn.isIdentity()) {
            applyTurn(turn, joints);
            applyTurn(turn, *skeleton->frameLayout(), motion->frames);
            skeleton = Skeleton::create(std::move(joints));
            if (!skeleton)
                return makeError(ErrorCode::Internal, "Turning the BVH skeleton upright broke it: " + skeleton.error().message);
            naming.report.turnedFrom = turn.description;
        }
    }
    for (std::size_t j = 0; j < jointCount; ++j) {
        const int element = skeleton->translationElement(int(j));
        if ((element >= 0 ? int(skeleton->frameLayout()->floatOffset(element)) : -1) != translationOffset[j])
            return makeError(ErrorCode::Internal, "The BVH reader and Skeleton disagree on the frame layout.");
    }

    const double rate = options.frameRate ? *options.frameRate : 1.0 / motion->frameTime;
    auto clip = KeyframeClip::create(skeleton->frameLayout(), rate, std::move(motion->frames), std::string(clipName));
    if (!clip)
        return makeError(ErrorCode::CorruptData, "The BVH motion is not valid: " + clip.error().message);

    ImportedClip imported{std::move(*skeleton), std::move(*clip), std::move(naming.report)};
    imported.report.jointCount = int(jointCount);
    imported.report.channelCount = h.channelCount;
    imported.report.frameTime = motion->frameTime;
    imported.report.extraFrameLines = motion->extraFrameLines;
    return imported;
}

Result<ImportedClip> load(const std::filesystem::path& path, const ImportOptions& options)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    return parseFile(*text, path, options);
}

Result<ImportedClip> parseFile(std::string_view text, const std::filesystem::path& path, const ImportOptions& options)
{
    auto imported = parse(text, options, path.stem().string());
    if (!imported)
        return inFile(path, imported.error());
    return imported;
}

} // namespace thespis::core::anim::bvh
