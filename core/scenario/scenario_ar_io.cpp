// The scenario's AR section as JSON: where the world sits on the tracked target and the phantom
// occluders (scenario.h's ArSpec). Written only when it differs from the defaults.
#include "scenario/scenario_json.h"
#include "scenario/scenario_object_reader.h"

namespace thespis::core::scenario::detail {

namespace {

constexpr NamedValue<PhantomOccluder::Shape> kOccluderShapes[] = {
    {PhantomOccluder::Shape::Box, "box"},
    {PhantomOccluder::Shape::Plane, "plane"},
    {PhantomOccluder::Shape::Model, "model"},
};

template <std::size_t N>
std::array<double, N> readNumbers(ObjectReader& r, std::string_view key, std::array<double, N> fallback, Range range)
{
    const json* value = r.find(key);
    if (!value)
        return fallback;
    const std::string path = r.fieldPath(key);
    if (!value->is_array() || value->size() != N)
        fail(path, "expected " + std::to_string(N) + " numbers, found " + describeValue(*value));
    std::array<double, N> numbers;
    for (std::size_t i = 0; i < N; ++i)
        numbers[i] = ObjectReader::checkedNumber((*value)[i], indexed(path, i), range);
    return numbers;
}

PhantomOccluder readOccluder(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "PhantomOccluder.1");
    PhantomOccluder occluder;
    occluder.name = r.string("name", false);
    occluder.shape = r.enumeration("shape", kOccluderShapes, true, PhantomOccluder::Shape::Box);
    occluder.position = readNumbers<3>(r, "position", occluder.position, Range::Any);
    occluder.size = readNumbers<3>(r, "size", occluder.size, Range::Positive);
    occluder.heading = r.number("heading", false, 0, Range::Any);
    occluder.model = r.string("model", occluder.shape == PhantomOccluder::Shape::Model);
    occluder.extra = r.extra();
    return occluder;
}

ojson numbers(const auto& values)
{
    ojson out = ojson::array();
    for (double v : values)
        out.push_back(v);
    return out;
}

} // namespace

ArSpec readArSpec(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Ar.1");
    ArSpec ar;
    ar.offset = readNumbers<2>(r, "offset", ar.offset, Range::Any);
    ar.heading = r.number("heading", false, 0, Range::Any);
    ar.scale = r.number("scale", false, 1, Range::Positive);
    ar.shadowCatcher = r.boolean("shadowCatcher", true);
    const json& occluders = r.array("occluders", false);
    for (std::size_t i = 0; i < occluders.size(); ++i)
        ar.occluders.push_back(readOccluder(occluders[i], indexed(r.fieldPath("occluders"), i)));
    ar.extra = r.extra();
    return ar;
}

ojson writeArSpec(const ArSpec& ar)
{
    ojson out = ojson::object();
    out["schema"] = "Ar.1";
    if (ar.offset != std::array<double, 2>{})
        out["offset"] = numbers(ar.offset);
    if (ar.heading != 0)
        out["heading"] = ar.heading;
    if (ar.scale != 1)
        out["scale"] = ar.scale;
    if (!ar.shadowCatcher)
        out["shadowCatcher"] = false;
    if (!ar.occluders.empty()) {
        ojson occluders = ojson::array();
        for (const PhantomOccluder& occluder : ar.occluders) {
            ojson entry = ojson::object();
            entry["schema"] = "PhantomOccluder.1";
            if (!occluder.name.empty())
                entry["name"] = occluder.name;
            entry["shape"] = nameOf(kOccluderShapes, occluder.shape);
            entry["position"] = numbers(occluder.position);
            entry["size"] = numbers(occluder.size);
            if (occluder.heading != 0)
                entry["heading"] = occluder.heading;
            if (!occluder.model.empty())
                entry["model"] = occluder.model;
            appendExtra(entry, occluder.extra);
            occluders.push_back(std::move(entry));
        }
        out["occluders"] = std::move(occluders);
    }
    appendExtra(out, ar.extra);
    return out;
}

} // namespace thespis::core::scenario::detail
