#include "scenario/package_bakes.h"

#include <optional>

#include "scenario/scenario_character.h"

namespace thespis::core::scenario {

namespace {

struct Needed {
    std::size_t character;
    scene::CharacterMesh mesh;
    lighting::BakeSettings settings;
    std::string reason;
};

/// Why a character's bake must be made again, or nothing when it still fits; `settings` takes
/// the old bake's settings when it can be read.
std::optional<std::string> staleness(const Character& character, const scene::CharacterMesh& mesh, const Assets& assets,
                                     lighting::BakeSettings& settings)
{
    if (character.bake.empty())
        return "it had none";
    auto bake = lighting::readBakeFile(assets.path(character.bake));
    if (!bake)
        return "its bake " + character.bake + " cannot be read: " + bake.error().message;
    settings.order = bake->order;
    settings.raysPerVertex = bake->raysPerVertex;
    settings.transfer = bake->transferKind;
    settings.epsilon = bake->epsilon;
    settings.seed = bake->seed;
    if (auto fits = lighting::checkBakeMatchesMesh(*bake, mesh); !fits)
        return "its bake " + character.bake + " no longer fits: " + fits.error().message;
    return std::nullopt;
}

} // namespace

Result<std::vector<PackageBake>> makePackageBakes(const Scenario& scenario, const Assets& assets,
                                                  const lighting::BakeSettings& settings, JobContext& context,
                                                  const char* stage)
{
    if (auto valid = lighting::validateBakeSettings(settings); !valid)
        return valid.error();
    std::vector<Needed> needed;
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < scenario.characters.size(); ++i) {
        auto body = loadCharacterBody(scenario, i, assets);
        if (!body)
            return body.error();
        lighting::BakeSettings own = settings;
        if (auto reason = staleness(scenario.characters[i], body->mesh, assets, own)) {
            total += body->mesh.positions.size();
            needed.push_back({i, std::move(body->mesh), own, std::move(*reason)});
        }
    }
    context.beginStage(stage, total);
    std::vector<PackageBake> bakes;
    std::uint64_t before = 0;
    for (Needed& need : needed) {
        const auto progress = [&](const lighting::BakeProgress& p) { context.setDone(before + p.verticesDone); };
        auto bake = lighting::bakeTransfer(need.mesh, need.settings, context.stopToken(), progress);
        if (!bake)
            return bake.error();
        const Character& character = scenario.characters[need.character];
        auto bytes = lighting::bakeFileBytes(*bake, character.name + ".prt");
        if (!bytes)
            return bytes.error();
        bakes.push_back({need.character, std::move(bytes).value(), std::move(need.reason)});
        before += need.mesh.positions.size();
    }
    return bakes;
}

} // namespace thespis::core::scenario
