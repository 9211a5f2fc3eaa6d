#include "arguments.h"

#include <charconv>
#include <cmath>

namespace thespis::cli {
namespace {

const OptionSpec* findOption(const CommandSpec& spec, std::string_view name)
{
    for (const OptionSpec& option : spec.options)
        if (option.name == name)
            return &option;
    return nullptr;
}

} // namespace

std::optional<std::string> ParsedArguments::value(const std::string& option) const
{
    const auto it = values.find(option);
    return it == values.end() ? std::nullopt : std::optional<std::string>(it->second);
}

std::vector<std::string> ParsedArguments::all(const std::string& option) const
{
    std::vector<std::string> found;
    const auto [first, last] = repeated.equal_range(option);
    for (auto it = first; it != last; ++it)
        found.push_back(it->second);
    return found;
}

ParseOutcome parseArguments(const CommandSpec& spec, std::span<const std::string_view> args)
{
    ParseOutcome outcome;
    ParsedArguments& parsed = outcome.arguments;
    for (std::string_view arg : args)
        if (arg == "--help" || arg == "-h") {
            parsed.help = true;
            return outcome;
        }

    bool optionsEnded = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (optionsEnded || arg.size() < 2 || arg.substr(0, 2) != "--") {
            if (!optionsEnded && arg.size() > 1 && arg[0] == '-' && arg != "-") {
                outcome.error = "unknown option '" + std::string(arg) + "'";
                return outcome;
            }
            parsed.positionals.emplace_back(arg);
            continue;
        }
        if (arg == "--") {
            optionsEnded = true;
            continue;
        }
        std::string_view name = arg.substr(2);
        std::optional<std::string_view> inlineValue;
        if (const auto eq = name.find('='); eq != std::string_view::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* option = findOption(spec, name);
        if (!option) {
            outcome.error = "unknown option '--" + std::string(name) + "'";
            return outcome;
        }
        if (option->valueName.empty()) {
            if (inlineValue) {
                outcome.error = "option '--" + option->name + "' takes no value";
                return outcome;
            }
            parsed.flags.insert(option->name);
            continue;
        }
        std::string value;
        if (inlineValue) {
            value = std::string(*inlineValue);
        } else if (i + 1 < args.size()) {
            value = std::string(args[++i]);
        } else {
            outcome.error = "option '--" + option->name + "' needs a value (" + option->valueName + ")";
            return outcome;
        }
        if (option->repeats)
            parsed.repeated.emplace(option->name, value);
        else if (parsed.values.count(option->name)) {
            outcome.error = "option '--" + option->name + "' is given twice";
            return outcome;
        }
        parsed.values.try_emplace(option->name, std::move(value));
    }

    if (parsed.positionals.size() + (spec.lastOptional ? 1 : 0) < spec.positionals.size()) {
        outcome.error = "missing " + spec.positionals[parsed.positionals.size()];
        return outcome;
    }
    if (parsed.positionals.size() > spec.positionals.size() && !spec.repeatsLast) {
        outcome.error = "unexpected argument '" + parsed.positionals[spec.positionals.size()] + "'";
        return outcome;
    }
    for (const OptionSpec& option : spec.options)
        if (option.required && !parsed.has(option.name)) {
            outcome.error = "missing --" + option.name + " " + option.valueName;
            return outcome;
        }
    return outcome;
}

std::string usageLine(const CommandSpec& spec)
{
    std::string line = "Usage: thespis-cli " + spec.name;
    for (std::size_t i = 0; i < spec.positionals.size(); ++i)
        line += spec.lastOptional && i + 1 == spec.positionals.size() ? " [" + spec.positionals[i] + "]"
                                                                       : " " + spec.positionals[i];
    if (spec.repeatsLast)
        line += "...";
    for (const OptionSpec& option : spec.options)
        if (option.required)
            line += " --" + option.name + (option.valueName.empty() ? "" : " " + option.valueName);
    bool optional = false;
    for (const OptionSpec& option : spec.options)
        optional = optional || !option.required;
    if (optional)
        line += " [options]";
    return line;
}

std::string helpText(const CommandSpec& spec)
{
    std::string text = usageLine(spec) + "\n\n" + spec.summary + "\n";
    if (!spec.description.empty())
        text += "\n" + spec.description + "\n";
    text += "\nOptions:\n";
    std::vector<std::pair<std::string, std::string>> rows;
    for (const OptionSpec& option : spec.options)
        rows.emplace_back("--" + option.name + (option.valueName.empty() ? "" : " " + option.valueName),
                          option.help + (option.required ? " (required)" : "") +
                              (option.repeats ? " (may be given more than once)" : ""));
    rows.emplace_back("-h, --help", "show this help and exit");
    std::size_t width = 0;
    for (const auto& row : rows)
        width = std::max(width, row.first.size());
    for (const auto& [left, right] : rows)
        text += "  " + left + std::string(width - left.size() + 2, ' ') + right + "\n";
    return text;
}

std::optional<ClipArgument> parseClipArgument(std::string_view text)
{
    ClipArgument clip;
    const std::size_t name = text.find_last_of("/\\") == std::string_view::npos ? 0 : text.find_last_of("/\\") + 1;
    if (const auto plus = text.find('+', name); plus != std::string_view::npos) {
        clip.skip = parseNumber(text.substr(plus + 1));
        if (!clip.skip || *clip.skip < 0)
            return std::nullopt;
        text = text.substr(0, plus);
    }
    if (const auto at = text.find('@', name); at != std::string_view::npos) {
        const auto rate = parseNumber(text.substr(at + 1));
        if (!rate || !(*rate > 0))
            return std::nullopt;
        clip.frameRate = *rate;
        text = text.substr(0, at);
    }
    clip.file = std::string(text);
    return clip;
}

std::optional<double> parseNumber(std::string_view text)
{
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

} // namespace thespis::cli
