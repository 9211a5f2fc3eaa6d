#include "scene/fap.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <string>

namespace thespis::core::scene {

namespace {

using enum FapUnit;

// ISO/IEC 14496-2 Table C-1 (FAP names, units, directions and feature points).
constexpr std::array<FapInfo, kFapCount> kFaps{{
    {1, "viseme", None, false, "", ""},
    {2, "expression", None, false, "", ""},
    {3, "open_jaw", MNS, false, "down", "2.1"},
    {4, "lower_t_midlip", MNS, true, "down", "2.2"},
    {5, "raise_b_midlip", MNS, true, "up", "2.3"},
    {6, "stretch_l_cornerlip", MW, true, "left", "2.4"},
    {7, "stretch_r_cornerlip", MW, true, "right", "2.5"},
    {8, "lower_t_lip_lm", MNS, true, "down", "2.6"},
    {9, "lower_t_lip_rm", MNS, true, "down", "2.7"},
    {10, "raise_b_lip_lm", MNS, true, "up", "2.8"},
    {11, "raise_b_lip_rm", MNS, true, "up", "2.9"},
    {12, "raise_l_cornerlip", MNS, true, "up", "2.4"},
    {13, "raise_r_cornerlip", MNS, true, "up", "2.5"},
    {14, "thrust_jaw", MNS, false, "forward", "2.1"},
    {15, "shift_jaw", MW, true, "right", "2.1"},
    {16, "push_b_lip", MNS, true, "forward", "2.3"},
    {17, "push_t_lip", MNS, true, "forward", "2.2"},
    {18, "depress_chin", MNS, true, "up", "2.10"},
    {19, "close_t_l_eyelid", IRISD, true, "down", "3.1"},
    {20, "close_t_r_eyelid", IRISD, true, "down", "3.2"},
    {21, "close_b_l_eyelid", IRISD, true, "up", "3.3"},
    {22, "close_b_r_eyelid", IRISD, true, "up", "3.4"},
    {23, "yaw_l_eyeball", AU, true, "left", ""},
    {24, "yaw_r_eyeball", AU, true, "left", ""},
    {25, "pitch_l_eyeball", AU, true, "down", ""},
    {26, "pitch_r_eyeball", AU, true, "down", ""},
    {27, "thrust_l_eyeball", ES, true, "forward", ""},
    {28, "thrust_r_eyeball", ES, true, "forward", ""},
    {29, "dilate_l_pupil", IRISD, true, "growing", "3.5"},
    {30, "dilate_r_pupil", IRISD, true, "growing", "3.6"},
    {31, "raise_l_i_eyebrow", ENS, true, "up", "4.1"},
    {32, "raise_r_i_eyebrow", ENS, true, "up", "4.2"},
    {33, "raise_l_m_eyebrow", ENS, true, "up", "4.3"},
    {34, "raise_r_m_eyebrow", ENS, true, "up", "4.4"},
    {35, "raise_l_o_eyebrow", ENS, true, "up", "4.5"},
    {36, "raise_r_o_eyebrow", ENS, true, "up", "4.6"},
    {37, "squeeze_l_eyebrow", ES, true, "right", "4.1"},
    {38, "squeeze_r_eyebrow", ES, true, "left", "4.2"},
    {39, "puff_l_cheek", ES, true, "left", "5.1"},
    {40, "puff_r_cheek", ES, true, "right", "5.2"},
    {41, "lift_l_cheek", ENS, false, "up", "5.3"},
    {42, "lift_r_cheek", ENS, false, "up", "5.4"},
    {43, "shift_tongue_tip", MW, true, "right", "6.1"},
    {44, "raise_tongue_tip", MNS, true, "up", "6.1"},
    {45, "thrust_tongue_tip", MW, true, "forward", "6.1"},
    {46, "raise_tongue", MNS, true, "up", "6.2"},
    {47, "tongue_roll", AU, false, "concave upward", "6.3"},
    {48, "head_pitch", AU, true, "down", ""},
    {49, "head_yaw", AU, true, "left", ""},
    {50, "head_roll", AU, true, "right", ""},
    {51, "lower_t_midlip_o", MNS, true, "down", "8.1"},
    {52, "raise_b_midlip_o", MNS, true, "up", "8.2"},
    {53, "stretch_l_cornerlip_o", MW, true, "left", "8.3"},
    {54, "stretch_r_cornerlip_o", MW, true, "right", "8.4"},
    {55, "lower_t_lip_lm_o", MNS, true, "down", "8.5"},
    {56, "lower_t_lip_rm_o", MNS, true, "down", "8.6"},
    {57, "raise_b_lip_lm_o", MNS, true, "up", "8.7"},
    {58, "raise_b_lip_rm_o", MNS, true, "up", "8.8"},
    {59, "raise_l_cornerlip_o", MNS, true, "up", "8.3"},
    {60, "raise_r_cornerlip_o", MNS, true, "up", "8.4"},
    {61, "stretch_l_nose", ENS, true, "left", "9.1"},
    {62, "stretch_r_nose", ENS, true, "right", "9.2"},
    {63, "raise_nose", ENS, true, "up", "9.3"},
    {64, "bend_nose", ENS, true, "right", "9.3"},
    {65, "raise_l_ear", ENS, true, "up", "10.1"},
    {66, "raise_r_ear", ENS, true, "up", "10.2"},
    {67, "pull_l_ear", ENS, true, "left", "10.3"},
    {68, "pull_r_ear", ENS, true, "right", "10.4"},
}};

constexpr std::array<std::string_view, kVisemeCount> kVisemes{"p_b_m", "f_v",  "T_D", "t_d", "k_g", "tS_dZ_S", "s_z",
                                                              "n_l",   "r",    "A:",  "e",   "I",   "Q",       "U"};
constexpr std::array<std::string_view, kExpressionCount> kExpressions{"joy",  "sadness", "anger",
                                                                      "fear", "disgust", "surprise"};

// The number after `prefix` in `name` ("fap12" → 12), or nullopt.
std::optional<int> numberAfter(std::string_view name, std::string_view prefix)
{
    if (!name.starts_with(prefix))
        return std::nullopt;
    int number = 0;
    const char* begin = name.data() + prefix.size();
    const char* end = name.data() + name.size();
    const auto [last, error] = std::from_chars(begin, end, number);
    if (error != std::errc() || last != end || begin == end)
        return std::nullopt;
    return number;
}

} // namespace

std::string_view fapUnitName(FapUnit unit)
{
    constexpr std::string_view names[] = {"", "IRISD", "ES", "ENS", "MNS", "MW", "AU"};
    return names[std::size_t(unit)];
}

double FapUnits::of(FapUnit unit) const
{
    switch (unit) {
    case FapUnit::IRISD:
        return irisd;
    case FapUnit::ES:
        return es;
    case FapUnit::ENS:
        return ens;
    case FapUnit::MNS:
        return mns;
    case FapUnit::MW:
        return mw;
    case FapUnit::AU:
        return au;
    case FapUnit::None:
        break;
    }
    return 0;
}

const FapInfo& fapInfo(int number)
{
    assert(number >= 1 && number <= kFapCount);
    return kFaps[std::size_t(number - 1)];
}

std::optional<int> findFap(std::string_view name)
{
    if (const std::optional<int> number = numberAfter(name, "fap"); number && *number >= 1 && *number <= kFapCount)
        return number;
    for (const FapInfo& fap : kFaps)
        if (fap.name == name)
            return fap.number;
    return std::nullopt;
}

std::string_view visemeName(int number)
{
    assert(number >= 1 && number <= kVisemeCount);
    return kVisemes[std::size_t(number - 1)];
}

std::string_view expressionName(int number)
{
    assert(number >= 1 && number <= kExpressionCount);
    return kExpressions[std::size_t(number - 1)];
}

std::optional<int> findExpression(std::string_view name)
{
    const auto it = std::find(kExpressions.begin(), kExpressions.end(), name);
    if (it != kExpressions.end())
        return int(it - kExpressions.begin()) + 1;
    return std::nullopt;
}

std::optional<int> findFaceChannel(std::string_view name)
{
    if (const std::optional<int> fap = findFap(name))
        return fapChannel(*fap);
    if (const std::optional<int> viseme = numberAfter(name, "viseme"); viseme && *viseme >= 1 && *viseme <= kVisemeCount)
        return visemeChannel(*viseme);
    if (const std::optional<int> e = numberAfter(name, "expression"); e && *e >= 1 && *e <= kExpressionCount)
        return expressionChannel(*e);
    if (const std::optional<int> e = findExpression(name))
        return expressionChannel(*e);
    return std::nullopt;
}

} // namespace thespis::core::scene
