// Face mapping tables (face_mapping.h): their JSON format, and applying one to a character.

#include "scene/face_mapping.h"

#include <array>
#include <cmath>

#include "scene/character.h"
#include "util/file_io.h"
#include "util/json_document.h"
#include "util/json_object_reader.h"
#include "util/text.h"

namespace thespis::core::scene {

namespace {

using json_document::json;
using json_document::describeValue;
using json_document::fail;
using json_document::quote;

// Upgrade steps, one per version after the first: kUpgradeSteps[i] takes a document of version
// i + 1 to version i + 2 before it is read. None yet.
using UpgradeStep = void (*)(json& document);
constexpr std::array<UpgradeStep, kFaceMappingVersion - 1> kUpgradeSteps{};

const char* sideName(MorphDrive::Side side)
{
    switch (side) {
    case MorphDrive::Side::Both: return "both";
    case MorphDrive::Side::Positive: return "positive";
    case MorphDrive::Side::Negative: return "negative";
    }
    return "both";
}

// A table's objects: the document reader's, with face channels.
class FieldReader : public json_document::ObjectReader {
public:
    FieldReader(const json& value, std::string path) : ObjectReader(value, std::move(path), "") {}

    double finite(std::string_view key) { return number(key, true, 0, json_document::Range::Any); }

    int channel(std::string_view key)
    {
        const json& value = require(key);
        if (value.is_number_integer()) {
            const double fap = value.get<double>(); // exact for every FAP number
            if (fap < 1 || fap > kFapCount)
                fail(fieldPath(key), "FAP numbers go from 1 to " + std::to_string(kFapCount) + ", found " + value.dump());
            return fapChannel(int(fap));
        }
        if (!value.is_string())
            fail(fieldPath(key), "expected a face channel's name or a FAP number, found " + describeValue(value));
        const std::string text = value.get<std::string>();
        const std::optional<int> channel = findFaceChannel(lowercase(text));
        if (!channel)
            fail(fieldPath(key), quote(text) + " is not a face channel (a FAP such as \"open_jaw\" or \"fap3\", \"viseme1\" "
                                               "… \"viseme14\", or an expression such as \"anger\")");
        return *channel;
    }

