#pragma once
// The public vocabulary of core/dialogue, the AIML dialogue manager of the paper's §5.3 ("a
// dialogue manager that responds to the user according to a predefined script that follows a
// similar approach as Alice"): categories as the script wrote them, load problems, answers.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace thespis::core::dialogue {

/// Where something was written: the file as given to the loader and its 1-based line.
struct SourcePlace {
    std::string file;
    int line = 0;
};

/// One AIML category as written. `pattern`, `that` and `topic` are space-separated tokens: words
/// in upper case, the wildcards `*` `_` `#` `^`, priority words `$WORD`, and the pattern-side
/// elements `<set>name</set>` and `<bot name="x"/>` spelled that way (see patternTokens()).
/// `that` and `topic` are "*" when the category does not give them.
struct Category {
    std::string pattern;
    std::string that = "*";
    std::string topic = "*";
    SourcePlace source;
    std::uint32_t templateIndex = 0; ///< into the owner's parsed templates (internal)
};

/// A pattern string of a Category split into its tokens ("<bot name=\"name\"/>" stays one token).
std::vector<std::string_view> patternTokens(std::string_view pattern);

/// Something wrong in a bot's files: loading goes on with the rest and reports these.
struct LoadProblem {
    std::string file;
    int line = 0;   ///< 0 when the problem is not at a line (a file that cannot be read)
    int column = 0; ///< 0 when unknown
    std::string message;
};

/// "file:line:column: message" (the parts that are known), for logs and the studio's problem list.
std::string describe(const LoadProblem& problem);

/// The category that answered one sentence of an input, for the studio's transcript.
struct MatchedCategory {
    std::string sentence; ///< the normalised sentence that was matched
    std::string pattern, that, topic;
    SourcePlace source;
    bool learned = false; ///< learned in this conversation (<learn>) rather than from the bot
};

/// What the bot says to one input.
struct Answer {
    std::string text;                      ///< empty when nothing matched; keeps speech markup as XML
    std::vector<MatchedCategory> matched;  ///< one per answered sentence, in order
    std::string problem; ///< empty, or why the answer was cut short (a loop, too much work)
};

} // namespace thespis::core::dialogue
