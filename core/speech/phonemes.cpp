#include "speech/phonemes.h"

#include <algorithm>
#include <array>

namespace thespis::core::speech {
namespace {

constexpr std::array<std::string_view, 39> kArpabet = {
    "AA", "AE", "AH", "AO", "AW", "AY", "B",  "CH", "D",  "DH", "EH", "ER", "EY",
    "F",  "G",  "HH", "IH", "IY", "JH", "K",  "L",  "M",  "N",  "NG", "OW", "OY",
    "P",  "R",  "S",  "SH", "T",  "TH", "UH", "UW", "V",  "W",  "Y",  "Z",  "ZH"};

struct EspeakPhoneme {
    std::string_view mnemonic;
    std::string_view arpabet; // space-separated; empty: a modifier
};

// espeak-ng 1.51's English phonemes (phsource/ph_english*), as the en and en-us voices report
// them in phoneme events.
constexpr EspeakPhoneme kEspeak[] = {
    // pauses
    {"_", "SIL"}, {"_:", "SIL"}, {"_!", "SIL"}, {"_^_", "SIL"}, {"_|", "SIL"}, {"||", "SIL"},
    // modifiers and stress
    {";", ""}, {"'", ""}, {",", ""}, {"%", ""}, {"=", ""}, {"#", ""},
    // vowels
    {"@", "AH"}, {"@2", "AH"}, {"@5", "AH"}, {"@L", "AH L"}, {"@r", "ER"}, {"3", "ER"}, {"3:", "ER"},
    {"a", "AE"}, {"a#", "AH"}, {"aa", "AA"}, {"a2", "AH"}, {"A:", "AA"}, {"A@", "AA R"}, {"A#", "AA"},
    {"aI", "AY"}, {"aI@", "AY ER"}, {"aI3", "AY ER"}, {"aU", "AW"}, {"aU@", "AW ER"},
    {"E", "EH"}, {"E2", "EH"}, {"e@", "EH R"}, {"eI", "EY"},
    {"i", "IY"}, {"i:", "IY"}, {"I", "IH"}, {"I2", "IH"}, {"I#", "IH"}, {"i@", "IY ER"}, {"i@3", "IY ER"},
    {"0", "AA"}, {"0#", "AA"}, {"O", "AO"}, {"O:", "AO"}, {"O@", "AO R"}, {"o@", "AO R"}, {"OI", "OY"},
    {"oU", "OW"}, {"oU#", "OW"}, {"U", "UH"}, {"U@", "UH R"}, {"u:", "UW"}, {"u", "UW"}, {"V", "AH"},
    // consonants
    {"p", "P"}, {"b", "B"}, {"t", "T"}, {"t#", "T"}, {"t2", "T"}, {"d", "D"}, {"d#", "D"}, {"k", "K"},
    {"g", "G"}, {"?", "T"}, {"f", "F"}, {"v", "V"}, {"T", "TH"}, {"D", "DH"}, {"s", "S"}, {"z", "Z"},
    {"S", "SH"}, {"Z", "ZH"}, {"tS", "CH"}, {"dZ", "JH"}, {"h", "HH"}, {"x", "HH"}, {"m", "M"},
    {"m-", "M"}, {"n", "N"}, {"n-", "N"}, {"N", "NG"}, {"l", "L"}, {"l/", "L"}, {"r", "R"}, {"r-", "R"},
    {"w", "W"}, {"W", "W"}, {"j", "Y"}, {"C", "HH"},
};

std::vector<std::string> split(std::string_view arpabet)
{
    std::vector<std::string> out;
    while (!arpabet.empty()) {
        const std::size_t space = arpabet.find(' ');
        out.emplace_back(arpabet.substr(0, space));
        arpabet = space == std::string_view::npos ? std::string_view{} : arpabet.substr(space + 1);
    }
    return out;
}

const EspeakPhoneme* findEspeak(std::string_view mnemonic)
{
    for (const EspeakPhoneme& p : kEspeak)
        if (p.mnemonic == mnemonic)
            return &p;
    return nullptr;
}

} // namespace

std::span<const std::string_view> arpabetPhonemes()
{
    return kArpabet;
}

bool isPhoneme(std::string_view phoneme)
{
    return phoneme == "SIL" || std::find(kArpabet.begin(), kArpabet.end(), phoneme) != kArpabet.end();
}

std::string normalizedPhoneme(std::string_view text)
{
    std::string out;
    for (char c : text) {
        if (c >= '0' && c <= '9')
            continue;
        out += c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
    }
    return out;
}

std::vector<std::string> arpabetFromEspeak(std::string_view mnemonic)
{
    for (std::size_t length = mnemonic.size(); length > 0; --length)
        if (const EspeakPhoneme* known = findEspeak(mnemonic.substr(0, length)))
            return split(known->arpabet);
    return {};
}

} // namespace thespis::core::speech
