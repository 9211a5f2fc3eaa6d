#pragma once
// Speech timing as a table for people and scripts (thespis-cli lipsync --out): tab-separated
// values, a header row, then one row per phoneme — start and end in seconds, the word (empty in
// a pause), the phoneme (ARPAbet, or SIL) and its MPEG-4 viseme number (0 in a pause).

#include <filesystem>
#include <string>

#include "speech/speech_timing.h"
#include "util/error.h"

namespace thespis::core::speech {

std::string timingTsv(const SpeechTiming& timing);
/// Writes timingTsv(timing) atomically. Errors name the file.
Result<void> writeTimingTsv(const std::filesystem::path& path, const SpeechTiming& timing);

} // namespace thespis::core::speech
