#include "render/scenario_scene.h"

#include <cmath>

#include "lighting/probe.h"
#include "lighting/probe_preview.h"
#include "lighting/probe_projection_job.h"
#include "render/shaders.h"
#include "scenario/scenario_character.h"

namespace thespis::core::render {

namespace {

// The bake file a character names (an asset name), when it can be read and still fits its
// body; otherwise the reason, one sentence.
Result<std::shared_ptr<const lighting::TransferBake>> readCharacterBake(const std::string& file,
                                                                       const scene::CharacterMesh& body,
                                                                       const scenario::Assets& assets)
{
    auto bake = lighting::readBakeFile(assets.path(file));
    if (!bake)
        return bake.error();
    if (bake->order < 1 || bake->order > shaders::kMaxTransferOrder)
        return makeError(ErrorCode::InvalidArgument, "Its order " + std::to_string(bake->order) +
                                                         " is above what the viewport draws (" +
                                                         std::to_string(shaders::kMaxTransferOrder) + ").");
    if (auto matches = lighting::checkBakeMatchesMesh(*bake, body); !matches)
        return matches.error();
    return std::make_shared<const lighting::TransferBake>(std::move(bake).value());
}

std::string lowerFirst(std::string sentence)
{
    if (!sentence.empty() && sentence[0] >= 'A' && sentence[0] <= 'Z')
        sentence[0] = char(sentence[0] - 'A' + 'a');
    return sentence;
}

} // namespace

Result<std::unique_ptr<ScenarioScene>> ScenarioScene::create(const scenario::Scenario& scenario,
                                                             const scenario::Assets& assets,
                                                             const ScenarioSceneOptions& options)
{
    std::unique_ptr<ScenarioScene> self(new ScenarioScene);
    if (options.stage) {
        if (options.stage->runtime().characters.size() != scenario.characters.size())
            return makeError(ErrorCode::InvalidArgument, "The stage does not play this scenario's characters.");
        self->m_stage = options.stage;
    } else {
        auto runtime = scenario::buildRuntime(scenario, assets);
        if (!runtime)
            return runtime.error();
        self->m_stage = std::make_shared<runtime::Stage>(std::move(runtime).value());
    }
    self->m_scene = std::make_unique<RenderScene>(options.skinningThreads);

    self->m_lighting = scenario.lighting;
    self->m_probeBackground = options.probeBackground;
    auto projection = probeProjectionFor(scenario, assets, options.lightOrder);
    if (!projection)
        return projection.error();
    if (*projection && options.projectProbe) {
        JobContext context;
        if (auto projected = (*projection)->run(context); !projected)
            return makeError(projected.error().code, "lighting.probe: " + projected.error().message,
                             projected.error().detail);
        self->setProbeLight(*(*projection)->probe, (*projection)->light);
    }

    for (std::size_t i = 0; i < scenario.characters.size(); ++i) {
        auto body = scenario::loadCharacterBody(scenario, i, assets);
        if (!body)
            return body.error();
        const scenario::CharacterRuntime* characterRuntime = self->runtime().findCharacter(scenario.characters[i].name);
        if (!characterRuntime)
            return makeError(ErrorCode::Internal, "The runtime lost character \"" + scenario.characters[i].name + "\".");
        for (const std::string& warning : body->warnings)
            self->m_warnings.push_back(scenario.characters[i].name + ": " + warning);
        // The caller's bake first; else the file the scenario names, when it still fits the body
        // (a missing or stale one leaves the character unshadowed, and the user is told).
        std::shared_ptr<const lighting::TransferBake> bake;
        const scenario::Character& spec = scenario.characters[i];
        if (const auto given = options.bakes.find(spec.name); given != options.bakes.end()) {
            bake = given->second;
        } else if (!spec.bake.empty()) {
            auto read = readCharacterBake(spec.bake, body->mesh, assets);
            if (read)
                bake = std::move(read).value();
            else
                self->m_warnings.push_back(spec.name + ": its bake \"" + spec.bake +
                                           "\" is left out, so it is lit unshadowed (DU): " +
                                           lowerFirst(read.error().message));
        }
        auto shared = std::make_shared<const scene::Character>(std::move(body).value());
        auto node = self->m_scene->addCharacter(shared, bake.get(), options.skinning);
        if (!node)
            return makeError(node.error().code, scenario.characters[i].name + ": " + node.error().message,
                             node.error().detail);
        Performer performer;
        performer.name = scenario.characters[i].name;
        performer.runtime = characterRuntime;
        performer.skeletonLayout = characterRuntime->skeleton.frameLayout();
        performer.node = *node;
        performer.retarget = scenario::retargetOntoBody(characterRuntime->skeleton, *shared);
        if (performer.retarget.mappedJointCount() < std::min(characterRuntime->skeleton.jointCount(), 4))
            self->m_warnings.push_back(scenario.characters[i].name + ": its body shares only " +
                                       std::to_string(performer.retarget.mappedJointCount()) +
                                       " joint names with its animation skeleton, so it will hardly move.");
        performer.bodyFrame = shared->skeleton.restFrame();
        performer.bodyLayout = shared->skeleton.frameLayout();
        self->m_performers.push_back(std::move(performer));
    }
    self->attachPerformers();
    self->setTime(0.0);
    return self;
}

void ScenarioScene::attachPerformers()
{
    m_poses = m_stage->makePoseSet();
    m_performerPose.clear();
    for (Performer& performer : m_performers) {
        performer.runtime = runtime().findCharacter(performer.name);
        m_performerPose.push_back(int(performer.runtime - runtime().characters.data()));
    }
}

Result<void> ScenarioScene::setRuntime(scenario::ScenarioRuntime runtime)
{
    if (auto fits = fitsPerformers(runtime); !fits)
        return fits;
    if (auto played = m_stage->setRuntime(std::move(runtime)); !played)
        return played.error();
    attachPerformers();
    setTime(m_time);
    return {};
}

// The performers may point into a runtime the stage no longer has: they are compared by the
// names and skeleton layouts they recorded.
Result<void> ScenarioScene::fitsPerformers(const scenario::ScenarioRuntime& next) const
{
    if (next.characters.size() != m_performers.size())
        return makeError(ErrorCode::InvalidArgument, "The scenario's characters changed: the scene must be rebuilt.");
    for (std::size_t i = 0; i < m_performers.size(); ++i)
        if (next.characters[i].name != m_performers[i].name
            || !(*next.characters[i].skeleton.frameLayout() == *m_performers[i].skeletonLayout))
            return makeError(ErrorCode::InvalidArgument,
                             "Character \"" + next.characters[i].name + "\" changed its skeleton: the scene must be rebuilt.");
    return {};
}

Result<std::optional<lighting::ProbeProjectionJob>> probeProjectionFor(const scenario::Scenario& scenario,
                                                                        const scenario::Assets& assets,
                                                                        int lightOrder)
{
    if (scenario.lighting.probe.empty())
        return std::optional<lighting::ProbeProjectionJob>();
    auto layout = lighting::parseProbeLayout(scenario.lighting.layout);
    if (!layout)
        return makeError(layout.error().code, "lighting.layout: " + layout.error().message);
    lighting::ProbeProjectionJob projection;
    projection.path = assets.path(scenario.lighting.probe);
    projection.layout = *layout;
    projection.order = lightOrder;
    return std::optional<lighting::ProbeProjectionJob>(std::move(projection));
}

void ScenarioScene::setProbeLight(const lighting::LightProbe& probe, const lighting::ShRgb& light)
{
    const scenario::LightingSpec& spec = m_lighting;
    m_scene->setLight(lighting::turnedLight(light, spec.rotation, spec.intensity));
    if (m_probeBackground)
        m_scene->setBackgroundProbe(probe, 512, spec.rotation, spec.intensity);
}

void ScenarioScene::setTime(double seconds)
{
    m_stage->evaluate(secondsToTicks(seconds), m_poses);
    setPoses(m_poses);
    m_time = seconds;
}

void ScenarioScene::setPoses(const runtime::PoseSet& poses)
{
    m_time = ticksToSeconds(poses.time);
    for (std::size_t i = 0; i < m_performers.size(); ++i) {
        Performer& performer = m_performers[i];
        const std::vector<float>& frame = poses.characters[std::size_t(m_performerPose[i])].body;
        // Placed after retargeting: a body of another size must not scale where it stands.
        performer.retarget.apply(frame, performer.bodyFrame);
        performer.runtime->place(*performer.bodyLayout, performer.bodyFrame);
        performer.node->setPose(performer.bodyFrame);
    }
}

Bounds ScenarioScene::boundsOverTimeline()
{
    const double now = m_time;
    Bounds bounds;
    const int samples = std::max(1, int(std::ceil(duration() * 10.0)));
    for (int i = 0; i <= samples; ++i) {
        setTime(duration() * i / samples);
        bounds.add(m_scene->characterBounds());
    }
    setTime(now);
    return bounds;
}

} // namespace thespis::core::render
