#include "scenario/scenario_runtime.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>
#include <optional>
#include <set>
#include <utility>

#include "anim/clip_retarget.h"
#include "scene/default_humanoid.h"
#include "scene/foot_soles.h"
#include "anim/hanim.h"
#include "anim/modifiers.h"
#include "motion/idle_motion.h"
#include "scenario/action_modifier.h"
#include "scenario/action_placement.h"
#include "scenario/gaze_cue.h"
#include "scenario/runtime_gestures.h"
#include "scenario/scenario_character.h"
#include "scenario/source_clip.h"
#include "lighting/probe.h"
#include "scene/gltf_mesh.h"
#include "util/text.h"

namespace thespis::core::scenario {

void CharacterRuntime::evaluateBody(double seconds, std::span<float> frame) const
{
    if (body)
        body->evaluate(seconds, frame);
    place(*skeleton.frameLayout(), frame);
}

void CharacterRuntime::place(const anim::FrameLayout& layout, std::span<float> frame) const
{
    placement.apply(layout, frame);
}

const CharacterRuntime* ScenarioRuntime::findCharacter(const std::string& characterName) const
{
    for (const CharacterRuntime& character : characters)
        if (character.name == characterName)
            return &character;
    return nullptr;
}

namespace {

using anim::BlendingSchedule;
using anim::KeyframeClip;

std::string joinNames(const std::vector<std::string>& names, std::size_t limit = 12)
{
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < limit; ++i)
        text += (i ? ", " : "") + names[i];
    if (names.size() > limit)
        text += " and " + std::to_string(names.size() - limit) + " more";
    return text;
}

} // namespace

namespace {

// Builds the runtime of a scenario and collects every problem it meets (buildRuntime fails with
// the first, validateScenario lists them all). A part that fails (a clip, an action, a
// character's skeleton) is left out, so that one mistake is reported once and not again by
// everything that depends on it. Problems name the character, layer, action and field.
class RuntimeBuilder {
public:
    RuntimeBuilder(const Scenario& scenario, Assets assets, AssetCache* cache = nullptr)
        : m_scenario(scenario), m_assets(std::move(assets)), m_cache(cache ? cache : &m_ownCache)
    {
    }

    ScenarioRuntime build()
    {
        ScenarioRuntime runtime;
        if (m_scenario.duration < 0)
            problem(ErrorCode::InvalidSchedule, "The scenario's duration must not be negative.");
        buildMasks();
        std::set<std::string> names;
        for (std::size_t i = 0; i < m_scenario.characters.size(); ++i) {
            const Character& character = m_scenario.characters[i];
            if (character.name.empty())
                problem(ErrorCode::InvalidSchedule, "Character " + std::to_string(i + 1) + " has no name.");
            else if (!names.insert(character.name).second)
                problem(ErrorCode::InvalidSchedule, "Two characters are named " + inQuotes(character.name) + ".");
            if (auto built = buildCharacter(character))
                runtime.characters.push_back(std::move(*built));
        }
        setDuration(runtime);
        return runtime;
    }

    // `previous` with the characters at `indices` built again (the others are shared with it).
    ScenarioRuntime rebuild(const ScenarioRuntime& previous, std::span<const int> indices)
    {
        ScenarioRuntime runtime = previous;
        buildMasks();
        for (const int i : indices) {
            if (auto built = buildCharacter(m_scenario.characters[std::size_t(i)]))
                runtime.characters[std::size_t(i)] = std::move(*built);
        }
        setDuration(runtime);
        return runtime;
    }

    std::vector<Error> errors;

private:
    void setDuration(ScenarioRuntime& runtime) const
    {
        runtime.duration = m_scenario.duration;
        if (m_scenario.duration == 0) {
            for (const CharacterRuntime& character : runtime.characters)
                for (const auto& layer : character.layers)
                    for (const anim::ActionId id : layer->actionIds())
                        if (const double end = layer->endTime(id); std::isfinite(end))
                            runtime.duration = std::max(runtime.duration, secondsToTicks(end));
        }
    }

    void problem(ErrorCode code, std::string message, std::string detail = {})
    {
        errors.push_back(makeError(code, std::move(message), std::move(detail)));
    }

