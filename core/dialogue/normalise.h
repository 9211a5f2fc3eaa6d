#pragma once
// Turning what a visitor typed into what patterns match: the bot's substitutions (normal,
// person, ...), sentence splitting, and the match form (upper case, punctuation removed).

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dialogue/bot_files.h"

namespace thespis::core::dialogue {

/// One of the bot's substitution lists. Applied in one pass from left to right: at each place the
/// first rule of the file that matches (ignoring ASCII case) is replaced, and the text after the
/// replacement is not looked at again, so " I " → " you " and " you " → " I " swap cleanly.
class Substitutions {
public:
    Substitutions() = default;
    explicit Substitutions(const Pairs& pairs);

    /// `text` with the rules applied; runs of spaces made one and the ends trimmed.
    std::string apply(std::string_view text) const;
    std::size_t size() const { return m_rules.size(); }
    const Pairs& rules() const { return m_rules; }

private:
    Pairs m_rules; // `from` in lower case
    // Rule indices by the first byte of `from`; most rules start with a space (" you "), so those
    // are found by their second byte instead.
    std::array<std::vector<std::uint32_t>, 256> m_byFirstByte, m_bySecondAfterSpace;
};

/// The sentences of `text`, split after each character of `splitters` (UTF-8; ".!?" when empty),
/// trimmed, empty ones dropped.
std::vector<std::string> splitSentences(std::string_view text, std::string_view splitters);

/// Text as patterns match it: ASCII letters in upper case, ASCII punctuation made a space (other
/// UTF-8 kept), one space between words. With `upper` false the letters keep their case: the same
/// words, as stars show them.
std::string matchForm(std::string_view text, bool upper = true);

/// The words of a text whose words are separated by single spaces (matchForm's result).
std::vector<std::string_view> splitWords(std::string_view text);
/// The same words as strings of their own.
std::vector<std::string> wordsOf(std::string_view text);

/// Runs of white space made one space, ends trimmed.
std::string collapseSpaces(std::string_view text);

} // namespace thespis::core::dialogue