    void finish() const { refuseUnknown("a face mapping"); }
};

FaceMappingDrive readDrive(const json& value, const std::string& path)
{
    FieldReader reader(value, path);
    FaceMappingDrive drive;
    drive.target = reader.name("target");
    drive.channel = reader.channel("channel");
    drive.coefficient = reader.finite("coefficient");
    if (const json* side = reader.find("side")) {
        const std::string text = side->is_string() ? side->get<std::string>() : std::string();
        if (text == "positive")
            drive.side = MorphDrive::Side::Positive;
        else if (text == "negative")
            drive.side = MorphDrive::Side::Negative;
        else if (text != "both")
            fail(reader.fieldPath("side"), "expected \"both\", \"positive\" or \"negative\", found " + describeValue(*side));
    }
    reader.finish();
    return drive;
}

FaceMappingJoint readJoint(const json& value, const std::string& path)
{
    FieldReader reader(value, path);
    FaceMappingJoint joint;
    joint.joint = reader.name("joint");
    joint.channel = reader.channel("channel");
    const json& axis = reader.require("axis");
    const auto component = [&](std::size_t i) {
        const json& c = axis[i];
        if (!c.is_number() || !std::isfinite(c.get<double>()))
            fail(json_document::indexed(reader.fieldPath("axis"), i), "expected a finite number, found " + describeValue(c));
        return c.get<double>();
    };
    if (!axis.is_array() || axis.size() != 3)
        fail(reader.fieldPath("axis"), "expected a list of 3 numbers, found " + describeValue(axis));
    const anim::Vec3d v{component(0), component(1), component(2)};
    const double length = std::sqrt(anim::dot(v, v));
    if (!(length > 1e-9) || !std::isfinite(length))
        fail(reader.fieldPath("axis"), "the axis has no direction (its length is " + std::to_string(length) + ")");
    // A unit axis stays as written, so that what the writer wrote reads back bit for bit.
    joint.axis = std::abs(length - 1) <= 1e-12 ? v : v * (1 / length);
    joint.radiansPerUnit = reader.finite("radiansPerUnit");
    reader.finish();
    return joint;
}

// `what` names the table in messages: "The face mapping" or "The face mapping <path>".
Result<FaceMapping> readDocument(std::string_view text, const std::string& what)
{
    static constexpr json_document::Kind kKind{"face mapping", kFaceMappingFormat, 1, kFaceMappingVersion};
    Result<json_document::Versioned> parsed = json_document::parseVersioned(text, kKind);
    if (!parsed) {
        const Error& error = parsed.error();
        if (error.code == ErrorCode::CorruptData)
            return makeError(error.code, what + " is not valid: " + error.message, error.detail);
        return makeError(error.code, what + ": " + error.message, error.detail);
    }
    for (int version = parsed->version; version < kFaceMappingVersion; ++version)
        kUpgradeSteps[std::size_t(version - 1)](parsed->document);
    try {
        FieldReader reader(parsed->document, "");
        (void)reader.find("format");
        (void)reader.find("version");
        FaceMapping mapping;
        mapping.name = reader.string("name", false);
        const json& drives = reader.array("drives", false);
        for (std::size_t i = 0; i < drives.size(); ++i)
            mapping.drives.push_back(readDrive(drives[i], json_document::indexed("drives", i)));
        const json& joints = reader.array("joints", false);
        for (std::size_t i = 0; i < joints.size(); ++i)
            mapping.joints.push_back(readJoint(joints[i], json_document::indexed("joints", i)));
        reader.finish();
        return mapping;
    } catch (const json_document::FieldError& e) {
        return makeError(ErrorCode::CorruptData,
                         what + " is not valid: " + (e.path.empty() ? "" : e.path + ": ") + e.message + ".");
    }
}

} // namespace

std::string faceChannelName(int channel)
{
    if (channel < kFapCount)
        return std::string(fapInfo(channel + 1).name);
    if (channel < kFapCount + kVisemeCount)
        return "viseme" + std::to_string(channel - kFapCount + 1);
    return std::string(expressionName(channel - kFapCount - kVisemeCount + 1));
}

std::string serializeFaceMapping(const FaceMapping& mapping)
{
    nlohmann::ordered_json document;
    document["format"] = kFaceMappingFormat;
    document["version"] = kFaceMappingVersion;
    document["name"] = mapping.name;
    document["drives"] = nlohmann::ordered_json::array();
    for (const FaceMappingDrive& drive : mapping.drives) {
        nlohmann::ordered_json item{{"target", drive.target},
                                    {"channel", faceChannelName(drive.channel)},
                                    {"coefficient", drive.coefficient}};
        if (drive.side != MorphDrive::Side::Both)
            item["side"] = sideName(drive.side);
        document["drives"].push_back(std::move(item));
    }
    document["joints"] = nlohmann::ordered_json::array();
    for (const FaceMappingJoint& joint : mapping.joints)
        document["joints"].push_back({{"joint", joint.joint},
                                      {"channel", faceChannelName(joint.channel)},
                                      {"axis", {joint.axis.x, joint.axis.y, joint.axis.z}},
                                      {"radiansPerUnit", joint.radiansPerUnit}});
    return document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

Result<FaceMapping> parseFaceMapping(std::string_view text)
{
    return readDocument(text, "The face mapping");
}

Result<FaceMapping> loadFaceMapping(const std::filesystem::path& path)
{
    Result<std::string> text = readTextFile(path);
    if (!text)
        return text.error();
    return readDocument(*text, "The face mapping " + path.string());
}

Result<void> saveFaceMapping(const std::filesystem::path& path, const FaceMapping& mapping)
{
    return writeFileAtomically(path, serializeFaceMapping(mapping));
}

std::vector<std::string> applyFaceMapping(const FaceMapping& mapping, Character& character)
{
    const std::string table = "The face mapping" + (mapping.name.empty() ? "" : " " + inQuotes(mapping.name));
    const std::string model = character.name.empty() ? "the model" : character.name;
    FaceRig& face = character.face;
    std::vector<std::string> warnings;
    face.drives.clear();
    face.joints.clear();
    std::set<std::string> missing;
    std::set<int> driven;
    for (const FaceMappingDrive& drive : mapping.drives) {
        bool found = false;
        for (std::size_t t = 0; t < face.targets.size(); ++t)
            if (face.targets[t].name == drive.target) {
                face.drives.push_back({int(t), drive.channel, float(drive.coefficient), drive.side});
                found = true;
            }
        if (found)
            driven.insert(drive.channel);
        else if (missing.insert(drive.target).second)
            warnings.push_back(table + " drives the morph target " + inQuotes(drive.target) + ", which " + model +
                               " does not have.");
    }
    for (const FaceMappingJoint& drive : mapping.joints) {
        int joint = character.skeleton.find(drive.joint);
        for (int j = 0; j < character.skeleton.jointCount() && joint < 0; ++j)
            if (character.skeleton.joint(j).sourceName == drive.joint)
                joint = j;
        if (joint >= 0) {
            face.joints.push_back({joint, drive.channel, drive.axis, drive.radiansPerUnit});
            driven.insert(drive.channel);
        } else if (missing.insert(drive.joint).second) {
            warnings.push_back(table + " turns the joint " + inQuotes(drive.joint) + ", which " + model +
                               " does not have.");
        }
    }
    for (int v = 1; v <= kVisemeCount; ++v)
        if (driven.contains(visemeChannel(v)))
            face.visemes[std::size_t(v - 1)].clear();
    for (int e = 1; e <= kExpressionCount; ++e)
        if (driven.contains(expressionChannel(e)))
            face.expressions[std::size_t(e - 1)].clear();
    return warnings;
}

std::vector<std::string> morphTargetNames(const Character& character)
{
    std::vector<std::string> names;
    std::set<std::string> seen;
    for (const MorphTarget& target : character.face.targets)
        if (seen.insert(target.name).second)
            names.push_back(target.name);
    return names;
}

} // namespace thespis::core::scene
