#pragma once
// The phoneme set speech works in: ARPAbet as CMUdict and pocketsphinx's en-us model use it
// (39 phonemes, upper case, stress digits dropped) plus "SIL" for a pause, and the conversion
// from espeak-ng's English phoneme mnemonics ("tS", "aI", "@L") to it.

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace thespis::core::speech {

/// The 39 ARPAbet phonemes, in CMUdict's order (AA AE AH … ZH).
std::span<const std::string_view> arpabetPhonemes();
/// True for one of the 39 or "SIL".
bool isPhoneme(std::string_view phoneme);
/// "AH0" → "AH", "ah" → "AH": upper case, stress digit dropped. The result may still not be a
/// phoneme (check with isPhoneme).
std::string normalizedPhoneme(std::string_view text);

/// The ARPAbet phonemes an espeak-ng English phoneme mnemonic stands for: usually one ("tS" →
/// CH), two for a syllabic consonant or an r-coloured vowel ("@L" → AH L, "e@" → EH R), "SIL" for
/// a pause ("_", "_:"), none for a modifier (";", stress marks). An unknown mnemonic is matched
/// by its longest known prefix ("i@3" → IY ER); none at all gives an empty list.
std::vector<std::string> arpabetFromEspeak(std::string_view mnemonic);

} // namespace thespis::core::speech
