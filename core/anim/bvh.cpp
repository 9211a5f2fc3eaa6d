#include "anim/bvh.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include "anim/bvh_naming.h"
#include "anim/hanim.h"
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

// A joint moves when some frame turns it more than this away from its first frame: well above
// the rounding noise of 6-decimal files (1e-6°), well below any deliberate motion.
constexpr double kMovingAngle = 0.5 * std::numbers::pi / 180.0;

// ---------------------------------------------------------------------------------------------
// Text scanning with line numbers. A line ends at LF, CRLF or a lone CR, so LF, CRLF and mixed
// files (the cgspeed releases mix them) count lines the same way as an editor does.

bool isInlineSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
bool isBreak(char c) { return c == '\n' || c == '\r'; }
bool isSpace(char c) { return isInlineSpace(c) || isBreak(c); }

/// The next whitespace-separated word of `line` from `pos` (moved past it); empty at the end.
std::string_view nextWord(std::string_view line, std::size_t& pos)
{
    while (pos < line.size() && isInlineSpace(line[pos]))
        ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !isInlineSpace(line[pos]))
        ++pos;
    return line.substr(start, pos - start);
}

bool equalsNoCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size()
           && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
                  return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
              });
}

bool startsWithNoCase(std::string_view s, std::string_view prefix)
{
    return s.size() >= prefix.size() && equalsNoCase(s.substr(0, prefix.size()), prefix);
}

/// A token as it appears in an error message: quoted, at most 40 characters, control and
/// non-ASCII bytes escaped (the fuzzer feeds anything; messages must stay readable).
std::string quote(std::string_view token)
{
    std::string out = "'";
    const std::size_t shown = std::min<std::size_t>(token.size(), 40);
    for (std::size_t i = 0; i < shown; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\x%02x", unsigned(c));
            out += buffer;
        }
    }
    if (shown < token.size())
        out += "…";
    return out + "'";
}

struct Token {
    std::string_view text; // empty at the end of the text
    int line = 0;
};

class Scanner {
public:
    explicit Scanner(std::string_view text) : m_text(text)
    {
        if (m_text.starts_with("\xEF\xBB\xBF")) // UTF-8 byte order mark
            m_pos = 3;
    }

    std::size_t remaining() const { return m_text.size() - m_pos; }

    /// The next whitespace-separated token, across lines. At the end of the text: an empty
    /// token on the line of the last token, so that errors name a line the file has.
    Token next()
    {
        while (m_pos < m_text.size() && isSpace(m_text[m_pos]))
            advanceOne();
        if (m_pos >= m_text.size())
            return {{}, m_lastTokenLine};
        return word();
    }

    /// The next token on the current line, or an empty token at the end of the line.
    Token nextOnLine()
    {
        while (m_pos < m_text.size() && isInlineSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos < m_text.size() && isBreak(m_text[m_pos]))
            return {{}, m_line};
        return word();
    }

    /// The rest of the current line (without its line break) and its number; moves to the next
    /// line. False at the end of the text.
    bool nextLine(std::string_view& text, int& number)
    {
        if (m_pos >= m_text.size())
            return false;
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isBreak(m_text[m_pos]))
            ++m_pos;
        text = m_text.substr(start, m_pos - start);
        number = m_line;
        if (m_pos < m_text.size())
            advanceOne(); // LF or CR
        if (m_pos < m_text.size() && m_text[m_pos] == '\n' && m_text[m_pos - 1] == '\r')
            advanceOne(); // the LF of a CRLF
        return true;
    }

    /// Skips the rest of the current line; false if it held anything but spaces.
    bool restOfLineIsEmpty(Token& found)
    {
        found = nextOnLine();
        return found.text.empty();
    }

private:
    Token word()
    {
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos > start)
            m_lastTokenLine = m_line;
        return {m_text.substr(start, m_pos - start), m_line};
    }

    void advanceOne()
    {
        const char c = m_text[m_pos++];
        if (c == '\n' || (c == '\r' && (m_pos >= m_text.size() || m_text[m_pos] != '\n')))
            ++m_line;
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line = 1;
    int m_lastTokenLine = 1;
};

Error corrupt(int line, const std::string& message)
{
    return makeError(ErrorCode::CorruptData, "line " + std::to_string(line) + ": " + message);
}

