#pragma once
// ObjectReader: reads one JSON object of a versioned document (util/json_document.h) field by
// field — typed fields by name, each read marking the name as known, so that the remaining
// members can be kept as `extra` or refused — and names the path of anything wrong by throwing
// FieldError. The scenario's reader and the face mapping tables' build on it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "util/json_document.h"

namespace thespis::core::json_document {

enum class Range { Any, NonNegative, Positive, UnitInterval };

class ObjectReader {
public:
    ObjectReader(const json& value, std::string path, std::string_view schema)
        : m_value(value), m_path(std::move(path))
    {
        if (!value.is_object())
            fail(m_path, "expected an object, found " + describeValue(value));
        if (!schema.empty()) {
            // "schema" names the object's type and version (OpenTimelineIO style); files written
            // by hand may leave it out, but a wrong one means this is not the object we expect.
            if (const json* s = find("schema")) {
                if (!s->is_string() || s->get_ref<const std::string&>() != schema)
                    fail(join(m_path, "schema"), "expected " + quote(schema) + ", found " + describeValue(*s));
            }
        }
    }

    const std::string& path() const { return m_path; }
    std::string fieldPath(std::string_view key) const { return join(m_path, key); }

    const json* find(std::string_view key)
    {
        m_known.emplace_back(key);
        const auto it = m_value.find(key);
        return it == m_value.end() ? nullptr : &*it;
    }

    const json& require(std::string_view key)
    {
        const json* value = find(key);
        if (!value)
            fail(fieldPath(key), "this field is required but missing");
        return *value;
    }

    std::string string(std::string_view key, bool required, std::string fallback = {})
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (!value->is_string())
            fail(fieldPath(key), "expected a text, found " + describeValue(*value));
        return value->get<std::string>();
    }

    std::string name(std::string_view key = "name")
    {
        std::string text = string(key, true);
        if (text.empty())
            fail(fieldPath(key), "must not be empty");
        return text;
    }

    bool boolean(std::string_view key, bool fallback)
    {
        const json* value = find(key);
        if (!value)
            return fallback;
        if (!value->is_boolean())
            fail(fieldPath(key), "expected true or false, found " + describeValue(*value));
        return value->get<bool>();
    }

    double number(std::string_view key, bool required, double fallback, Range range)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        return checkedNumber(*value, fieldPath(key), range);
    }

    float floatNumber(std::string_view key, bool required, float fallback, Range range)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        return checkedFloat(*value, fieldPath(key), range);
    }

    std::int64_t integer(std::string_view key, bool required, std::int64_t fallback, std::int64_t min,
                         std::int64_t max)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (!value->is_number_integer())
            fail(fieldPath(key), "expected a whole number, found " + describeValue(*value));
        const bool tooLarge = value->is_number_unsigned() && value->get<std::uint64_t>() > std::uint64_t(max);
        const auto n = tooLarge ? max : value->get<std::int64_t>();
        if (tooLarge || n < min || n > max)
            fail(fieldPath(key), "must be between " + std::to_string(min) + " and " + std::to_string(max)
                                     + ", found " + value->dump());
        return n;
    }

    /// The list under `key` (empty when absent).
    const json& array(std::string_view key, bool required)
    {
        static const json empty = json::array();
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return empty;
        if (!value->is_array())
            fail(fieldPath(key), "expected a list, found " + describeValue(*value));
        return *value;
    }

    std::vector<std::string> names(std::string_view key)
    {
        std::vector<std::string> result;
        std::set<std::string> seen;
        const json& list = array(key, false);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = indexed(fieldPath(key), i);
            if (!list[i].is_string())
                fail(at, "expected a text, found " + describeValue(list[i]));
            const auto& text = list[i].get_ref<const std::string&>();
            if (text.empty())
                fail(at, "must not be empty");
            if (!seen.insert(text).second)
                fail(at, quote(text) + " is listed twice");
            result.push_back(text);
        }
        return result;
    }

    /// Members this reader has not asked for: kept so that they are written back unchanged.
    json extra() const
    {
        json result = json::object();
        for (const auto& [key, value] : m_value.items())
            if (std::find(m_known.begin(), m_known.end(), key) == m_known.end())
                result[key] = value;
        return result;
    }

    /// Fails naming the first member this reader has not asked for: for formats that refuse
    /// unknown fields, so that a misspelt one is not silently ignored. `what` names the object
    /// ("a face mapping").
    void refuseUnknown(std::string_view what) const
    {
        for (const auto& [key, value] : m_value.items())
            if (std::find(m_known.begin(), m_known.end(), key) == m_known.end())
                fail(fieldPath(key), "is not a field of " + std::string(what) + " here");
    }

    static double checkedNumber(const json& value, const std::string& path, Range range)
    {
        if (!value.is_number())
            fail(path, "expected a number, found " + describeValue(value));
        const double d = value.get<double>();
        if (!std::isfinite(d))
            fail(path, "expected a finite number, found " + value.dump());
        checkRange(d, path, range);
        return d;
    }

    static float checkedFloat(const json& value, const std::string& path, Range range)
    {
        const double d = checkedNumber(value, path, range);
        // Doubles below FLT_MAX + half its ulp still round to FLT_MAX (3.4028235e38 is written
        // for it); from there on the conversion would overflow.
        constexpr double kFloatLimit = double(std::numeric_limits<float>::max()) + 0x1p103;
        if (std::abs(d) >= kFloatLimit)
            fail(path, "the number " + value.dump() + " is too large");
        return float(d);
    }

private:
    static void checkRange(double d, const std::string& path, Range range)
    {
        switch (range) {
        case Range::Any: break;
        case Range::NonNegative:
            if (d < 0)
                fail(path, "must not be negative, found " + json(d).dump());
            break;
        case Range::Positive:
            if (!(d > 0))
                fail(path, "must be greater than 0, found " + json(d).dump());
            break;
        case Range::UnitInterval:
            if (d < 0 || d > 1)
                fail(path, "must be between 0 and 1, found " + json(d).dump());
            break;
        }
    }

    const json& m_value;
    std::string m_path;
    std::vector<std::string> m_known;
};

} // namespace thespis::core::json_document
