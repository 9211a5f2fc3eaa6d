// Which files a scenario package holds, and under which names (package_contents.h).

#include "scenario/package_contents.h"

#include <algorithm>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "scenario/package_manifest.h"
#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::scenario {

namespace {

namespace fs = std::filesystem;

class Planner {
public:
    Planner(const Assets& assets, PackagePlan& plan) : m_assets(assets), m_plan(plan)
    {
        m_taken.insert(plan.scenarioEntry);
        m_taken.insert(std::string(kManifestName));
    }

    /// Adds the file `name` names (nothing for an empty name) and rewrites `name` to its entry.
    Result<void> add(std::string& name, const std::string& field)
    {
        if (name.empty())
            return {};
        const fs::path source = m_assets.path(name);
        std::error_code error;
        if (!fs::is_regular_file(source, error))
            return makeError(ErrorCode::NotFound, field + " names " + name + ", which is not a file (looked for "
                                                      + source.string() + " in " + m_assets.describe() + ").");
        const std::string key = fs::weakly_canonical(source, error).string();
        if (const auto known = m_entryOf.find(key); known != m_entryOf.end()) {
            name = known->second;
            return {};
        }
        const std::string entry = entryFor(name, source);
        m_entryOf.emplace(key, entry);
        m_plan.files.push_back({entry, source, field});
        name = entry;
        if (source.extension() == ".gltf")
            return addGltfDependencies(entry, source, field);
        return {};
    }

private:
    /// The name as it stands when it is relative and stays inside the folder; else assets/<file>.
    std::string entryFor(const std::string& name, const fs::path& source)
    {
        const std::string normal = fs::path(name).lexically_normal().generic_string();
        if (checkEntryName(normal) && m_taken.insert(normal).second)
            return normal;
        const fs::path file = source.filename();
        std::string entry = "assets/" + file.generic_string();
        for (int n = 2; !m_taken.insert(entry).second; ++n)
            entry = "assets/" + file.stem().generic_string() + "-" + std::to_string(n) + file.extension().generic_string();
        return entry;
    }

    /// A .gltf's buffers and images travel with it, beside it as they were.
    Result<void> addGltfDependencies(const std::string& entry, const fs::path& source, const std::string& field)
    {
        auto text = readTextFile(source);
        if (!text)
            return text.error();
        const nlohmann::json document = nlohmann::json::parse(*text, nullptr, false);
        if (!document.is_object())
            return makeError(ErrorCode::CorruptData, field + ": " + source.string() + " is not a glTF (JSON) file.");
        const std::string folder = fs::path(entry).parent_path().generic_string();
        for (const char* list : {"buffers", "images"}) {
            const auto found = document.find(list);
            if (found == document.end() || !found->is_array())
                continue;
            for (const nlohmann::json& item : *found) {
                const auto uri = item.find("uri");
                if (uri == item.end() || !uri->is_string() || uri->get_ref<const std::string&>().starts_with("data:"))
                    continue;
                const std::string& relative = uri->get_ref<const std::string&>();
                const std::string name = folder.empty() ? relative : folder + "/" + relative;
                if (!checkEntryName(fs::path(relative).lexically_normal().generic_string()))
                    return makeError(ErrorCode::CorruptData, field + ": " + source.string() + " names " + relative
                                                                 + ", outside its folder: a package keeps a glTF's files beside it.");
                const fs::path file = source.parent_path() / relative;
                std::error_code error;
                if (!fs::is_regular_file(file, error))
                    return makeError(ErrorCode::NotFound, field + ": " + source.string() + " names " + relative
                                                              + ", which is not a file (looked for " + file.string() + ").");
                const std::string key = fs::weakly_canonical(file, error).string();
                if (m_entryOf.contains(key))
                    continue;
                m_taken.insert(name);
                m_entryOf.emplace(key, name);
                m_plan.files.push_back({name, file, field});
            }
        }
        return {};
    }

public:
    /// Files a script's string literals name ('speech/hello.wav'), added and renamed in its text.
    Result<void> addScriptFiles(ScriptSpec& script)
    {
        std::string& text = script.source;
        for (std::size_t at = 0; at < text.size(); ++at) {
            const char quote = text[at];
            if (quote != '\'' && quote != '"')
                continue;
            const std::size_t end = text.find(quote, at + 1);
            if (end == std::string::npos)
                continue;
            std::string literal = text.substr(at + 1, end - at - 1);
            std::error_code error;
            // Every quote is tried as an opening one, so an apostrophe in a comment cannot hide a name.
            if (literal.empty() || literal.find('\n') != std::string::npos || !isScriptMediaFile(literal) ||
                !fs::is_regular_file(m_assets.path(literal), error))
                continue;
            if (auto added = add(literal, "scripts[" + script.name + "]"); !added)
                return added.error();
            text.replace(at + 1, end - at - 1, literal);
            at += literal.size() + 1;
        }
        return {};
    }

private:
    const Assets& m_assets;
    PackagePlan& m_plan;
    std::set<std::string> m_taken;
    std::map<std::string, std::string> m_entryOf; // canonical source → entry
};

} // namespace

