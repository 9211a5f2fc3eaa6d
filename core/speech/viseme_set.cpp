#include "speech/viseme_set.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "speech/phonemes.h"
#include "util/file_io.h"
#include "util/json_object_reader.h"
#include "util/text.h"

namespace thespis::core::speech {
namespace {

using json_document::fail;
using json_document::indexed;
using json_document::json;
using json_document::ObjectReader;
using json_document::Range;

// How each kind of mouth shape blends (α, weight, spread). Lip closures and lip–teeth contacts
// must be reached, so they are at full weight and reach little past their phoneme; shapes made
// with the tongue behind the teeth show less and borrow more from their neighbours; vowels open
// the mouth and carry into the consonants around them.
// The last argument is the MPEG-4 viseme the shape shows as on the face.
const Viseme kSilence{0, "sil", 4, 1, 0.5, 0};
Viseme lips(int id, std::string name, int mpeg4) { return {id, std::move(name), 3, 1, 0.3, mpeg4}; }
Viseme tongue(int id, std::string name, int mpeg4) { return {id, std::move(name), 5, 0.8, 0.5, mpeg4}; }
Viseme vowel(int id, std::string name, int mpeg4) { return {id, std::move(name), 4, 1, 0.6, mpeg4}; }

using PhonemeTable = std::initializer_list<std::pair<std::string_view, std::vector<int>>>;

VisemeSet makeSet(std::string name, std::vector<Viseme> visemes, PhonemeTable table)
{
    VisemeSet set{std::move(name), std::move(visemes), {}};
    for (const auto& [phoneme, ids] : table)
        set.phonemes.emplace(std::string(phoneme), ids);
    return set;
}

// MPEG-4 and Oculus group the phonemes alike (Oculus is MPEG-4's 14 plus silence).
constexpr std::pair<std::string_view, int> kMpeg4Groups[] = {
    {"P", 1},  {"B", 1},  {"M", 1},   {"F", 2},   {"V", 2},   {"TH", 3},  {"DH", 3},  {"T", 4},
    {"D", 4},  {"K", 5},  {"G", 5},   {"NG", 5},  {"HH", 5},  {"CH", 6},  {"JH", 6},  {"SH", 6},
    {"ZH", 6}, {"S", 7},  {"Z", 7},   {"N", 8},   {"L", 8},   {"R", 9},   {"ER", 9},  {"AA", 10},
    {"AH", 10}, {"AE", 10}, {"AY", 10}, {"AW", 10}, {"EH", 11}, {"EY", 11}, {"IH", 12}, {"IY", 12},
    {"Y", 12}, {"AO", 13}, {"OW", 13}, {"OY", 13}, {"UH", 14}, {"UW", 14}, {"W", 14}};

VisemeSet groupedSet(std::string name, const std::vector<std::string>& names)
{
    std::vector<Viseme> visemes{kSilence};
    for (int id = 1; id <= 14; ++id) {
        const std::string& n = names[std::size_t(id - 1)];
        visemes.push_back(id <= 2 ? lips(id, n, id) : id <= 9 ? tongue(id, n, id) : vowel(id, n, id));
    }
    VisemeSet set{std::move(name), std::move(visemes), {}};
    for (const auto& [phoneme, id] : kMpeg4Groups)
        set.phonemes.emplace(std::string(phoneme), std::vector<int>{id});
    return set;
}

} // namespace

const Viseme* VisemeSet::find(int id) const
{
    const auto it = std::find_if(visemes.begin(), visemes.end(), [&](const Viseme& v) { return v.id == id; });
    return it == visemes.end() ? nullptr : &*it;
}

std::vector<int> VisemeSet::visemesOf(std::string_view phoneme) const
{
    const auto it = phonemes.find(normalizedPhoneme(phoneme));
    if (it == phonemes.end() || it->second.empty())
        return {0};
    return it->second;
}

Result<void> VisemeSet::validate() const
{
    auto invalid = [](const std::string& field, const std::string& message) {
        return makeError(ErrorCode::InvalidArgument, field + ": " + message + ".");
    };
    std::set<int> ids;
    for (std::size_t i = 0; i < visemes.size(); ++i) {
        const Viseme& v = visemes[i];
        const std::string at =
            "visemes[" + std::to_string(i) + "]" + (v.name.empty() ? std::string() : " (" + v.name + ")");
        if (v.id < 0 || v.id > 99)
            return invalid(at + ".id", "must be 0 … 99");
        if (!ids.insert(v.id).second)
            return invalid(at + ".id", "the id " + std::to_string(v.id) + " is used twice");
        if (v.name.empty())
            return invalid(at + ".name", "must not be empty");
        if (!(v.alpha > 0) || !std::isfinite(v.alpha))
            return invalid(at + ".alpha", "must be greater than 0");
        if (!(v.weight >= 0 && v.weight <= 1))
            return invalid(at + ".weight", "must be 0 … 1");
        if (!(v.spread >= 0 && v.spread <= 2))
            return invalid(at + ".spread", "must be 0 … 2");
        if (v.mpeg4 < 0 || v.mpeg4 > 14)
            return invalid(at + ".mpeg4", "must be an MPEG-4 viseme, 1 … 14, or 0 for the mouth at rest");
    }
    for (const auto& [phoneme, list] : phonemes) {
        if (!isPhoneme(phoneme))
            return invalid("phonemes." + phoneme, "not an ARPAbet phoneme");
        for (int id : list)
            if (!ids.count(id))
                return invalid("phonemes." + phoneme, "there is no viseme " + std::to_string(id));
    }
    return {};
}

const VisemeSet& mpeg4Visemes()
{
    static const VisemeSet set = groupedSet(
        "mpeg4", {"p_b_m", "f_v", "T_D", "t_d", "k_g", "tS_dZ_S", "s_z", "n_l", "r", "A:", "e", "I", "Q", "U"});
    return set;
}

const VisemeSet& oculusVisemes()
{
    static const VisemeSet set =
        groupedSet("oculus", {"PP", "FF", "TH", "DD", "kk", "CH", "SS", "nn", "RR", "aa", "E", "ih", "oh", "ou"});
    return set;
}

const VisemeSet& sapiVisemes()
{
    // Microsoft's numbering, as its speech service documents it for en-US.
    static const VisemeSet set = makeSet(
        "sapi",
        // Each shown as the MPEG-4 viseme of the phonemes it stands for (its first, for a diphthong).
        {kSilence, vowel(1, "ae_ax_ah", 10), vowel(2, "aa", 10), vowel(3, "ao", 13), vowel(4, "ey_eh_uh", 11),
         vowel(5, "er", 9), vowel(6, "y_iy_ih_ix", 12), vowel(7, "w_uw", 14), vowel(8, "ow", 13), vowel(9, "aw", 10),
         vowel(10, "oy", 13), vowel(11, "ay", 10), tongue(12, "h", 5), tongue(13, "r", 9), tongue(14, "l", 8),
         tongue(15, "s_z", 7), tongue(16, "sh_ch_jh_zh", 6), tongue(17, "th_dh", 3), lips(18, "f_v", 2),
         tongue(19, "d_t_n", 4), tongue(20, "k_g_ng", 5), lips(21, "p_b_m", 1)},
        {{"IY", {6}},  {"IH", {6}},  {"EY", {4, 6}}, {"EH", {4}},      {"AE", {1}},  {"AA", {2}},  {"AO", {3}},
         {"UH", {4}},  {"OW", {8, 4}}, {"UW", {7}},  {"AH", {1}},      {"AY", {11}}, {"AW", {9}},  {"OY", {10}},
         {"ER", {5}},  {"W", {7}},   {"Y", {6}},     {"P", {21}},      {"B", {21}},  {"T", {19}},  {"D", {19}},
         {"K", {20}},  {"G", {20}},  {"M", {21}},    {"N", {19}},      {"NG", {20}}, {"F", {18}},  {"V", {18}},
         {"TH", {19}}, {"DH", {17}}, {"S", {15}},    {"Z", {15}},      {"SH", {16}}, {"ZH", {16}}, {"HH", {12}},
         {"CH", {19, 16}}, {"JH", {19, 16}}, {"L", {14}}, {"R", {13}}});
    return set;
}

const VisemeSet* builtInVisemeSet(std::string_view name)
{
    for (const VisemeSet* set : {&mpeg4Visemes(), &oculusVisemes(), &sapiVisemes()})
        if (set->name == name)
            return set;
    return nullptr;
}

int mpeg4Viseme(std::string_view phoneme)
{
    return mpeg4Visemes().visemesOf(phoneme).front();
}

std::string serializeVisemeSet(const VisemeSet& set)
{
    nlohmann::ordered_json document;
    document["format"] = kVisemeSetFormat;
    document["version"] = kVisemeSetVersion;
    document["name"] = set.name;
    document["visemes"] = nlohmann::ordered_json::array();
    for (const Viseme& v : set.visemes)
        document["visemes"].push_back(
            {{"id", v.id}, {"name", v.name}, {"alpha", v.alpha}, {"weight", v.weight}, {"spread", v.spread}, {"mpeg4", v.mpeg4}});
    document["phonemes"] = nlohmann::ordered_json::object();
    for (const auto& [phoneme, ids] : set.phonemes)
        document["phonemes"][phoneme] = ids;
    return document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

namespace {

Result<VisemeSet> readDocument(std::string_view text, const std::string& what)
{
    static constexpr json_document::Kind kKind{"viseme set", kVisemeSetFormat, 1, kVisemeSetVersion};
    Result<json_document::Versioned> parsed = json_document::parseVersioned(text, kKind);
    if (!parsed) {
        const Error& error = parsed.error();
        return makeError(error.code, what + (error.code == ErrorCode::CorruptData ? " is not valid: " : ": ")
                                         + error.message, error.detail);
    }
    try {
        ObjectReader reader(parsed->document, "", {});
        (void)reader.find("format");
        (void)reader.find("version");
        VisemeSet set;
        set.name = reader.string("name", false);
        const VisemeSet* builtIn = builtInVisemeSet(set.name);
        const json& visemes = reader.array("visemes", true);
        for (std::size_t i = 0; i < visemes.size(); ++i) {
            ObjectReader v(visemes[i], indexed("visemes", i), {});
            Viseme viseme;
            viseme.id = int(v.integer("id", true, 0, 0, 99));
            viseme.name = v.name();
            viseme.alpha = v.number("alpha", false, viseme.alpha, Range::Positive);
            viseme.weight = v.number("weight", false, viseme.weight, Range::UnitInterval);
            viseme.spread = v.number("spread", false, viseme.spread, Range::NonNegative);
            if (viseme.spread > 2)
                fail(v.fieldPath("spread"), "must be 0 … 2");
            if (parsed->version >= 2) {
                viseme.mpeg4 = int(v.integer("mpeg4", true, 0, 0, 14));
            } else if (const Viseme* same = builtIn ? builtIn->find(viseme.id) : nullptr) {
                viseme.mpeg4 = same->mpeg4;
            } else {
                viseme.mpeg4 = viseme.id <= 14 ? viseme.id : 0;
            }
            if (set.find(viseme.id))
                fail(v.fieldPath("id"), "the id " + std::to_string(viseme.id) + " is used twice");
            v.refuseUnknown("a viseme");
            set.visemes.push_back(std::move(viseme));
        }
        const json* phonemes = reader.find("phonemes");
        if (!phonemes || !phonemes->is_object())
            fail("phonemes", "expected an object of ARPAbet phonemes and their viseme ids");
        for (const auto& [phoneme, ids] : phonemes->items()) {
            const std::string path = json_document::join("phonemes", phoneme);
            if (!isPhoneme(phoneme))
                fail(path, "not an ARPAbet phoneme (AA … ZH, SIL)");
            if (!ids.is_array())
                fail(path, "expected a list of viseme ids, found " + json_document::describeValue(ids));
            std::vector<int> list;
            for (std::size_t i = 0; i < ids.size(); ++i) {
                if (!ids[i].is_number_integer() || !set.find(ids[i].get<int>()))
                    fail(indexed(path, i), "expected the id of one of the set's visemes, found "
                                               + json_document::describeValue(ids[i]));
                list.push_back(ids[i].get<int>());
            }
            set.phonemes.emplace(phoneme, std::move(list));
        }
        reader.refuseUnknown("a viseme set");
        return set;
    } catch (const json_document::FieldError& e) {
        return makeError(ErrorCode::CorruptData,
                         what + " is not valid: " + (e.path.empty() ? "" : e.path + ": ") + e.message + ".");
    }
}

} // namespace

Result<VisemeSet> parseVisemeSet(std::string_view text)
{
    return readDocument(text, "The viseme set");
}

Result<VisemeSet> loadVisemeSet(const std::filesystem::path& path)
{
    Result<std::string> text = readTextFile(path);
    if (!text)
        return text.error();
    return readDocument(*text, "The viseme set " + path.string());
}

Result<void> saveVisemeSet(const std::filesystem::path& path, const VisemeSet& set)
{
    return writeFileAtomically(path, serializeVisemeSet(set));
}

} // namespace thespis::core::speech
