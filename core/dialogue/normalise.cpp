#include "dialogue/normalise.h"

#include <algorithm>
#include <limits>

#include "util/text.h"

namespace thespis::core::dialogue {
namespace {

char lowerAscii(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// The length of the UTF-8 character starting with byte `lead` (1 for a stray continuation byte).
std::size_t utf8Length(unsigned char lead)
{
    return lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

} // namespace

Substitutions::Substitutions(const Pairs& pairs)
{
    for (const auto& [from, to] : pairs) {
        if (from.empty())
            continue;
        const auto index = std::uint32_t(m_rules.size());
        if (from[0] == ' ' && from.size() > 1)
            m_bySecondAfterSpace[static_cast<unsigned char>(lowerAscii(from[1]))].push_back(index);
        else
            m_byFirstByte[static_cast<unsigned char>(lowerAscii(from[0]))].push_back(index);
        m_rules.emplace_back(lowercase(from), to);
    }
}

std::string Substitutions::apply(std::string_view text) const
{
    // Rules such as " you " need a space on each side, so the text gets one at each end.
    std::string padded;
    padded.reserve(text.size() + 2);
    padded += ' ';
    padded += text;
    padded += ' ';
    std::string out;
    out.reserve(padded.size() + 16);
    for (std::size_t at = 0; at < padded.size();) {
        const auto matchesHere = [&](std::uint32_t index) {
            const std::string& from = m_rules[index].first;
            if (from.size() > padded.size() - at)
                return false;
            for (std::size_t i = 0; i < from.size(); ++i)
                if (lowerAscii(padded[at + i]) != from[i])
                    return false;
            return true;
        };
        // The first rule in file order of the two lists that apply here (each is in file order).
        std::uint32_t rule = std::numeric_limits<std::uint32_t>::max();
        for (std::uint32_t index : m_byFirstByte[static_cast<unsigned char>(lowerAscii(padded[at]))])
            if (matchesHere(index)) {
                rule = index;
                break;
            }
        if (padded[at] == ' ' && at + 1 < padded.size())
            for (std::uint32_t index : m_bySecondAfterSpace[static_cast<unsigned char>(lowerAscii(padded[at + 1]))]) {
                if (index > rule)
                    break;
                if (matchesHere(index)) {
                    rule = index;
                    break;
                }
            }
        if (rule == std::numeric_limits<std::uint32_t>::max()) {
            out += padded[at++];
            continue;
        }
        const auto& [from, to] = m_rules[rule];
        // A rule's closing space may open the next word's rule (" i am " → " i " then " am ").
        // (Not for a rule that is only a space: the text would never move on.)
        const bool shareSpace = from.size() > 1 && from.back() == ' ' && !to.empty() && to.back() == ' ';
        out.append(to, 0, shareSpace ? to.size() - 1 : to.size());
        at += shareSpace ? from.size() - 1 : from.size();
    }
    return collapseSpaces(out);
}

std::vector<std::string> splitSentences(std::string_view text, std::string_view splitters)
{
    if (splitters.empty())
        splitters = ".!?";
    std::vector<std::string> sentences;
    std::size_t start = 0;
    const auto close = [&](std::size_t end) {
        std::string sentence = collapseSpaces(text.substr(start, end - start));
        if (!sentence.empty())
            sentences.push_back(std::move(sentence));
    };
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = std::min(utf8Length(static_cast<unsigned char>(text[at])), text.size() - at);
        const std::string_view character = text.substr(at, length);
        at += length;
        if (splitters.find(character) != std::string_view::npos) {
            close(at - length);
            start = at;
        }
    }
    close(text.size());
    return sentences;
}

std::string matchForm(std::string_view text, bool upper)
{
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        const bool keep = byte >= 0x80 || (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (keep)
            out += upper && c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
        else if (!out.empty() && out.back() != ' ')
            out += ' ';
    }
    if (!out.empty() && out.back() == ' ')
        out.pop_back();
    return out;
}

std::vector<std::string_view> splitWords(std::string_view text)
{
    std::vector<std::string_view> words;
    while (!text.empty()) {
        const std::size_t space = std::min(text.find(' '), text.size());
        if (space > 0)
            words.push_back(text.substr(0, space));
        text.remove_prefix(std::min(space + 1, text.size()));
    }
    return words;
}

std::vector<std::string> wordsOf(std::string_view text)
{
    std::vector<std::string> words;
    for (const std::string_view word : splitWords(text))
        words.emplace_back(word);
    return words;
}

std::string collapseSpaces(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (char c : trimmed(text)) {
        if (!isSpace(c))
            out += c;
        else if (out.back() != ' ')
            out += ' ';
    }
    return out;
}

} // namespace thespis::core::dialogue
