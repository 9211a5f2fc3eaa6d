#include "dialogue/bot.h"

#include <algorithm>

#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::dialogue {

std::string Bot::property(std::string_view name) const
{
    if (const auto it = m_properties.find(std::string(name)); it != m_properties.end())
        return it->second;
    const auto fallback = m_properties.find("default-property");
    return fallback != m_properties.end() ? fallback->second : "unknown";
}

std::string_view Bot::sentenceSplitters() const
{
    const auto it = m_properties.find("sentence-splitters");
    return it != m_properties.end() ? std::string_view(it->second) : std::string_view();
}

const Substitutions& Bot::substitutions(std::string_view name) const
{
    static const Substitutions kNone;
    const auto it = m_substitutions.find(name);
    return it != m_substitutions.end() ? it->second : kNone;
}

void BotBuilder::addAiml(std::string_view text, const std::string& file)
{
    readAiml(text, file, m_bot->m_store, m_problems);
}

void BotBuilder::addSet(const std::string& name, std::string_view text, const std::string& file)
{
    m_bot->m_sets[lowercase(name)] = readSet(text, file, m_problems);
}

void BotBuilder::addMap(const std::string& name, std::string_view text, const std::string& file)
{
    PhraseMap& map = m_bot->m_maps[lowercase(name)];
    for (auto& [key, value] : readPairs(text, file, m_problems))
        map[matchForm(key)] = std::move(value);
}

void BotBuilder::addSubstitutions(const std::string& name, std::string_view text, const std::string& file)
{
    m_bot->m_substitutions[lowercase(name)] = Substitutions(readPairs(text, file, m_problems));
}

void BotBuilder::addProperties(std::string_view text, const std::string& file)
{
    for (auto& [key, value] : readPairs(text, file, m_problems))
        m_bot->m_properties[key] = std::move(value);
}

void BotBuilder::addPredicateDefaults(std::string_view text, const std::string& file)
{
    for (auto& [key, value] : readPairs(text, file, m_problems))
        m_bot->m_predicateDefaults[key] = std::move(value);
}

void BotBuilder::addFile(const std::filesystem::path& path)
{
    const std::string extension = lowercase(path.extension().string());
    const bool known = extension == ".aiml" || extension == ".set" || extension == ".map" || extension == ".substitution"
                       || extension == ".properties" || extension == ".pdefaults";
    if (!known)
        return;
    const std::string file = path.string();
    const Result<std::string> text = readTextFile(path);
    if (!text) {
        m_problems.push_back(LoadProblem{file, 0, 0, text.error().message});
        return;
    }
    const std::string stem = path.stem().string();
    if (extension == ".aiml")
        addAiml(*text, file);
    else if (extension == ".set")
        addSet(stem, *text, file);
    else if (extension == ".map")
        addMap(stem, *text, file);
    else if (extension == ".substitution")
        addSubstitutions(stem, *text, file);
    else if (extension == ".properties")
        addProperties(*text, file);
    else
        addPredicateDefaults(*text, file);
}

LoadedBot BotBuilder::build() &&
{
    Bot& bot = *m_bot;
    const PatternContext context = bot.patternContext();
    std::string problem;
    for (std::size_t i = 0; i < bot.m_store.categories.size(); ++i) {
        const Category& category = bot.m_store.categories[i];
        if (!bot.m_graph.add(category, std::uint32_t(i), context, problem))
            m_problems.push_back(LoadProblem{category.source.file, category.source.line, 0, problem + "; the category is skipped"});
    }
    bot.m_graph.freeze();
    bot.m_vocabularySize = bot.m_graph.wordCount() - 2;
    return LoadedBot{std::shared_ptr<const Bot>(std::move(m_bot)), std::move(m_problems)};
}

Result<LoadedBot> loadBot(std::span<const std::filesystem::path> paths)
{
    BotBuilder builder;
    for (const std::filesystem::path& path : paths) {
        std::error_code error;
        if (!std::filesystem::is_directory(path, error)) {
            if (!std::filesystem::exists(path, error))
                return makeError(ErrorCode::FileNotFound, "The bot file or folder " + inQuotes(path.string()) + " does not exist.");
            builder.addFile(path);
            continue;
        }
        std::vector<std::filesystem::path> files;
        for (auto it = std::filesystem::recursive_directory_iterator(path, error);
             !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error))
            if (it->is_regular_file(error))
                files.push_back(it->path());
        if (error)
            return makeError(ErrorCode::IoError, "The bot folder " + inQuotes(path.string()) + " could not be listed.", error.message());
        // Sorted by name so that update files ("z_update.aiml") come last and win over what they replace.
        std::sort(files.begin(), files.end());
        for (const std::filesystem::path& file : files)
            builder.addFile(file);
    }
    return std::move(builder).build();
}

Result<LoadedBot> loadBotFolder(const std::filesystem::path& folder)
{
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return makeError(ErrorCode::FileNotFound, "The bot folder " + inQuotes(folder.string()) + " does not exist.");
    return loadBot(std::span(&folder, 1));
}

LoadedBot loadBotFiles(std::span<const std::filesystem::path> aimlFiles)
{
    BotBuilder builder;
    for (const std::filesystem::path& file : aimlFiles)
        builder.addFile(file);
    return std::move(builder).build();
}

} // namespace thespis::core::dialogue