/// Parses a whole token as a finite double ("+1.5", "-.25", "1e-05"). from_chars does not
/// accept a leading '+', which some exporters write.
bool parseNumber(std::string_view token, double& value)
{
    if (token.starts_with('+')) {
        token.remove_prefix(1);
        if (token.starts_with('-'))
            return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseInteger(std::string_view token, long long& value)
{
    if (token.starts_with('+')) {
        token.remove_prefix(1);
        if (token.starts_with('-'))
            return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && ec == std::errc() && end == token.data() + token.size();
}

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
// Rotations. BVH Euler angles are intrinsic, the first channel outermost: "Zrotation Xrotation
// Yrotation" means R = Rz·Rx·Ry, applied to column vectors in the parent's frame, so the
// quaternion is qz·qx·qy (Hamilton product, q v q*).

Quatd axisRotation(int axis, double degrees)
{
    const double half = std::fmod(degrees, 360.0) * (std::numbers::pi / 360.0);
    Quatd q{0, 0, 0, std::cos(half)};
    (axis == 0 ? q.x : axis == 1 ? q.y : q.z) = std::sin(half);
    return q;
}

using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 toMatrix(const Quatd& q0)
{
    const Quatd q = normalize(q0);
    const double x = q.x, y = q.y, z = q.z, w = q.w;
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
             {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
             {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b)
{
    Matrix3 m{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m[r][c] = a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c];
    return m;
}

Matrix3 axisMatrix(int axis, double radians)
{
    return toMatrix(axisRotation(axis, radians * 180.0 / std::numbers::pi));
}

/// Euler angles (radians) of R = R_i(a)·R_j(b)·R_k(c) for a permutation (i, j, k) of the axes.
/// b is in [−π/2, π/2]. In gimbal lock (|b| = π/2) only a ± c is defined: c is then kept at
/// `lockedC` (the previous frame's value, so curves stay continuous) and a takes the rest.
std::array<double, 3> decompose(const Matrix3& r, int i, int j, int k, double lockedC)
{
    const double s = (j - i + 3) % 3 == 1 ? 1.0 : -1.0; // +1 for cyclic orders (XYZ, YZX, ZXY)
    const double cosB = std::hypot(r[i][i], r[i][j]);
    const double b = std::atan2(s * r[i][k], cosB);
    if (cosB > 1e-9) {
        const double a = std::atan2(-s * r[j][k], r[k][k]);
        const double c = std::atan2(-s * r[i][j], r[i][i]);
        return {a, b, c};
    }
    const Matrix3 m = multiply(r, axisMatrix(k, -lockedC)); // = R_i(a)·R_j(b)
    const double a = std::atan2(s * m[k][j], m[j][j]);
    return {a, b, lockedC};
}

double unwrapNear(double angle, double reference)
{
    const double turn = 2 * std::numbers::pi;
    return angle + turn * std::round((reference - angle) / turn);
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

bool reachesBody(const std::set<std::string, std::less<>>& mapped)
{
    auto all = [&](std::initializer_list<std::string_view> names) {
        return std::all_of(names.begin(), names.end(), [&](std::string_view n) { return mapped.count(n) > 0; });
    };
    // The root plus both legs or both arms: whole bodies, and upper- or lower-body captures.
    return all({"humanoid_root"})
           && (all({"l_hip", "r_hip", "l_knee", "r_knee", "l_talocrural", "r_talocrural"})
               || all({"l_shoulder", "r_shoulder", "l_elbow", "r_elbow", "l_radiocarpal", "r_radiocarpal"}));
}

struct Naming {
    std::vector<std::string> names; // final joint names
    ImportReport report;            // convention, isBody, unmapped
};

/// Decides the joint names: the user's table or the detected convention's; a mapped name that
/// is taken (by an earlier joint, or as the own name of another joint of the file) is refused
/// and that joint keeps its own name, so names stay unique.
Naming nameJoints(const Hierarchy& h, const Motion& motion, std::size_t floatCount, const ImportOptions& options)
{
    Naming result;
    std::vector<std::string> fileNames;
    for (const FileJoint& joint : h.joints)
        fileNames.push_back(joint.name);

    JointMapping table;
    bool userTable = false;
    if (options.mapping) {
        table = *options.mapping;
        userTable = true;
        result.report.convention = "user";
    } else {
        naming::Detection detection = naming::detect(fileNames);
        result.report.convention = detection.convention;
        table = std::move(detection.mapping);
    }

    std::set<std::string, std::less<>> fileNameSet(fileNames.begin(), fileNames.end());
    std::set<std::string, std::less<>> used;
    std::vector<std::string> candidate(fileNames.size());
    for (std::size_t j = 0; j < fileNames.size(); ++j) {
        auto it = table.find(fileNames[j]);
        if (it == table.end() && userTable)
            it = table.find(std::string(naming::stripNamespace(fileNames[j])));
        if (it == table.end() || it->second.empty())
            continue;
        const std::string& target = it->second;
        if (used.count(target) || (target != fileNames[j] && fileNameSet.count(target)))
            continue;
        used.insert(target);
        candidate[j] = target;
    }

    // A face clip: only facial joints move (MakeHuman's face pose units sit on a full body rig
    // whose body joints stay still). It imports with its own names, as any non-body file.
    const std::vector<double> range = rotationRanges(motion, h.joints.size(), floatCount);
    bool faceMoves = false, bodyMoves = false;
    for (std::size_t j = 0; j < h.joints.size(); ++j) {
        if (range[j] <= kMovingAngle)
            continue;
        (naming::isFacialName(fileNames[j]) ? faceMoves : bodyMoves) = true;
    }
    const bool faceClip = faceMoves && !bodyMoves;

    const bool body = !faceClip && reachesBody(used);
    const bool rename = options.mapToHAnim && (userTable || body);
    result.report.isBody = body && rename;
    for (std::size_t j = 0; j < fileNames.size(); ++j) {
        if (rename && !candidate[j].empty()) {
            result.names.push_back(candidate[j]);
        } else {
            result.names.push_back(fileNames[j]);
            result.report.unmapped.push_back(fileNames[j]);
        }
    }
    return result;
}

// ---------------------------------------------------------------------------------------------
// Writing.

void appendNumber(std::string& out, double value)
{
    if (value == 0)
        value = 0; // no "-0"
    char buffer[32];
    const int n = std::snprintf(buffer, sizeof buffer, "%.9g", value);
    out.append(buffer, std::size_t(std::max(0, n)));
}

/// The shortest decimal frame time whose reciprocal is exactly `rate`, so that the file reads
/// back with the same frame rate, bit for bit ("0.0083333", not "0.0083333000000000001").
std::string frameTimeText(double rate)
{
    const double seconds = 1.0 / rate;
    char buffer[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, seconds);
        double back = 0;
        std::from_chars(buffer, buffer + std::char_traits<char>::length(buffer), back);
        if (back > 0 && 1.0 / back == rate)
            return buffer;
    }
    std::snprintf(buffer, sizeof buffer, "%.17g", seconds);
    return buffer;
}

/// The axes of a rotation order ("ZXY" → 2 0 1); letters other than X Y Z, or repeated ones,
/// fall back to ZXY (the common BVH order).
std::vector<int> orderAxes(const std::string& order)
{
    std::vector<int> axes;
    for (char c : order) {
        const int axis = c == 'X' || c == 'x' ? 0 : c == 'Y' || c == 'y' ? 1 : c == 'Z' || c == 'z' ? 2 : -1;
        if (axis < 0 || std::find(axes.begin(), axes.end(), axis) != axes.end() || axes.size() == 3)
            return {2, 0, 1};
        axes.push_back(axis);
    }
    return axes;
}

std::string writableName(const Joint& joint, int index)
{
    std::string name = joint.sourceName.empty() ? joint.name : joint.sourceName;
    for (char& c : name)
        if (isSpace(c) || c == '{' || c == '}')
            c = '_';
    return name.empty() ? "joint" + std::to_string(index) : name;
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

    Naming naming = nameJoints(h, *motion, floatCount, options);
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
    auto imported = parse(*text, options, path.stem().string());
    if (!imported) {
        Error error = imported.error();
        error.message = path.filename().string() + ", " + error.message;
        error.detail = path.string();
        return error;
    }
    return imported;
}

std::string write(const Skeleton& skeleton, const KeyframeClip& clip)
{
    const int jointCount = skeleton.jointCount();
    const FrameLayout& layout = *clip.layout();

    // Children and depth-first order (parents come before children in a Skeleton).
    std::vector<std::vector<int>> children(static_cast<std::size_t>(jointCount));
    for (int j = 1; j < jointCount; ++j)
        children[std::size_t(skeleton.joint(j).parent)].push_back(j);

    // File names: source names where known, unique.
    std::vector<std::string> names;
    std::set<std::string> taken;
    for (int j = 0; j < jointCount; ++j) {
        std::string name = writableName(skeleton.joint(j), j);
        for (int n = 2; taken.count(name); ++n)
            name = writableName(skeleton.joint(j), j) + "_" + std::to_string(n);
        taken.insert(name);
        names.push_back(std::move(name));
    }

    struct Plan {
        int joint;
        std::vector<int> axes; // rotation channels
        int rotation;          // rotation element in the clip's layout, or -1
        int translation;       // translation element in the clip's layout, or -1
    };
    std::vector<Plan> plans;

    std::string out = "HIERARCHY\n";
    // Iterative depth-first walk: (joint, next child index).
    std::vector<std::pair<int, std::size_t>> stack{{0, 0}};
    auto indent = [&](std::size_t depth) { out.append(depth, '\t'); };
    auto openJoint = [&](int j, std::size_t depth) {
        const Joint& joint = skeleton.joint(j);
        indent(depth);
        out += (j == 0 ? "ROOT " : "JOINT ") + names[std::size_t(j)] + "\n";
        indent(depth);
        out += "{\n";
        indent(depth + 1);
        out += "OFFSET ";
        appendNumber(out, joint.offset.x);
        out += ' ';
        appendNumber(out, joint.offset.y);
        out += ' ';
        appendNumber(out, joint.offset.z);
        out += '\n';
        Plan plan{j, joint.rotationOrder.empty() ? std::vector<int>{} : orderAxes(joint.rotationOrder),
                  layout.find(joint.name, ElementKind::Rotation), layout.find(joint.name, ElementKind::Translation)};
        const bool translates = j == 0 || joint.translates;
        indent(depth + 1);
        out += "CHANNELS " + std::to_string((translates ? 3 : 0) + plan.axes.size());
        if (translates)
            out += " Xposition Yposition Zposition";
        for (int axis : plan.axes)
            out += std::string(" ") + char('X' + axis) + "rotation";
        out += '\n';
        if (!translates)
            plan.translation = -2; // no position channels
        plans.push_back(std::move(plan));
    };
    auto closeJoint = [&](int j, std::size_t depth) {
        const Joint& joint = skeleton.joint(j);
        std::optional<Vec3d> endSite = joint.endSite;
        if (!endSite && children[std::size_t(j)].empty())
            endSite = joint.offset * 0.5; // a leaf needs an end for its bone; continue its direction
        if (endSite) {
            indent(depth + 1);
            out += "End Site\n";
            indent(depth + 1);
            out += "{\n";
            indent(depth + 2);
            out += "OFFSET ";
            appendNumber(out, endSite->x);
            out += ' ';
            appendNumber(out, endSite->y);
            out += ' ';
            appendNumber(out, endSite->z);
            out += '\n';
            indent(depth + 1);
            out += "}\n";
        }
        indent(depth);
        out += "}\n";
    };

    openJoint(0, 0);
    while (!stack.empty()) {
        auto& [j, next] = stack.back();
        const std::size_t depth = stack.size() - 1;
        if (next < children[std::size_t(j)].size()) {
            const int child = children[std::size_t(j)][next++];
            openJoint(child, depth + 1);
            stack.emplace_back(child, 0);
        } else {
            closeJoint(j, depth);
            stack.pop_back();
        }
    }

    out += "MOTION\nFrames: " + std::to_string(clip.frameCount()) + "\nFrame Time: " + frameTimeText(clip.frameRate())
           + "\n";

    // Per joint, the previous frame's Euler angles: each frame picks, of the two Euler
    // solutions and their 360° turns, the one nearest to it, so curves in an animation tool
    // stay continuous.
    std::vector<std::array<double, 3>> previous(plans.size(), {0, 0, 0});
    for (int f = 0; f < clip.frameCount(); ++f) {
        const std::span<const float> frame = clip.frame(f);
        bool firstValue = true;
        auto value = [&](double v) {
            if (!firstValue)
                out += ' ';
            firstValue = false;
            appendNumber(out, v);
        };
        for (std::size_t p = 0; p < plans.size(); ++p) {
            const Plan& plan = plans[p];
            const Joint& joint = skeleton.joint(plan.joint);
            if (plan.translation != -2) {
                if (plan.translation >= 0) {
                    const std::size_t t = layout.floatOffset(plan.translation);
                    value(frame[t]);
                    value(frame[t + 1]);
                    value(frame[t + 2]);
                } else {
                    value(joint.offset.x);
                    value(joint.offset.y);
                    value(joint.offset.z);
                }
            }
            if (plan.axes.empty())
                continue;
            Quatd q = Quatd::identity();
            if (plan.rotation >= 0) {
                const Quat& r = rotationAt(frame, plan.rotation);
                q = {r.x, r.y, r.z, r.w};
            }
            // Complete a partial order (a joint with fewer than three rotation channels) with the
            // missing axes; the angles of those come out zero for motion such a joint can make.
            std::array<int, 3> axes{};
            std::size_t n = 0;
            for (int axis : plan.axes)
                axes[n++] = axis;
            for (int axis = 0; axis < 3 && n < 3; ++axis)
                if (std::find(plan.axes.begin(), plan.axes.end(), axis) == plan.axes.end())
                    axes[n++] = axis;
            const Matrix3 m = toMatrix(q);
            std::array<double, 3>& prev = previous[p];
            const std::array<double, 3> primary = decompose(m, axes[0], axes[1], axes[2], prev[2]);
            const double pi = std::numbers::pi;
            const std::array<double, 3> alternative = {primary[0] + pi, pi - primary[1], primary[2] + pi};
            std::array<double, 3> best{};
            double bestCost = std::numeric_limits<double>::infinity();
            for (const auto& candidate : {primary, alternative}) {
                std::array<double, 3> c = candidate;
                double cost = 0;
                for (int k = 0; k < 3; ++k) {
                    c[std::size_t(k)] = unwrapNear(c[std::size_t(k)], f == 0 ? 0.0 : prev[std::size_t(k)]);
                    const bool written = std::size_t(k) < plan.axes.size();
                    const double d = c[std::size_t(k)] - (f == 0 || !written ? 0.0 : prev[std::size_t(k)]);
                    // Angles of axes that are not written must be (near) zero; first frames
                    // prefer small angles.
                    cost += written ? d * d : 1e6 * d * d;
                }
                if (cost < bestCost) {
                    bestCost = cost;
                    best = c;
                }
            }
            // Continuity lets angles grow past ±180° on a spinning joint; beyond five turns they
            // are brought back near zero, so that 9 significant digits keep 1e-5° resolution.
            for (double& a : best)
                if (std::abs(a) > 10 * pi)
                    a = std::remainder(a, 2 * pi);
            prev = best;
            for (std::size_t k = 0; k < plan.axes.size(); ++k)
                value(best[k] * (180.0 / pi));
        }
        out += '\n';
    }
    return out;
}

Result<void> save(const std::filesystem::path& path, const Skeleton& skeleton, const KeyframeClip& clip)
{
    return writeFileAtomically(path, write(skeleton, clip));
}

Result<JointMapping> parseMapping(std::string_view text)
{
    JointMapping mapping;
    std::map<std::string, int> sourceLine, targetLine;
    std::map<std::string, std::string> targetSource;
    Scanner scanner(text);
    std::string_view line;
    int number = 0;
    while (scanner.nextLine(line, number)) {
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        std::vector<std::string_view> words;
        std::size_t pos = 0;
        for (std::string_view word = nextWord(line, pos); !word.empty(); word = nextWord(line, pos))
            words.push_back(word);
        if (words.empty())
            continue;
        // "file_joint hanim_joint", also written "file_joint = hanim_joint" or "… -> …".
        if (words.size() == 3 && (words[1] == "=" || words[1] == "->"))
            words.erase(words.begin() + 1);
        if (words.size() != 2)
            return corrupt(number, "expected 'file_joint_name hanim_joint_name', found " + quote(line));
        const std::string source(words[0]);
        const std::string target(hanim::fromHAnim11(words[1]));
        if (!hanim::isJointName(target))
            return corrupt(number, quote(words[1]) + " is not an H-Anim 2.0 joint name (e.g. l_hip, vl5, skullbase)");
        if (const auto it = sourceLine.find(source); it != sourceLine.end())
            return corrupt(number, "joint " + quote(source) + " is mapped twice (first on line "
                                       + std::to_string(it->second) + ")");
        if (const auto it = targetLine.find(target); it != targetLine.end())
            return corrupt(number, quote(target) + " is already the target of " + quote(targetSource[target])
                                       + " (line " + std::to_string(it->second) + ")");
        sourceLine.emplace(source, number);
        targetLine.emplace(target, number);
        targetSource.emplace(target, source);
        mapping.emplace(source, target);
    }
    return mapping;
}

Result<JointMapping> loadMapping(const std::filesystem::path& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto mapping = parseMapping(*text);
    if (!mapping) {
        Error error = mapping.error();
        error.message = path.filename().string() + ", " + error.message;
        error.detail = path.string();
        return error;
    }
    return mapping;
}

} // namespace thespis::core::anim::bvh