    void buildMasks()
    {
        std::set<std::string> names;
        for (std::size_t i = 0; i < m_scenario.masks.size(); ++i) {
            const NamedMask& mask = m_scenario.masks[i];
            if (mask.name.empty()) {
                problem(ErrorCode::InvalidSchedule, "Mask " + std::to_string(i + 1) + " has no name.");
                continue;
            }
            if (!names.insert(mask.name).second) {
                problem(ErrorCode::InvalidSchedule, "Two masks are named " + inQuotes(mask.name) + ".");
                continue;
            }
            if (auto ok = mask.mask.validate(); !ok) {
                problem(ErrorCode::InvalidSchedule, "Mask " + inQuotes(mask.name) + ": " + ok.error().message);
                continue;
            }
            m_masks[mask.name] = std::make_shared<const anim::JointMask>(mask.mask);
        }
    }

    std::optional<anim::Skeleton> resolveSkeleton(const Character& character, const std::string& who,
                                                  std::map<std::string, SourceClip>& sources)
    {
        const std::string& spec = character.skeleton;
        for (const auto& [name, level] : {std::pair{"hanim-loa1", anim::hanim::Level::Loa1},
                                          std::pair{"hanim-loa2", anim::hanim::Level::Loa2},
                                          std::pair{"hanim-25", anim::hanim::Level::Subset25}})
            if (spec == name) {
                if (character.model.empty()) // the built-in humanoid: motion keeps its own feet down
                    m_soles = scene::defaultHumanoidSoles(level);
                return anim::hanim::skeleton(level);
            }
        if (spec == "model") {
            if (character.model.empty()) {
                problem(ErrorCode::InvalidSchedule, who + ", skeleton \"model\": the character has no model to take its rig from.");
                return std::nullopt;
            }
            auto rig = m_cache->modelRig(m_assets.path(character.model));
            if (!rig) {
                problem(rig.error().code, who + ", model " + inQuotes(character.model) + ": " + rig.error().message,
                        rig.error().detail);
                return std::nullopt;
            }
            m_soles = (*rig)->soles;
            return (*rig)->skeleton;
        }
        if (spec.starts_with("clip:") && spec.size() > 5) {
            const std::string clipName = spec.substr(5);
            const auto it = sources.find(clipName);
            if (it == sources.end()) {
                const bool exists = std::any_of(character.clips.begin(), character.clips.end(),
                                                [&](const ClipAsset& c) { return c.name == clipName; });
                if (!exists)
                    problem(ErrorCode::InvalidSchedule,
                            who + ", skeleton " + inQuotes(spec) + ": the character has no clip named " + inQuotes(clipName) + ".");
                return std::nullopt; // a clip that failed to load was reported already
            }
            if (!it->second.file) {
                problem(ErrorCode::InvalidSchedule, who + ", skeleton " + inQuotes(spec)
                                                        + (it->second.idle ? ": the clip is synthesized" : ": the clip is stored inline")
                                                        + std::string("; only a clip read from a file carries a skeleton."));
                return std::nullopt;
            }
            return it->second.file->skeleton;
        }
        problem(ErrorCode::InvalidSchedule, who + ": unknown skeleton " + inQuotes(spec)
                                                + " (expected hanim-loa1, hanim-loa2, hanim-25, model or clip:NAME).");
        return std::nullopt;
    }

    // A file's clip on the character's skeleton: as it is when it is that very rig, else
    // retargeted (resized by the legs, on the performer's floor). Null (and a problem) when it
    // shares no joint with the skeleton.
    std::shared_ptr<const KeyframeClip> retargeted(const SourceClip& source, const anim::Skeleton& skeleton,
                                                   const std::string& where)
    {
        const anim::Skeleton& rig = source.file->skeleton;
        if (rig.joints() == skeleton.joints())
            return source.clip;
        anim::ClipRetargetOptions options;
        options.retarget.sourceUnit = source.asset->unit > 0 ? source.asset->unit : source.file->report.unit;
        options.fitGround = source.asset->fitGround;
        options.retarget.targetSoles = m_soles;
        // Kept between builds: the file as read, the options and the skeleton (with its body).
        std::string key = "retarget\n" + m_assets.where(source.asset->file) + "\n"
                          + std::to_string(m_assets.stamp(source.asset->file)) + "\n"
                          + source.asset->animation + "\n" + std::to_string(source.asset->frameRateOverride) + "\n"
                          + std::to_string(options.retarget.sourceUnit) + (options.fitGround ? " fit" : " keep")
                          + (source.asset->keepCalibrationFrame ? " calibration" : "") + "\n" + m_skeletonKey;
        for (const auto& [joint, name] : source.asset->mapping)
            key += "\n" + joint + "=" + name;
        auto made = m_cache->retargeted(key, [&]() -> Result<AssetCache::ClipPtr> {
            auto clip = anim::retargetClip(*source.clip, rig, skeleton, options);
            if (!clip)
                return clip.error();
            return AssetCache::ClipPtr(clip->clip);
        });
        if (!made) {
            problem(ErrorCode::InvalidSchedule, where + ": " + made.error().message);
            return nullptr;
        }
        return *made;
    }

