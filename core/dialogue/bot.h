#pragma once
// A bot: its categories (matched through one graphmaster), sets, maps, substitutions, properties
// and predicate defaults. Immutable once built and shared by every conversation with it; what a
// visitor changes (predicates, learned categories) lives in the Conversation.

#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dialogue/aiml.h"
#include "dialogue/aiml_reader.h"
#include "dialogue/bot_files.h"
#include "dialogue/graphmaster.h"
#include "dialogue/normalise.h"
#include "util/error.h"

namespace thespis::core::dialogue {

class Bot {
public:
    /// Every category of every AIML file, in load order (files sorted by name, then file order).
    const std::vector<Category>& categories() const { return m_store.categories; }
    /// Sets by lower-case name (the file's stem: "lib/sets/color.set" → "color").
    const std::map<std::string, PhraseSet>& sets() const { return m_sets; }
    /// Maps by lower-case name; keys in match form.
    const std::map<std::string, PhraseMap>& maps() const { return m_maps; }
    const std::map<std::string, std::string>& properties() const { return m_properties; }
    /// A property's value, or the "default-property" property (else "unknown") when it has none.
    std::string property(std::string_view name) const;
    /// The characters that end a sentence: the "sentence-splitters" property, else "" (".!?").
    std::string_view sentenceSplitters() const;
    /// Predicate values a new conversation starts with (the .pdefaults files).
    const std::map<std::string, std::string>& predicateDefaults() const { return m_predicateDefaults; }
    /// A substitution list by name ("normal", "denormal", "person", "person2", "gender"); empty if none.
    const Substitutions& substitutions(std::string_view name) const;
    /// Each distinct word the patterns match (for <vocabulary/> and grammar generation).
    std::size_t vocabularySize() const { return m_vocabularySize; }

    const Graphmaster& graph() const { return m_graph; }
    const Template& templateOf(const Category& category) const { return m_store.templates[category.templateIndex]; }
    PatternContext patternContext() const { return PatternContext{&m_sets, &m_properties}; }

private:
    friend class BotBuilder;
    CategoryStore m_store;
    Graphmaster m_graph;
    std::map<std::string, PhraseSet> m_sets;
    std::map<std::string, PhraseMap> m_maps;
    std::map<std::string, std::string> m_properties, m_predicateDefaults;
    std::map<std::string, Substitutions, std::less<>> m_substitutions;
    std::size_t m_vocabularySize = 0;
};

struct LoadedBot {
    std::shared_ptr<const Bot> bot;
    std::vector<LoadProblem> problems; ///< what was skipped, by file and line
};

/// Gathers a bot's files (as text, so tests and fuzzers need no files), then builds it. Data
/// files (sets, maps, properties) may come in any order relative to the AIML: patterns are
/// resolved against them in build().
class BotBuilder {
public:
    void addAiml(std::string_view text, const std::string& file);
    void addSet(const std::string& name, std::string_view text, const std::string& file);
    void addMap(const std::string& name, std::string_view text, const std::string& file);
    void addSubstitutions(const std::string& name, std::string_view text, const std::string& file);
    void addProperties(std::string_view text, const std::string& file);
    void addPredicateDefaults(std::string_view text, const std::string& file);
    /// Reads one file, its kind told by its extension (.aiml .set .map .substitution .properties
    /// .pdefaults; others are ignored). A file that cannot be read is a problem, not a failure.
    void addFile(const std::filesystem::path& path);

    LoadedBot build() &&;

private:
    std::unique_ptr<Bot> m_bot = std::make_unique<Bot>();
    std::vector<LoadProblem> m_problems;
};

/// Loads a bot folder in Rosie's layout (lib/aiml, lib/sets, lib/maps, lib/substitutions,
/// lib/system; the folder itself or its "lib" may be given; files in any subfolder are found by
/// extension). FileNotFound when the folder does not exist.
Result<LoadedBot> loadBotFolder(const std::filesystem::path& folder);

/// Loads a bot from folders (as loadBotFolder() reads one) and files (their kind told by their
/// extension), in the order given. FileNotFound naming the first path that does not exist.
Result<LoadedBot> loadBot(std::span<const std::filesystem::path> paths);

/// Loads a list of AIML files (no sets, maps or substitutions besides what is built in).
LoadedBot loadBotFiles(std::span<const std::filesystem::path> aimlFiles);

} // namespace thespis::core::dialogue
