#pragma once
// A small command-line parser for thespis-cli subcommands: positional arguments, long options
// with a value ("--fps 30" or "--fps=30"), flags, and --help. Each subcommand describes its
// arguments once; usage text and error messages come from that description.

#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace thespis::cli {

struct OptionSpec {
    std::string name;      ///< without the leading "--"
    std::string valueName; ///< empty: a flag without a value
    std::string help;
    bool required = false;
    bool repeats = false;  ///< may be given more than once (ParsedArguments::all())
};

struct CommandSpec {
    std::string name;                    ///< e.g. "bake-motion"
    std::string summary;                 ///< one line for the command list
    std::vector<std::string> positionals;///< names shown in usage, all required (e.g. "SCENARIO")
    bool repeatsLast = false;            ///< the last positional takes one or more values ("CLIP...")
    bool lastOptional = false;           ///< the last positional may be left out ("[SCENARIO]")
    std::vector<OptionSpec> options;
    std::string description;             ///< paragraphs shown by --help after the usage line
};

class ParsedArguments {
public:
    std::vector<std::string> positionals;
    std::map<std::string, std::string> values;   ///< the first value of each option
    std::multimap<std::string, std::string> repeated; ///< every value of the options that repeat
    std::set<std::string> flags;
    bool help = false;

    bool has(const std::string& option) const { return values.count(option) || flags.count(option); }
    std::optional<std::string> value(const std::string& option) const;
    /// Every value of an option that repeats, in the order given.
    std::vector<std::string> all(const std::string& option) const;
};

struct ParseOutcome {
    ParsedArguments arguments;
    std::string error; ///< empty on success; else what is wrong, for the user
};

/// Parses `args` (the words after the subcommand name) against `spec`. --help anywhere wins
/// over every other rule, so that "cmd --help" always works.
ParseOutcome parseArguments(const CommandSpec& spec, std::span<const std::string_view> args);

/// "Usage: thespis-cli NAME ARGS [options]" followed by the options table and description.
std::string helpText(const CommandSpec& spec);
/// The one usage line.
std::string usageLine(const CommandSpec& spec);

/// A motion file on the command line: "FILE[@FPS][+SKIP]" — the file, the frame rate that
/// replaces its header's (CMU's index gives 60 fps for takes whose headers say 120) and the seconds
/// left out at its start. Nullopt when the rate or the skip is not a number (rate > 0, skip ≥ 0).
struct ClipArgument {
    std::string file;
    double frameRate = 0;          ///< 0: as the file says
    std::optional<double> skip;
};
std::optional<ClipArgument> parseClipArgument(std::string_view text);

/// Parses a finite number; nullopt when `text` is not one entirely.
std::optional<double> parseNumber(std::string_view text);

} // namespace thespis::cli