    // The clip on `layout`; caches per layout kind. Null (and a problem) when the clip shares no
    // element with the layout.
    std::shared_ptr<const KeyframeClip> onLayout(const SourceClip& source, const anim::FrameLayoutPtr& layout,
                                           std::span<const float> rest, const std::string& where,
                                           std::vector<std::string>* dropped)
    {
        if (source.clip->layout() == layout || *source.clip->layout() == *layout)
            return source.clip;
        std::vector<std::string> lost;
        auto remapped = anim::remapClip(*source.clip, layout, rest, &lost);
        if (!remapped) {
            problem(ErrorCode::InvalidSchedule, where + ": " + remapped.error().message);
            return nullptr;
        }
        if (int(lost.size()) >= source.clip->layout()->elementCount())
            return nullptr;
        if (dropped) {
            std::sort(lost.begin(), lost.end());
            lost.erase(std::unique(lost.begin(), lost.end()), lost.end());
            *dropped = std::move(lost);
        }
        return std::move(remapped).value();
    }

    // Whether the scenario names posture bases that can be read; says nothing when they cannot
    // (an action with the filter does, through postureBases()).
    bool postureBasesReadable()
    {
        if (m_bases)
            return true;
        if (m_scenario.postureBases.empty())
            return false;
        return m_cache->postureBases(m_scenario.postureBases, m_assets).ok();
    }

    // The scenario's posture bases, read once per build (a problem, once, when they cannot be).
    Result<std::shared_ptr<const motion::PostureBases>> postureBases()
    {
        if (m_bases)
            return m_bases;
        if (m_basesError)
            return *m_basesError;
        if (m_scenario.postureBases.empty()) {
            m_basesError = makeError(ErrorCode::InvalidSchedule,
                                     "the dependent-joint filter needs the scenario's posture bases (postureBases: a .pca "
                                     "file made by thespis-cli train-pca).");
            return *m_basesError;
        }
        auto read = m_cache->postureBases(m_scenario.postureBases, m_assets);
        if (!read) {
            problem(read.error().code, "Posture bases " + inQuotes(m_scenario.postureBases) + ": " + read.error().message,
                    "looked for " + m_assets.where(m_scenario.postureBases));
            m_basesError = makeError(read.error().code, "the posture bases cannot be read (reported above).");
            return *m_basesError;
        }
        m_bases = *read;
        return m_bases;
    }

    static bool weightIsNonNegative(const anim::Curve& curve)
    {
        if (curve.kind() == anim::CurveKind::Keyframed)
            return std::all_of(curve.keys().begin(), curve.keys().end(),
                               [](const anim::CurveKey& k) { return k.value >= 0; });
        return curve.envelope().peak >= 0;
    }

    struct Context {
        const Character& character;
        const std::map<std::string, SourceClip>& sources;
        std::map<std::string, std::shared_ptr<const KeyframeClip>> faceClips;
    };

