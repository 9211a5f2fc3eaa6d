#include "motion/gaze_target.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "util/text.h"

namespace thespis::core::motion {

namespace {

// Three finite numbers separated by spaces or commas, and nothing else.
bool readPoint(std::string_view text, anim::Vec3d& point)
{
    std::array<double, 3> values{};
    const char* at = text.data();
    const char* end = text.data() + text.size();
    for (double& value : values) {
        while (at < end && (*at == ' ' || *at == ',' || *at == '\t'))
            ++at;
        const auto [next, error] = std::from_chars(at, end, value);
        if (error != std::errc() || !std::isfinite(value))
            return false;
        at = next;
    }
    while (at < end && (*at == ' ' || *at == '\t'))
        ++at;
    if (at != end)
        return false;
    point = {values[0], values[1], values[2]};
    return true;
}

} // namespace

Result<GazeTarget> parseGazeTarget(std::string_view text)
{
    text = trimmed(text);
    GazeTarget target;
    if (text.empty())
        return makeError(ErrorCode::InvalidArgument,
                         "A gaze target is \"camera\", a character (\"Antigone\", \"Antigone:l_radiocarpal\") or a "
                         "point (\"0.5 1.6 2\"); it is empty.");
    if (uppercase(text) == "CAMERA") {
        target.kind = GazeTarget::Kind::Camera;
        return target;
    }
    if (readPoint(text, target.point)) {
        target.kind = GazeTarget::Kind::Point;
        return target;
    }
    if (std::isdigit(static_cast<unsigned char>(text.front())) || text.front() == '-' || text.front() == '.')
        return makeError(ErrorCode::InvalidArgument,
                         "The gaze target \"" + std::string(text) + "\" is not a point: it needs three numbers, x y z.");
    target.kind = GazeTarget::Kind::Joint;
    const std::size_t colon = text.find(':');
    target.character = std::string(trimmed(text.substr(0, colon)));
    if (colon != std::string_view::npos)
        target.joint = std::string(trimmed(text.substr(colon + 1)));
    if (target.character.empty() || (colon != std::string_view::npos && target.joint.empty()))
        return makeError(ErrorCode::InvalidArgument,
                         "The gaze target \"" + std::string(text) + "\" needs a character before the colon and a joint after it.");
    return target;
}

std::string gazeTargetString(const GazeTarget& target)
{
    switch (target.kind) {
    case GazeTarget::Kind::Camera: return "camera";
    case GazeTarget::Kind::Point: {
        char text[96];
        std::snprintf(text, sizeof text, "%g %g %g", target.point.x, target.point.y, target.point.z);
        return text;
    }
    case GazeTarget::Kind::Joint: break;
    }
    return target.joint.empty() ? target.character : target.character + ":" + target.joint;
}

Result<GazeInfluence> parseGazeInfluence(std::string_view text)
{
    const std::string name = uppercase(trimmed(text));
    if (name == "EYES")
        return GazeInfluence::Eyes;
    if (name == "HEAD" || name == "NECK")
        return GazeInfluence::Head;
    if (name == "SHOULDER")
        return GazeInfluence::Shoulder;
    if (name == "WAIST" || name == "WHOLE")
        return GazeInfluence::Waist;
    return makeError(ErrorCode::InvalidArgument, "The gaze influence \"" + std::string(text) +
                                                     "\" is none of EYES, HEAD, NECK, SHOULDER, WAIST, WHOLE.");
}

std::string_view gazeInfluenceName(GazeInfluence influence)
{
    switch (influence) {
    case GazeInfluence::Eyes: return "EYES";
    case GazeInfluence::Head: return "HEAD";
    case GazeInfluence::Shoulder: return "SHOULDER";
    case GazeInfluence::Waist: break;
    }
    return "WAIST";
}

Result<void> setGazeOffset(GazeSettings& settings, double angleDegrees, std::string_view direction)
{
    // Clockwise from up, as BML's POLAR: the named ones are its multiples of 45°.
    const std::string name = uppercase(trimmed(direction));
    double polar = 0;
    if (name.empty() || angleDegrees == 0) {
        settings.offsetHeading = settings.offsetPitch = 0;
        return {};
    }
    static constexpr std::pair<std::string_view, double> kNamed[] = {
        {"UP", 0}, {"UPRIGHT", 45}, {"RIGHT", 90}, {"DOWNRIGHT", 135},
        {"DOWN", 180}, {"DOWNLEFT", 225}, {"LEFT", 270}, {"UPLEFT", 315}};
    const auto named = std::find_if(std::begin(kNamed), std::end(kNamed), [&](const auto& n) { return n.first == name; });
    if (named != std::end(kNamed)) {
        polar = named->second;
    } else if (name.rfind("POLAR", 0) == 0) {
        const std::string_view number = trimmed(std::string_view(name).substr(5));
        const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), polar);
        if (error != std::errc() || end != number.data() + number.size() || !std::isfinite(polar))
            return makeError(ErrorCode::InvalidArgument, "The gaze offset direction \"" + std::string(direction) +
                                                             "\" needs a number of degrees after POLAR.");
    } else {
        return makeError(ErrorCode::InvalidArgument, "The gaze offset direction \"" + std::string(direction) +
                                                         "\" is none of RIGHT, LEFT, UP, DOWN, UPRIGHT, UPLEFT, "
                                                         "DOWNRIGHT, DOWNLEFT, POLAR n.");
    }
    const double radians = polar * std::numbers::pi / 180;
    // Heading + is to the character's left, pitch + down.
    settings.offsetHeading = -angleDegrees * std::sin(radians);
    settings.offsetPitch = -angleDegrees * std::cos(radians);
    return {};
}

} // namespace thespis::core::motion
