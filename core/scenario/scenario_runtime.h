#pragma once
// Turns a scenario document into runnable blending schedules: loads every clip (BVH files
// relative to the scenario's folder, inline keyframes), builds each character's skeleton,
// applies modifiers, resolves masks and fills one schedule per layer, nested in one schedule
// per character and kind (body, face). The document is not changed; problems are errors naming
// the character, action and field.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "anim/blending_schedule.h"
#include "anim/keyframe_clip.h"
#include "anim/skeleton.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

/// A character's schedules. Every layer is built (so that its actions are checked and can be
/// found by id), but only the layers that play — not muted, and solo when any layer of the
/// character is solo — are nested in `body` / `face`.
struct CharacterRuntime {
    std::string name;
    anim::Skeleton skeleton;
    std::map<std::string, std::shared_ptr<anim::KeyframeClip>> clips; ///< on skeleton's layout
    std::shared_ptr<anim::BlendingSchedule> body;       ///< every body layer, nested
    std::shared_ptr<anim::BlendingSchedule> face;       ///< every face layer (MPEG-4 FAPs), nested
    std::vector<std::shared_ptr<anim::BlendingSchedule>> layers; ///< per Layer, same order
    std::vector<std::vector<anim::ActionId>> actionIds; ///< per layer, per ActionSpec
    std::vector<std::string> warnings;                  ///< e.g. unmapped BVH joints
};

struct ScenarioRuntime {
    std::vector<CharacterRuntime> characters;
    double duration = 0; ///< seconds: Scenario::duration, or the latest end of a finite action
    const CharacterRuntime* findCharacter(const std::string& name) const;
};

/// BVH clips already read, by file and frame rate, so that an editor rebuilding the runtime after
/// every edit reads each file once. A file changed on disk is read again (its time stamp is kept).
class ClipFileCache {
public:
    ClipFileCache();
    ~ClipFileCache();
    ClipFileCache(const ClipFileCache&) = delete;
    ClipFileCache& operator=(const ClipFileCache&) = delete;

    struct Entry;
    /// The cached import of `path` read at `frameRateOverride` (0: the file's own), or null.
    const Entry* find(const std::filesystem::path& path, double frameRateOverride) const;
    void store(const std::filesystem::path& path, double frameRateOverride, Entry entry);
    void clear();

private:
    struct Key;
    std::vector<std::pair<std::unique_ptr<Key>, std::unique_ptr<Entry>>> m_entries;
};

/// `baseDir` is where relative clip files are looked up (the scenario file's folder). `cache`
/// (optional) keeps BVH files read between builds.
Result<ScenarioRuntime> buildRuntime(const Scenario& scenario, const std::filesystem::path& baseDir,
                                     ClipFileCache* cache = nullptr);

/// Checks a scenario without keeping the result: every problem found, empty when valid.
std::vector<Error> validateScenario(const Scenario& scenario, const std::filesystem::path& baseDir);

} // namespace thespis::core::scenario