    std::optional<anim::BlendingAction> buildAction(const ActionSpec& spec, const Layer& layer, Context& ctx,
                                                    const std::string& where, CharacterRuntime& runtime)
    {
        const std::size_t before = errors.size();
        anim::BlendingAction action;
        action.name = spec.name;
        action.start = ticksToSeconds(spec.start);
        action.renderOutsideDomain = spec.renderOutsideDomain;
        if (spec.start < 0)
            problem(ErrorCode::InvalidSchedule, where + ", start: must not be negative.");

        // Source: the clip on the layer's layout.
        anim::BlendablePtr source;
        const auto clip = ctx.sources.find(spec.clip);
        const bool declared = std::any_of(ctx.character.clips.begin(), ctx.character.clips.end(),
                                          [&](const ClipAsset& c) { return c.name == spec.clip; });
        if (layer.kind == LayerKind::Gaze) {
            source = gazeSpan(spec, where);
        } else if (spec.gaze) {
            problem(ErrorCode::InvalidSchedule, where + ", gaze: only an action of a gaze layer looks at something.");
        } else if (!declared) {
            std::vector<std::string> names;
            for (const ClipAsset& c : ctx.character.clips)
                names.push_back(c.name);
            problem(ErrorCode::InvalidSchedule, where + ", clip: the character has no clip named " + inQuotes(spec.clip)
                                                    + (names.empty() ? "." : " (its clips: " + joinNames(names) + ")."));
        } else if (clip != ctx.sources.end()) { // else it failed to load, reported already
            if (layer.kind == LayerKind::Body) {
                const auto it = runtime.clips.find(spec.clip);
                if (it != runtime.clips.end())
                    source = it->second;
                else
                    problem(ErrorCode::InvalidSchedule, where + ", clip " + inQuotes(spec.clip)
                                                            + ": it moves no joint of the character's skeleton.");
            } else if (clip->second.idle) {
                problem(ErrorCode::InvalidSchedule, where + ", clip " + inQuotes(spec.clip)
                                                        + ": idle motion moves a body; it cannot play on a face layer.");
            } else if (clip->second.blinks) {
                source = clip->second.blinks;
            } else {
                auto& face = ctx.faceClips[spec.clip];
                if (!face) {
                    const auto layout = anim::FrameLayout::mpeg4Face();
                    face = onLayout(clip->second, layout, anim::neutralFrame(*layout), where, nullptr);
                }
                if (face)
                    source = face;
                else
                    problem(ErrorCode::InvalidSchedule, where + ", clip " + inQuotes(spec.clip)
                                                            + ": a face layer needs MPEG-4 FAP values (fap1 … fap68) or the weights of visemes or "
                                                              "expressions (viseme1 … viseme14, expression1 … expression6), "
                                                              "and the clip has none.");
            }
        }

        if (spec.pointing && layer.kind != LayerKind::Body)
            problem(ErrorCode::InvalidSchedule, where + ", pointing: only an action of a body layer points.");
        else if (spec.pointing)
            if (auto cue = readPointingCue(*spec.pointing, m_scenario, runtime.skeleton); !cue)
                problem(cue.error().code, where + ", " + cue.error().message);

        // Modifiers, in order: the first wraps the clip.
        for (std::size_t m = 0; source && m < spec.modifiers.size(); ++m) {
            auto wrapped = applyModifier(source, spec.modifiers[m], runtime.skeleton, layer.kind,
                                         [this] { return postureBases(); });
            if (!wrapped) {
                problem(ErrorCode::InvalidSchedule,
                        where + ", modifiers[" + std::to_string(m) + "]: " + wrapped.error().message);
                source = nullptr;
            } else {
                source = std::move(wrapped).value();
            }
        }
        action.source = source;

        // Blending parameters.
        if (auto ok = spec.weight.validate(); !ok)
            problem(ErrorCode::InvalidSchedule, where + ", weight: " + ok.error().message);
        else if (!weightIsNonNegative(spec.weight))
            problem(ErrorCode::InvalidSchedule, where + ", weight: a weight must not be negative.");
        if (auto ok = spec.scale.validate(); !ok)
            problem(ErrorCode::InvalidSchedule, where + ", scale: " + ok.error().message);
        action.params.weight = spec.weight;
        action.params.scale = spec.scale;
        action.params.mode = spec.mode;
        if (!spec.mask.empty()) {
            const auto mask = m_masks.find(spec.mask);
            if (mask != m_masks.end())
                action.params.mask = mask->second;
            else if (!m_scenario.findMask(spec.mask))
                problem(ErrorCode::InvalidSchedule, where + ", mask: the scenario has no mask named " + inQuotes(spec.mask) + ".");
        }
        if (errors.size() != before || !source)
            return std::nullopt;
        return action;
    }

