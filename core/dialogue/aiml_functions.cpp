#include "dialogue/aiml_functions.h"

#include <charconv>
#include <cstring>

#include "util/text.h"

namespace thespis::core::dialogue {

std::string strftimeFromJava(std::string_view java)
{
    std::string out;
    for (std::size_t at = 0; at < java.size();) {
        const char c = java[at];
        std::size_t run = 1;
        while (at + run < java.size() && java[at + run] == c)
            ++run;
        at += run;
        switch (c) {
        case 'y': out += run == 2 ? "%y" : "%Y"; break;
        case 'M': out += run >= 4 ? "%B" : run == 3 ? "%b" : "%m"; break;
        case 'd': out += "%d"; break;
        case 'E': out += run >= 4 ? "%A" : "%a"; break;
        case 'h': out += "%I"; break;
        case 'H': out += "%H"; break;
        case 'm': out += "%M"; break;
        case 's': out += "%S"; break;
        case 'a': out += "%p"; break;
        case 'z': out += "%Z"; break;
        case '%': out += "%%"; break;
        default: out.append(run, c);
        }
    }
    return out;
}

std::string formatDate(std::string_view format, std::time_t now)
{
    std::tm local{};
    localtime_r(&now, &local);
    const std::string pattern = format.empty() ? "%B %d, %Y" : std::string(format);
    char buffer[256];
    const std::size_t written = std::strftime(buffer, sizeof buffer, pattern.c_str(), &local);
    return std::string(buffer, written);
}

std::optional<long long> dateInterval(std::string_view from, std::string_view to, std::string_view format, std::string_view style)
{
    const std::string pattern = format.empty() ? "%B %d, %Y" : std::string(format);
    const auto read = [&](std::string_view text) -> std::optional<std::tm> {
        std::tm time{};
        time.tm_mday = 1;
        time.tm_year = 100; // a format without a year reads both dates in the same year
        const std::string value(trimmed(text));
        const char* end = strptime(value.c_str(), pattern.c_str(), &time);
        if (!end)
            return std::nullopt;
        time.tm_isdst = -1;
        return time;
    };
    std::optional<std::tm> a = read(from), b = read(to);
    if (!a || !b)
        return std::nullopt;
    if (style == "years" || style == "months") {
        long long months = (b->tm_year - a->tm_year) * 12LL + (b->tm_mon - a->tm_mon);
        if (b->tm_mday < a->tm_mday)
            --months;
        return style == "years" ? months / 12 : months;
    }
    const double seconds = std::difftime(timegm(&*b), timegm(&*a));
    const double unit = style == "minutes" ? 60 : style == "hours" ? 3600 : style == "seconds" ? 1 : 86400;
    return static_cast<long long>(seconds / unit);
}

std::optional<std::string> builtInMap(std::string_view name, std::string_view key)
{
    if (name == "successor" || name == "predecessor") {
        long long number = 0;
        const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), number);
        if (error != std::errc() || end != key.data() + key.size() || number < -1'000'000'000'000LL || number > 1'000'000'000'000LL)
            return std::nullopt;
        return std::to_string(name == "successor" ? number + 1 : number - 1);
    }
    const std::string word = lowercase(key);
    if (word.empty())
        return std::nullopt;
    const auto endsWith = [&](std::string_view tail) { return word.size() > tail.size() && word.ends_with(tail); };
    if (name == "plural") {
        if (endsWith("y") && std::string_view("aeiou").find(word[word.size() - 2]) == std::string_view::npos)
            return word.substr(0, word.size() - 1) + "ies";
        if (endsWith("s") || endsWith("x") || endsWith("z") || endsWith("ch") || endsWith("sh"))
            return word + "es";
        return word + "s";
    }
    if (name == "singular") {
        if (endsWith("ies"))
            return word.substr(0, word.size() - 3) + "y";
        if (endsWith("ches") || endsWith("shes") || endsWith("xes") || endsWith("sses"))
            return word.substr(0, word.size() - 2);
        if (endsWith("s") && !endsWith("ss"))
            return word.substr(0, word.size() - 1);
        return word;
    }
    return std::nullopt;
}

std::string formal(std::string_view text)
{
    std::string out(text);
    bool wordStart = true;
    for (char& c : out) {
        if (c == ' ') {
            wordStart = true;
            continue;
        }
        if (wordStart && c >= 'a' && c <= 'z')
            c = char(c - 'a' + 'A');
        else if (!wordStart && c >= 'A' && c <= 'Z')
            c = char(c - 'A' + 'a');
        wordStart = false;
    }
    return out;
}

std::string sentenceCase(std::string_view text)
{
    std::string out(text);
    for (char& c : out) {
        if (c == ' ')
            continue;
        if (c >= 'a' && c <= 'z')
            c = char(c - 'a' + 'A');
        break;
    }
    return out;
}

} // namespace thespis::core::dialogue
