#include "render/scenario_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/probe.h"
#include "lighting/probe_preview.h"
#include "lighting/probe_projection_job.h"
#include "render/shaders.h"
#include "runtime/timeline_samples.h"
#include "scenario/scenario_character.h"
#include "util/text.h"

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

} // namespace

Result<std::unique_ptr<ScenarioScene>> ScenarioScene::create(const scenario::Scenario& scenario,
                                                             const scenario::Assets& assets,
                                                             const ScenarioSceneOptions& options)
{
    std::unique_ptr<ScenarioScene> self(new ScenarioScene);
    if (!options.stage) {
        auto runtime = scenario::buildRuntime(scenario, assets);
        if (!runtime)
            return runtime.error();
        self->m_stage = std::make_shared<runtime::Stage>(std::move(runtime).value());
    } else {
        self->m_stage = options.stage;
    }
    // A copy: the owner of a shared stage may give it a new runtime meanwhile, on its thread.
    const scenario::ScenarioRuntime played = self->m_stage->runtimeCopy();
    if (played.characters.size() != scenario.characters.size())
        return makeError(ErrorCode::InvalidArgument, "The stage does not play this scenario's characters.");
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
        const scenario::CharacterRuntime* characterRuntime = played.findCharacter(scenario.characters[i].name);
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
        performer.pose = std::size_t(characterRuntime - played.characters.data());
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
    self->m_poses = self->m_stage->makePoseSet();
    if (options.stage)
        self->setPoses(self->m_poses); // at rest where each stands, until the owner's poses come
    else
        self->playAt(0);
    return self;
}

Result<void> ScenarioScene::followStage()
{
    const scenario::ScenarioRuntime& next = m_stage->runtime();
    if (next.characters.size() != m_performers.size())
        return makeError(ErrorCode::InvalidArgument, "The scenario's characters changed: the scene must be rebuilt.");
    for (Performer& performer : m_performers) {
        const scenario::CharacterRuntime* character = next.findCharacter(performer.name);
        if (!character || !(*character->skeleton.frameLayout() == *performer.skeletonLayout))
            return makeError(ErrorCode::InvalidArgument, "Character \"" + performer.name +
                                                             "\" changed its skeleton: the scene must be rebuilt.");
        performer.pose = std::size_t(character - next.characters.data());
    }
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

void ScenarioScene::playAt(Tick t)
{
    m_stage->evaluate(t, m_poses);
    setPoses(m_poses);
}

void ScenarioScene::setPoses(const runtime::PoseSet& poses)
{
    if (&poses != &m_poses)
        runtime::copyPoses(poses, m_poses);
    for (Performer& performer : m_performers)
        if (performer.pose < poses.characters.size())
            pose(performer, poses.characters[performer.pose]);
}

void ScenarioScene::pose(Performer& performer, const runtime::CharacterPose& pose)
{
    // Placed after retargeting: a body of another size must not scale where it stands.
    performer.retarget.apply(pose.body, performer.bodyFrame);
    pose.placement.apply(*performer.bodyLayout, performer.bodyFrame);
    performer.node->setPose(performer.bodyFrame, pose.face);
}

Result<ScenarioScene::Head> ScenarioScene::head(std::string_view character) const
{
    std::string names;
    for (const Performer& performer : m_performers) {
        names += (names.empty() ? "" : ", ") + performer.name;
        if (performer.name != character)
            continue;
        const scene::Character& body = performer.node->character();
        const int skull = body.skeleton.find("skullbase");
        Head head;
        const std::span<const anim::Vec3> posed = performer.node->posedPositions();
        for (const scene::Segment& segment : body.mesh.segments)
            if (skull >= 0 && segment.joint == "skullbase")
                for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v)
                    head.bounds.add(anim::Vec3d{posed[v].x, posed[v].y, posed[v].z});
        if (head.bounds.empty())
            return makeError(ErrorCode::InvalidArgument, "Character \"" + std::string(character) +
                                                             "\" has no head to frame (no segment follows skullbase).");
        head.facing = anim::rotate(performer.node->jointRotation(skull), anim::Vec3d{0, 0, 1});
        return head;
    }
    return makeError(ErrorCode::InvalidArgument,
                     "There is no character \"" + std::string(character) + "\" (the scenario has: " + names + ").");
}

CameraView ScenarioScene::closeUpView(const Head& head, double azimuthDegrees, double elevationDegrees, double aspect,
                                      double fovYDegrees)
{
    constexpr double Degrees = 180 / std::numbers::pi;
    const double heading = std::atan2(head.facing.x, head.facing.z) * Degrees;
    const double pitch = std::asin(std::clamp(head.facing.y, -1.0, 1.0)) * Degrees;
    return frameBounds(head.bounds, heading + azimuthDegrees, std::max(-20.0, elevationDegrees + pitch), aspect,
                       fovYDegrees);
}

Bounds ScenarioScene::boundsOver(std::span<const runtime::PoseSet> samples)
{
    Bounds bounds;
    for (const runtime::PoseSet& sample : samples) {
        for (Performer& performer : m_performers)
            if (performer.pose < sample.characters.size())
                pose(performer, sample.characters[performer.pose]);
        bounds.add(m_scene->characterBounds());
    }
    setPoses(m_poses);
    return bounds;
}

Bounds ScenarioScene::boundsOverTimeline()
{
    const std::vector<runtime::PoseSet> samples = runtime::sampleTimeline(runtime());
    return boundsOver(samples);
}

} // namespace thespis::core::render