    // A gaze action's source (gazeSpanClip), once what it looks at reads.
    anim::BlendablePtr gazeSpan(const ActionSpec& spec, const std::string& where)
    {
        if (!spec.gaze) {
            problem(ErrorCode::InvalidSchedule, where + ", gaze: an action of a gaze layer needs a target.");
            return nullptr;
        }
        if (!spec.clip.empty())
            problem(ErrorCode::InvalidSchedule, where + ", clip: an action of a gaze layer plays no clip.");
        if (auto cue = readGazeCue(*spec.gaze, m_scenario); !cue) {
            problem(cue.error().code, where + ", " + cue.error().message);
            return nullptr;
        }
        return gazeSpanClip();
    }

    // Every clip with face values on the face layout (the Stage's face actions), shared with the
    // face layers that play them.
    void buildFaceClips(Context& ctx, CharacterRuntime& runtime, const std::string& who)
    {
        const auto layout = anim::FrameLayout::mpeg4Face();
        for (const auto& [name, source] : ctx.sources) {
            if (source.blinks) {
                runtime.faceClips.emplace(name, source.blinks);
                continue;
            }
            if (source.idle || !hasFaceValues(*source.clip->layout()))
                continue;
            if (auto face = onLayout(source, layout, anim::neutralFrame(*layout), who + ", clip " + inQuotes(name), nullptr)) {
                ctx.faceClips[name] = face;
                runtime.faceClips.emplace(name, std::move(face));
            }
        }
    }

    static bool hasFaceValues(const anim::FrameLayout& layout)
    {
        const auto face = anim::FrameLayout::mpeg4Face();
        for (int e = layout.rotationCount() + layout.translationCount(); e < layout.elementCount(); ++e)
            if (face->find(layout.name(e), anim::ElementKind::Scalar) >= 0)
                return true;
        return false;
    }

    // A gesture's action as a body or face action of the character. What keeps it from being
    // built is a warning, not an error: the gesture is left out of what scripts can play, the
    // rest plays.
    std::optional<anim::BlendingAction> buildGestureAction(const ActionSpec& spec, LayerKind kind,
                                                           const NamedMask* widened, const std::string& where,
                                                           Context& ctx, CharacterRuntime& runtime)
    {
        if (widened && !m_masks.contains(widened->name))
            m_masks[widened->name] = std::make_shared<const anim::JointMask>(widened->mask);
        Layer layer;
        layer.kind = kind;
        const std::size_t before = errors.size();
        auto built = buildAction(spec, layer, ctx, where, runtime);
        // The gesture's own problems become warnings; the scenario's (its posture bases cannot be
        // read) stay errors, as for any action.
        const auto own = std::stable_partition(errors.begin() + std::ptrdiff_t(before), errors.end(),
                                               [&](const Error& e) { return !e.message.starts_with(where); });
        for (auto e = own; e != errors.end(); ++e) {
            runtime.warnings.push_back(e->message + " Scripts cannot play this gesture.");
            runtime.warningClips.resize(runtime.warnings.size(), spec.clip);
        }
        errors.erase(own, errors.end());
        return built;
    }

