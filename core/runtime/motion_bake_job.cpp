#include "runtime/motion_bake_job.h"

#include <cmath>
#include <thread>

#include "anim/bvh.h"
#include "anim/keyframe_clip.h"
#include "runtime/stage.h"
#include "scenario/scenario_character.h"
#include "scenario/scenario_runtime.h"
#include "scene/gltf_character_export.h"
#include "scene/gltf_motion_export.h"

namespace thespis::core::runtime {

using scenario::Character;
using scenario::CharacterRuntime;
using scenario::Scenario;

namespace {
// Refuse bakes whose frames would not fit comfortably in memory (1 GiB of floats).
constexpr double MaxBakeFloats = double(1u << 28);

std::string joinNames(const Scenario& scenario)
{
    std::string names;
    for (const Character& c : scenario.characters)
        names += (names.empty() ? "" : ", ") + c.name;
    return names.empty() ? std::string("none") : names;
}
} // namespace

std::string MotionBakeJob::title() const
{
    return "The motion bake into " + output.string();
}

Result<void> MotionBakeJob::validate() const
{
    if (!(fps > 0) || !std::isfinite(fps))
        return makeError(ErrorCode::InvalidArgument, "fps must be a positive number.");
    if (!(start >= 0))
        return makeError(ErrorCode::InvalidArgument, "start must not be negative.");
    if (end && !(*end >= start))
        return makeError(ErrorCode::InvalidArgument, "end (" + std::to_string(*end) + " s) is before start ("
                                                         + std::to_string(start) + " s).");
    if (output.extension() != ".bvh" && output.extension() != ".glb")
        return makeError(ErrorCode::InvalidArgument,
                         "The output must be a .bvh or .glb file, not '" + output.string() + "'.");
    const std::filesystem::path folder = output.parent_path().empty() ? "." : output.parent_path();
    if (std::error_code ec; !std::filesystem::is_directory(folder, ec))
        return makeError(ErrorCode::FileNotFound, "Cannot write " + output.string() + ": the folder " + folder.string()
                                                      + " does not exist.");
    if (!scenario.findCharacter(character))
        return makeError(ErrorCode::NotFound, "The scenario has no character named '" + character
                                                  + "' (its characters: " + joinNames(scenario) + ").");
    return {};
}

Result<void> MotionBakeJob::run(JobContext& context)
{
    frameCount = 0;
    context.beginStage(LoadingStage);
    auto runtime = scenario::buildRuntime(scenario, assets);
    if (!runtime)
        return runtime.error();
    const CharacterRuntime* body = runtime->findCharacter(character);
    if (!body || !body->body)
        return makeError(ErrorCode::NotFound, "Character '" + character + "' has no body animation to bake.");
    if (!end && runtime->duration <= 0)
        return makeError(ErrorCode::InvalidArgument,
                         "The scenario has no duration and no finite action; give the bake's end.");
    const double last = end.value_or(ticksToSeconds(runtime->duration));
    if (last < start)
        return makeError(ErrorCode::InvalidArgument, "The bake starts (" + std::to_string(start)
                                                         + " s) after the scenario ends (" + std::to_string(last) + " s).");

    // The frames are the Stage's, as the studio plays them: the idle motion under the authored
    // schedule, muted and soloed layers as they are. A stage of this character alone: the
    // others would be evaluated for nothing.
    scenario::ScenarioRuntime alone;
    alone.characters = {*body};
    alone.duration = runtime->duration;
    Stage stage(alone);
    PoseSet poses = stage.makePoseSet();
    const anim::FrameLayoutPtr& layout = body->body->layout();
    const std::size_t floats = layout->floatCount();
    const std::size_t faceFloats = body->face ? body->face->layout()->floatCount() : 0;
    // A small tolerance so that e.g. 8.4 s × 30 fps gives 253 frames despite rounding.
    const double intervals = std::floor((last - start) * fps + 1e-6);
    if ((intervals + 1) * double(floats) > MaxBakeFloats)
        return makeError(ErrorCode::InvalidArgument, "The bake would hold " + std::to_string(long(intervals + 1))
                                                         + " frames of " + std::to_string(floats)
                                                         + " values; lower the frame rate or bake a shorter range.");
    const long count = long(intervals) + 1;

    // The frame buffer is allocated once; evaluation itself allocates nothing.
    context.beginStage(FramesStage, std::uint64_t(count));
    std::vector<float> frames(std::size_t(count) * floats), face(std::size_t(count) * faceFloats);
    for (long i = 0; i < count; ++i) {
        if (context.stopRequested())
            return cancelledError(title());
        stage.evaluate(secondsToTicks(start + double(i) / fps), poses);
        const CharacterPose& pose = poses.characters.front();
        std::copy(pose.body.begin(), pose.body.end(), frames.begin() + std::ptrdiff_t(std::size_t(i) * floats));
        if (faceFloats > 0)
            std::copy(pose.face.begin(), pose.face.end(), face.begin() + std::ptrdiff_t(std::size_t(i) * faceFloats));
        context.setDone(std::uint64_t(i + 1));
        if (frameDelay.count() > 0)
            std::this_thread::sleep_for(frameDelay);
    }

    if (output.extension() == ".glb") {
        if (auto written = writeGltf(*body, frames, face, count); !written)
            return written;
        frameCount = count;
        lastTime = start + double(count - 1) / fps;
        return {};
    }
    auto clip = anim::KeyframeClip::create(layout, fps, std::move(frames), character);
    if (!clip)
        return clip.error();
    std::shared_ptr<anim::KeyframeClip> onSkeleton = clip.value();
    const anim::Skeleton& skeleton = body->skeleton;
    if (!(*layout == *skeleton.frameLayout())) {
        // The body schedule is built on the skeleton's layout; this keeps the writer safe if a
        // future runtime ever differs.
        auto remapped = anim::remapClip(*onSkeleton, skeleton.frameLayout(), skeleton.restFrame());
        if (!remapped)
            return remapped.error();
        onSkeleton = remapped.value();
    }
    if (context.stopRequested())
        return cancelledError(title());
    if (auto saved = anim::bvh::save(output, skeleton, *onSkeleton); !saved)
        return saved;
    frameCount = count;
    lastTime = start + double(count - 1) / fps;
    return {};
}

// The frames onto the model's rig, as the renderer poses it, and the face at the same times.
Result<void> MotionBakeJob::writeGltf(const CharacterRuntime& body, std::span<const float> frames,
                                      std::span<const float> face, long count)
{
    const auto index = std::size_t(scenario.findCharacter(character) - scenario.characters.data());
    auto model = scenario::loadCharacterBody(scenario, index, assets);
    if (!model)
        return model.error();
    const anim::FrameRetarget retarget = scenario::retargetOntoBody(body.skeleton, *model);
    const std::size_t from = body.skeleton.frameLayout()->floatCount();
    const std::size_t to = model->skeleton.frameLayout()->floatCount();
    std::vector<float> onModel(std::size_t(count) * to);
    for (long i = 0; i < count; ++i)
        retarget.apply(frames.subspan(std::size_t(i) * from, from), std::span<float>(onModel).subspan(std::size_t(i) * to, to));
    scene::GltfMotion motion;
    motion.name = character;
    motion.fps = fps;
    motion.bodyFrames = onModel;
    if (body.face) {
        motion.faceLayout = body.face->layout();
        motion.faceFrames = face;
        motion.face = &model->face;
    }
    const std::string& modelFile = scenario.findCharacter(character)->model;
    if (modelFile.empty()) {
        // The built-in humanoid has no file to carry the motion: it is written whole.
        auto written = scene::writeGltfCharacter(output, *model, motion, animationOnly);
        if (!written)
            return written.error();
        warnings = written->warnings;
        return {};
    }
    auto written = scene::writeGltfMotion(output, assets.path(modelFile), model->skeleton, motion, animationOnly);
    if (!written)
        return written.error();
    morphTargets = written->morphTargets;
    return {};
}

void MotionBakeJob::discardOutput()
{
    std::error_code ignored;
    std::filesystem::remove(output, ignored);
}

} // namespace thespis::core::runtime