bool isScriptMediaFile(const std::filesystem::path& file)
{
    const std::string extension = lowercase(file.extension().string());
    for (const char* known : {".wav", ".ogg", ".flac", ".aiml", ".jsgf", ".gram", ".csv"})
        if (extension == known)
            return true;
    return false;
}

std::string addMadeFile(PackagePlan& plan, const std::string& preferred, const std::string& usedBy, std::string content)
{
    const auto taken = [&](const std::string& name) {
        return name == plan.scenarioEntry || name == kManifestName ||
               std::any_of(plan.files.begin(), plan.files.end(), [&](const PackageFile& f) { return f.name == name; });
    };
    const fs::path path(preferred);
    std::string entry = preferred;
    for (int n = 2; taken(entry); ++n)
        entry = (path.parent_path() / (path.stem().string() + "-" + std::to_string(n) + path.extension().string())).generic_string();
    plan.files.push_back({entry, {}, usedBy, std::move(content)});
    return entry;
}

Result<PackagePlan> planPackage(const Scenario& scenario, const Assets& assets, const std::string& scenarioEntry)
{
    if (auto allowed = checkEntryName(scenarioEntry); !allowed)
        return makeError(ErrorCode::InvalidArgument, allowed.error().message);
    PackagePlan plan;
    plan.scenario = scenario;
    plan.scenarioEntry = scenarioEntry;
    Planner planner(assets, plan);
    Scenario& s = plan.scenario;
    const auto add = [&](std::string& name, const std::string& field) { return planner.add(name, field); };
    for (Character& character : s.characters) {
        const std::string at = "characters[" + character.name + "]";
        if (auto added = add(character.model, at + ".model"); !added)
            return added.error();
        if (auto added = add(character.bake, at + ".bake"); !added)
            return added.error();
        if (auto added = add(character.faceMapping, at + ".faceMapping"); !added)
            return added.error();
        for (SpeechLine& line : character.speech)
            if (auto added = add(line.audio, at + ".speech[" + line.name + "].audio"); !added)
                return added.error();
        for (ClipAsset& clip : character.clips) {
            if (auto added = add(clip.file, at + ".clips[" + clip.name + "].file"); !added)
                return added.error();
            if (clip.idle)
                if (auto added = add(clip.idle->database, at + ".clips[" + clip.name + "].idle.database"); !added)
                    return added.error();
        }
    }
    if (auto added = add(s.lighting.probe, "lighting.probe"); !added)
        return added.error();
    if (auto added = add(s.postureBases, "postureBases"); !added)
        return added.error();
    for (PhantomOccluder& occluder : s.ar.occluders)
        if (auto added = add(occluder.model, "ar.occluders[" + occluder.name + "].model"); !added)
            return added.error();
    for (ScriptSpec& script : s.scripts)
        if (auto added = planner.addScriptFiles(script); !added)
            return added.error();
    return plan;
}

} // namespace thespis::core::scenario