    std::optional<CharacterRuntime> buildCharacter(const Character& character)
    {
        const std::string who = "Character " + inQuotes(character.name);
        const std::size_t before = errors.size();
        CharacterRuntime runtime;
        runtime.name = character.name;
        runtime.speech = character.speech;

        // Clips as read from their sources.
        std::map<std::string, SourceClip> sources;
        for (std::size_t i = 0; i < character.clips.size(); ++i) {
            const ClipAsset& asset = character.clips[i];
            const std::string where = who + ", clip " + (asset.name.empty() ? std::to_string(i + 1) : inQuotes(asset.name));
            if (asset.name.empty()) {
                problem(ErrorCode::InvalidSchedule, where + ": a clip needs a name.");
                continue;
            }
            if (sources.count(asset.name)) {
                problem(ErrorCode::InvalidSchedule, where + ": two clips have this name.");
                continue;
            }
            if (auto loaded = readSourceClip(asset, where, *m_cache, m_assets))
                sources.emplace(asset.name, std::move(*loaded));
            else
                errors.push_back(std::move(loaded).error());
        }

        m_soles.clear();
        m_skeletonKey = character.skeleton + "\n" + character.model + "\n"
                        + (character.model.empty() ? std::string() : std::to_string(m_assets.stamp(character.model)));
        auto skeleton = resolveSkeleton(character, who, sources);
        if (!skeleton)
            return std::nullopt;
        runtime.skeleton = *skeleton;
        if (!std::isfinite(character.heading) || !std::isfinite(character.position.x)
            || !std::isfinite(character.position.y) || !std::isfinite(character.position.z))
            problem(ErrorCode::InvalidSchedule, who + ": its position and heading must be finite numbers.");
        runtime.placement.rotation =
            anim::Quat::fromAxisAngle(anim::Vec3{0, 1, 0}, float(character.heading * std::numbers::pi / 180.0));
        runtime.placement.translation = character.position;
        const std::vector<float> rest = runtime.skeleton.restFrame();
        for (const auto& [name, source] : sources) {
            if (source.blinks)
                continue; // a face clip: an error if a body layer plays it
            if (source.idle) {
                motion::IdleOptions options;
                options.seed = source.asset->idle->seed;
                options.amplitude = float(source.asset->idle->amplitude);
                auto idle = motion::IdleMotion::create(source.idle, runtime.skeleton, options);
                if (!idle)
                    problem(ErrorCode::InvalidSchedule, who + ", clip " + inQuotes(name) + ": " + idle.error().message);
                else
                    runtime.clips.emplace(name, std::move(idle).value());
                continue;
            }
            if (source.file) {
                runtime.clipReports[name] = source.file->report;
                if (const auto lost = unmappedJointsMovingNothing(*source.file, runtime.skeleton); !lost.empty()) {
                    runtime.warnings.push_back(who + ", clip " + inQuotes(name) + ": " + std::to_string(lost.size())
                                               + " joints of the file have no H-Anim name and move nothing of the character: "
                                               + joinNames(lost) + ".");
                    runtime.warningClips.resize(runtime.warnings.size(), name);
                }
                const auto& joints = source.file->skeleton.joints();
                if (std::none_of(joints.begin(), joints.end(),
                                 [&](const anim::Joint& j) { return runtime.skeleton.find(j.name) >= 0; }))
                    continue; // no body joint: fine for a face clip, an error if a body layer plays it
                if (auto onSkeleton = retargeted(source, runtime.skeleton, who + ", clip " + inQuotes(name)))
                    runtime.clips.emplace(name, std::move(onSkeleton));
                continue;
            }
            std::vector<std::string> dropped;
            auto onSkeleton = onLayout(source, runtime.skeleton.frameLayout(), rest, who + ", clip " + inQuotes(name), &dropped);
            if (!onSkeleton)
                continue; // no body joint: fine for a face clip, an error if a body layer plays it
            if (!dropped.empty()) {
                runtime.warnings.push_back(who + ", clip " + inQuotes(name) + ": " + std::to_string(dropped.size())
                                           + " of its joints are not in the skeleton and are left out: "
                                           + joinNames(dropped) + ".");
                runtime.warningClips.resize(runtime.warnings.size(), name);
            }
            runtime.clips.emplace(name, std::move(onSkeleton));
        }

        for (std::size_t g = 0; g < character.gestures.size(); ++g) {
            const Gesture& gesture = character.gestures[g];
            const std::string where = who + ", gesture " + (gesture.name.empty() ? std::to_string(g + 1) : inQuotes(gesture.name));
            if (gesture.name.empty())
                problem(ErrorCode::InvalidSchedule, where + ": a gesture needs a name.");
            if (!character.findClip(gesture.clip))
                problem(ErrorCode::InvalidSchedule, where + ", clip: the character has no clip named " + inQuotes(gesture.clip) + ".");
            if (!gesture.mask.empty() && !m_scenario.findMask(gesture.mask))
                problem(ErrorCode::InvalidSchedule, where + ", mask: the scenario has no mask named " + inQuotes(gesture.mask) + ".");
            if (gesture.fadeIn < 0 || gesture.fadeOut < 0)
                problem(ErrorCode::InvalidSchedule, where + ": fade times must not be negative.");
        }

        buildBmlLexicon(character, runtime);

        Context ctx{character, sources, {}};
        buildFaceClips(ctx, runtime, who);
        if (errors.size() == before)
            buildGestures(m_scenario, character, [&](const ActionSpec& spec, LayerKind kind, const NamedMask* widened,
                                                     const std::string& where) {
                return buildGestureAction(spec, kind, widened, where, ctx, runtime);
            }, postureBasesReadable(), runtime);

        const bool anySolo = std::any_of(character.layers.begin(), character.layers.end(),
                                         [](const Layer& layer) { return layer.solo; });
        runtime.body = std::make_shared<BlendingSchedule>(runtime.skeleton);
        runtime.face = std::make_shared<BlendingSchedule>(anim::FrameLayout::mpeg4Face());
        bool firstBody = true, firstFace = true;
        std::set<std::string> layerNames;
        for (std::size_t l = 0; l < character.layers.size(); ++l) {
            const Layer& layer = character.layers[l];
            const std::string where = who + ", layer " + (layer.name.empty() ? std::to_string(l + 1) : inQuotes(layer.name));
            if (layer.name.empty())
                problem(ErrorCode::InvalidSchedule, where + ": a layer needs a name.");
            else if (!layerNames.insert(layer.name).second)
                problem(ErrorCode::InvalidSchedule, where + ": two layers of the character have this name.");
            const bool body = layer.kind == LayerKind::Body;
            auto schedule = body ? std::make_shared<BlendingSchedule>(runtime.skeleton)
                                 : std::make_shared<BlendingSchedule>(anim::FrameLayout::mpeg4Face());
            std::vector<std::optional<anim::BlendingAction>> actions;
            for (std::size_t a = 0; a < layer.actions.size(); ++a) {
                const ActionSpec& spec = layer.actions[a];
                const std::string at = where + ", action " + (spec.name.empty() ? std::to_string(a + 1) : inQuotes(spec.name));
                actions.push_back(buildAction(spec, layer, ctx, at, runtime));
            }
            if (body)
                placeActions(layer, actions);
            std::vector<anim::ActionId> ids;
            for (std::size_t a = 0; a < layer.actions.size(); ++a) {
                const ActionSpec& spec = layer.actions[a];
                const std::string at = where + ", action " + (spec.name.empty() ? std::to_string(a + 1) : inQuotes(spec.name));
                if (!actions[a]) {
                    ids.push_back(0);
                    continue;
                }
                auto id = schedule->addAction(std::move(*actions[a]));
                if (!id) {
                    problem(ErrorCode::InvalidSchedule, at + ": " + id.error().message, id.error().detail);
                    ids.push_back(0);
                    continue;
                }
                ids.push_back(*id);
            }

            // Nest the layer in the character's schedule of its kind. It starts at 0 and renders
            // outside its domain, so it keeps playing while actions are added to it live. A nested
            // schedule passes on its coverage, so a layer above the base changes only the joints
            // its actions drive, and only while they play.
            runtime.layers.push_back(schedule);
            runtime.actionIds.push_back(std::move(ids));
            if (layer.mute || (anySolo && !layer.solo))
                continue;
            if (layer.kind == LayerKind::Gaze) {
                addGazeCues(layer, *schedule, runtime.actionIds.back(), m_scenario, runtime.gaze);
                continue;
            }
            if (body)
                addPointingCues(layer, *schedule, runtime.actionIds.back(), m_scenario, runtime.skeleton, runtime.pointing);
            bool& first = body ? firstBody : firstFace;
            anim::BlendingAction nested;
            nested.name = layer.name;
            nested.source = schedule;
            nested.start = 0;
            nested.renderOutsideDomain = true;
            nested.params.mode = first ? anim::BlendMode::Normalized : layer.mode;
            nested.params.additiveReference = anim::AdditiveReference::RestPose;
            first = false;
            auto& parent = body ? runtime.body : runtime.face;
            if (auto id = parent->addAction(std::move(nested)); !id)
                problem(ErrorCode::InvalidSchedule, where + ": " + id.error().message, id.error().detail);
        }
        if (errors.size() != before)
            return std::nullopt;
        return runtime;
    }

