#pragma once
// Private to the scenario readers (scenario_read.cpp, scenario_ar_io.cpp, package_manifest.cpp):
// ObjectReader reads one JSON object field by field, naming the path of anything wrong — the
// document reader's (util/json_object_reader.h) with the scenario's ticks and enumerations.

#include <limits>
#include <string>

#include "scenario/scenario_json.h"
#include "util/json_object_reader.h"

namespace thespis::core::scenario::detail {

using json_document::Range;

class ObjectReader : public json_document::ObjectReader {
public:
    using json_document::ObjectReader::ObjectReader;

    Tick ticks(std::string_view key, bool required)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return 0;
        if (!value->is_number_integer() || (value->is_number_unsigned()
                                            && value->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<Tick>::max())))
            fail(fieldPath(key), "expected an integer number of ticks (" + std::to_string(TicksPerSecond)
                                     + " per second), found " + describeValue(*value));
        const Tick n = value->get<Tick>();
        if (n < 0)
            fail(fieldPath(key), "must not be negative, found " + std::to_string(n) + " ticks");
        return n;
    }

    template <class E, std::size_t N>
    E enumeration(std::string_view key, const NamedValue<E> (&table)[N], bool required, E fallback)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (value->is_string())
            for (const auto& entry : table)
                if (entry.name == value->get_ref<const std::string&>())
                    return entry.value;
        fail(fieldPath(key), "expected " + namesOf(table) + ", found " + describeValue(*value));
    }
};

} // namespace thespis::core::scenario::detail
