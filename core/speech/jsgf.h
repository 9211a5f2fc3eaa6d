#pragma once
// JSGF V1.0 (Java Speech Grammar Format) read into a rule tree, for pocketsphinx's grammars: the
// ones the dialogue generates and the ones people write. The reader checks what pocketsphinx
// would stumble on later (a missing header or grammar name, duplicate rules and imports, rules
// referred to but nowhere defined, weights on some alternatives only) and names the line and
// column of each problem. Imports are resolved from the grammar's folder ("<polite.*>" reads
// polite.gram). A grammar set says whether a word sequence is a sentence of the grammar.
//
// Read: header "#JSGF V1.0 [charset [locale]];", "grammar name;", "import <g.rule>;" or
// "import <g.*>;", "[public] <rule> = expansion;", alternatives "|" with optional weights
// "/2.5/", sequences, "[ ]" optional, "( )" groups, one "*" or "+" after an item, "<NULL>",
// "<VOID>", tags "{…}" (kept, never matched), quoted tokens, "//" and "/* */" comments.

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

/// One node of a rule's expansion.
struct JsgfExpansion {
    enum class Kind {
        Token,        ///< a word (`text`)
        RuleRef,      ///< a rule (`text`: "name" or "grammar.name")
        Null,         ///< <NULL>: matches nothing spoken
        Void,         ///< <VOID>: matches nothing at all
        Sequence,     ///< `children` one after another
        Alternatives, ///< one of `children` (weights in `weights` when given)
        Optional,     ///< [child]
        ZeroOrMore,   ///< child*
        OneOrMore,    ///< child+
    };
    Kind kind = Kind::Sequence;
    std::string text;
    std::vector<JsgfExpansion> children;
    std::vector<double> weights;   ///< Alternatives: one per child, or none
    std::vector<std::string> tags; ///< "{…}" after this item, without the braces
    int line = 0, column = 0;      ///< where it starts (1-based)
};

struct JsgfRule {
    std::string name; ///< without the angle brackets
    bool isPublic = false;
    JsgfExpansion expansion;
    int line = 0, column = 0;
};

struct JsgfImport {
    std::string grammar; ///< "polite"
    std::string rule;    ///< "startPolite", or "*" for all its public rules
    int line = 0, column = 0;
};

struct JsgfGrammar {
    std::string version = "V1.0";
    std::string charset, locale; ///< from the header; empty when not given
    std::string name;
    std::vector<JsgfImport> imports;
    std::vector<JsgfRule> rules; ///< in the file's order

    const JsgfRule* findRule(std::string_view name) const;
    /// The public rules, in order; pocketsphinx listens for the first.
    std::vector<const JsgfRule*> publicRules() const;
};

/// Reads JSGF text. Errors: NotOurFormat without a "#JSGF" header; CorruptData naming the line
/// and column of a syntax error, a duplicate rule or import, a reference to a rule neither
/// defined nor imported, weights on only some alternatives, text that is not UTF-8.
Result<JsgfGrammar> parseJsgf(std::string_view text);

/// A grammar with the grammars it imports, transitively; grammars[0] is the one read.
struct JsgfSet {
    std::vector<JsgfGrammar> grammars;

    /// The rule `reference` names as `from` sees it (local, imported, or "grammar.rule");
    /// nullptr when there is none.
    const JsgfRule* resolve(const JsgfGrammar& from, std::string_view reference) const;
    /// The grammar a rule belongs to.
    const JsgfGrammar& grammarOf(const JsgfRule& rule) const;
    /// Whether `words` is a sentence of one of the first grammar's public rules (or of the rule
    /// named `rule`, when given). Tags are ignored; tokens compare exactly.
    bool accepts(std::span<const std::string> words, std::string_view rule = {}) const;
    /// Every distinct token the grammars use, sorted.
    std::vector<std::string> tokens() const;
};

/// Text of an imported grammar by its name; an error when it cannot be had.
using JsgfLoader = std::function<Result<std::string>(const std::string& grammarName)>;

/// `grammar` with its imports read through `load` and checked: each imported grammar exists,
/// has the rule imported and that rule is public. Errors name the import's line and column.
Result<JsgfSet> resolveJsgf(JsgfGrammar grammar, const JsgfLoader& load);
/// Reads a .gram file and its imports from the same folder ("<polite.x>" → polite.gram).
/// Errors name the file.
Result<JsgfSet> readJsgfFile(const std::filesystem::path& path);

} // namespace thespis::core::speech