    const Scenario& m_scenario;
    Assets m_assets;
    AssetCache m_ownCache; // when the caller keeps none
    std::vector<anim::BodyMeasure::SolePoint> m_soles; // the character's model's, when it plays on its rig
    std::string m_skeletonKey; // what the character's skeleton and soles are made from
    AssetCache* m_cache = nullptr;
    std::map<std::string, std::shared_ptr<const anim::JointMask>> m_masks;
    std::shared_ptr<const motion::PostureBases> m_bases;
    std::optional<Error> m_basesError;
};

} // namespace

namespace {

// The first of the builder's errors, with a count and summary of the others in its detail.
Error firstError(const RuntimeBuilder& builder)
{
    Error first = builder.errors.front();
    if (builder.errors.size() > 1) {
        std::string others = std::to_string(builder.errors.size() - 1) + " more problem(s): ";
        for (std::size_t i = 1; i < builder.errors.size(); ++i)
            others += (i > 1 ? " | " : "") + builder.errors[i].message;
        first.detail = first.detail.empty() ? others : first.detail + "; " + others;
    }
    return first;
}

} // namespace

Result<ScenarioRuntime> buildRuntime(const Scenario& scenario, const Assets& assets, AssetCache* cache)
{
    RuntimeBuilder builder(scenario, assets, cache);
    ScenarioRuntime runtime = builder.build();
    if (!builder.errors.empty())
        return firstError(builder);
    return runtime;
}

