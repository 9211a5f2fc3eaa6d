#pragma once
// The parts of AIML templates that compute rather than look up: dates, intervals between dates,
// the maps Pandorabots builds in (successor, predecessor, plural, singular) and text casing.

#include <ctime>
#include <optional>
#include <string>
#include <string_view>

namespace thespis::core::dialogue {

/// A Java SimpleDateFormat pattern ("MMMM dd, yyyy", AIML's jformat) as a strftime one.
std::string strftimeFromJava(std::string_view java);

/// `now` in local time formatted by `format` (strftime); "%B %d, %Y" when empty.
std::string formatDate(std::string_view format, std::time_t now);

/// Whole `style` units ("years", "months", "days", "hours", "minutes", "seconds") from `from` to
/// `to`, both read with strftime `format`; nullopt when either cannot be read.
std::optional<long long> dateInterval(std::string_view from, std::string_view to, std::string_view format, std::string_view style);

/// The built-in maps: nullopt when `name` is not one or `key` is not in it.
std::optional<std::string> builtInMap(std::string_view name, std::string_view key);

/// Each word's first letter in upper case, the rest in lower case (<formal>).
std::string formal(std::string_view text);
/// The first letter in upper case (<sentence>).
std::string sentenceCase(std::string_view text);

} // namespace thespis::core::dialogue
