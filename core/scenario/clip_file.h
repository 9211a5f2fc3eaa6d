#pragma once
// A scenario clip's file read as it is (scenario.h's ClipAsset with a file): a BVH file, or one
// animation of a glTF file with the rig it plays on, before it is retargeted onto a character.
// What the reader found is reported for the user (the studio's import dialog, load warnings).
// AssetCache keeps files read (and models' rigs) while they are unchanged on disk, so that an
// editor rebuilding the runtime after every edit reads each file once.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "anim/body_measure.h"
#include "anim/keyframe_clip.h"
#include "anim/skeleton.h"
#include "motion/idle_database.h"
#include "motion/posture_bases.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct ClipFileReport {
    std::string format;                  ///< "bvh" or "gltf"
    std::string convention;              ///< joint naming found ("cmu", "mixamo", …, "user", "none")
    std::vector<std::string> unmapped;   ///< file joints that kept their own name (no H-Anim one)
    std::string turnedFrom;              ///< how the body lay before it was stood up, or empty
    bool calibrationFrame = false;       ///< a BVH's first frame is a calibration pose
    bool calibrationFrameDropped = false;
    /// Metres per file unit as the file tells: 1 for glTF, a BVH's by its convention (CMU's
    /// 0.0564) or by the size of its legs (metres, decimetres, centimetres, inches); 0 unknown.
    double unit = 0;
    std::string unitName;                ///< "CMU", "centimetres", … for people
    std::vector<std::string> animations; ///< glTF: every animation in the file
    int frameCount = 0;
    double frameRate = 0;
    std::vector<std::string> warnings;   ///< from the reader (glTF channels not imported …)
};

struct ClipFile {
    std::shared_ptr<const anim::KeyframeClip> clip; ///< on skeleton's layout
    anim::Skeleton skeleton;
    ClipFileReport report;
};

/// The file's joints that kept their own names (report.unmapped) and move nothing of a character
/// whose skeleton is `target`: neither they nor any joint below them is in it. A joint between
/// mapped ones (CMU's LHipJoint) is not among them: the retarget carries its turn to the joints
/// below.
std::vector<std::string> unmappedJointsMovingNothing(const ClipFile& file, const anim::Skeleton& target);

/// Reads the asset `asset.file` from `assets` with the asset's options: frame rate, calibration
/// frame, joint mapping and, for glTF, which animation. Errors name the file and what is wrong
/// (a BVH line, a missing animation and the ones there are).
Result<ClipFile> readClipFile(const ClipAsset& asset, const Assets& assets);

/// The rig of a glTF model, as a character with skeleton "model" plays on it, and the soles of
/// its feet (scene/foot_soles.h), so that motion retargeted onto it keeps the model's own feet on
/// the floor.
struct ModelRig {
    anim::Skeleton skeleton;
    std::vector<anim::BodyMeasure::SolePoint> soles;
};
Result<ModelRig> readModelRig(const std::filesystem::path& path);

class AssetCache {
public:
    AssetCache();
    ~AssetCache();
    AssetCache(const AssetCache&) = delete;
    AssetCache& operator=(const AssetCache&) = delete;

    /// readClipFile(), from the cache while the file is unchanged on disk (errors are not kept).
    Result<std::shared_ptr<const ClipFile>> clipFile(const ClipAsset& asset, const Assets& assets);
    /// readModelRig(), likewise.
    Result<std::shared_ptr<const ModelRig>> modelRig(const std::filesystem::path& path);
    /// A clip retargeted onto a character, kept under `key` (the runtime makes it from the file,
    /// the options and the skeleton, with the files' modification times); `make` makes it when
    /// it is not kept. The last 64 are kept.
    using ClipPtr = std::shared_ptr<const anim::KeyframeClip>;
    Result<ClipPtr> retargeted(const std::string& key, const std::function<Result<ClipPtr>()>& make);
    /// An idle motion database (motion/idle_database.h) read through `assets`, from the cache
    /// while its file is unchanged: every character idling on it shares one copy.
    Result<std::shared_ptr<const motion::IdleDatabase>> idleDatabase(const std::string& name, const Assets& assets);
    /// Posture bases (motion/posture_bases.h) read through `assets`, likewise.
    Result<std::shared_ptr<const motion::PostureBases>> postureBases(const std::string& name, const Assets& assets);
    /// True when the asset's file, as it is on disk now, is in the cache.
    bool holds(const ClipAsset& asset, const Assets& assets) const;
    void clear();

private:
    struct Entry;
    /// A binary motion file read through `assets` into the entry member `slot`, kept while unchanged.
    template <class T, class Parse>
    Result<std::shared_ptr<const T>> motionFile(const std::string& kind, const std::string& name, const Assets& assets,
                                                Parse parse, std::shared_ptr<const T> Entry::*slot);
    std::map<std::string, std::unique_ptr<Entry>> m_entries; // by key: path and the read options
    std::map<std::string, ClipPtr> m_retargeted;
    std::vector<std::string> m_retargetedOrder; // oldest first
};

} // namespace thespis::core::scenario