Result<ScenarioRuntime> rebuildRuntime(const Scenario& scenario, const Assets& assets, const ScenarioRuntime& previous,
                                       std::span<const int> characters, AssetCache* cache)
{
    if (previous.characters.size() != scenario.characters.size())
        return makeError(ErrorCode::InvalidArgument, "The scenario's characters changed: build its runtime anew.");
    for (const int i : characters)
        if (i < 0 || std::size_t(i) >= scenario.characters.size())
            return makeError(ErrorCode::InvalidArgument, "There is no character " + std::to_string(i) + " to rebuild.");
    RuntimeBuilder builder(scenario, assets, cache);
    ScenarioRuntime runtime = builder.rebuild(previous, characters);
    if (!builder.errors.empty())
        return firstError(builder);
    return runtime;
}

namespace {

// An error of a file the scenario names, prefixed with the field that names it.
Error fieldError(const std::string& field, const Error& error)
{
    return makeError(error.code, field + ": " + error.message, error.detail);
}

// The lighting side of a scenario (models and their segment tags, the probe): loaded only to
// validate, since the runtime plays animation and the renderer loads meshes itself.
void validateLightingFiles(const Scenario& scenario, const Assets& assets, std::vector<Error>& errors)
{
    for (std::size_t i = 0; i < scenario.characters.size(); ++i) {
        const Character& character = scenario.characters[i];
        const std::string field = "characters[" + std::to_string(i) + "]";
        if (character.model.empty())
            continue; // the built-in humanoid (rendering issue) checks its own tags when it is built
        auto mesh = scene::loadGltfMesh(assets.path(character.model));
        if (!mesh) {
            errors.push_back(fieldError(field + ".model", mesh.error()));
            continue;
        }
        if (auto tagged = scene::applySegmentTags(*mesh, character.segmentTags); !tagged)
            errors.push_back(fieldError(field + ".segments", tagged.error()));
    }
    if (!scenario.lighting.probe.empty()) {
        auto layout = lighting::parseProbeLayout(scenario.lighting.layout);
        auto image = lighting::readHdrImage(assets.path(scenario.lighting.probe));
        if (!image)
            errors.push_back(fieldError("lighting.probe", image.error()));
        else if (layout)
            if (auto fits = lighting::checkProbeSize(*image, *layout); !fits)
                errors.push_back(fieldError("lighting.probe", fits.error()));
    }
}

} // namespace

std::vector<Error> validateScenario(const Scenario& scenario, const Assets& assets)
{
    RuntimeBuilder builder(scenario, assets);
    (void)builder.build();
    validateLightingFiles(scenario, assets, builder.errors);
    // A table that cannot be used: playing leaves it out with a warning, checking names it.
    for (std::size_t i = 0; i < scenario.characters.size(); ++i)
        if (auto table = readCharacterFaceMapping(scenario, i, assets); !table)
            builder.errors.push_back(table.error());
    return std::move(builder.errors);
}

} // namespace thespis::core::scenario
