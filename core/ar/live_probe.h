#pragma once
// The light of the AR scene (paper §6 and §7): a chrome ball in the camera's view, unwrapped every
// few frames into a mirror-ball probe and projected onto spherical harmonics, the characters' PRT
// light — or, for a scene without a ball, a probe file read once. One object answers "how is the
// AR scene lit" either way.
//
// Per processed frame: the ball's circle → the ball resampled into a probeSize² mirror-ball image
// (probe.h's layout: the camera is taken as orthographic, so a small or distant ball is best) in
// linear radiance (the video is sRGB 8-bit: decoded, then scaled by the exposure) →
// lighting::ProbeProjector, the projector every probe goes through → exponential smoothing over
// the frames' timestamps. The circle is given by the user, or found: first where the ball was
// last seen, else by Hough circles on the grey frame reduced to searchSize, strongest first.
// Each is refined on the full frame (along radial profiles, the outermost clear step is the rim —
// the ball's outer ring mirrors what is beside it, so the true rim is often fainter than
// reflections just inside — then a robust circle fit) and kept only if a third of the rays agree
// on it and their edges run along the circle (a checkerboard has edges near any circle, but
// across it). The pixel of the rim the frame blends with the background is left out (samples
// there are pulled in by one pixel).
//
// The light is in the probe's frame, the camera's view of the ball: −z towards the camera, +y the
// picture's up, +x its left. Where the world is not the camera's, turn it with the camera's pose
// (lighting::ShRotation) before handing it to the renderer.
//
// Clipped highlights: a pixel with a channel ≥ 250 was clipped by the camera, so its radiance is
// at least what it shows and probably much more. It counts as clipped (clippedFraction()) and is
// scaled by LiveProbeSettings::clippedGain (1 by default: the lower bound). A camera set so that
// the brightest light stays under 250 needs neither.
//
// Owns its buffers: after the first processed frame nothing is allocated per frame but what
// OpenCV's circle search and the projector's per-call sums take.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "ar/video_frame.h"
#include "lighting/probe.h"
#include "lighting/probe_preview.h"
#include "lighting/sh.h"
#include "util/error.h"

namespace thespis::core::ar {

/// A circle in frame pixels. Continuous coordinates as in probe.h: pixel (x, y) covers
/// [x, x+1] × [y, y+1], so the top-left pixel's centre is (0.5, 0.5).
struct BallCircle {
    double centerX = 0, centerY = 0, radius = 0;
};

/// Where the ball was seen in the last processed frame.
struct BallSighting {
    bool found = false;
    BallCircle circle;  ///< when found
    std::string reason; ///< when not found, one sentence for the user ("No circle between 24 and 240 px …")
};

enum class BallLocation {
    Automatic, ///< looked for in every processed frame
    Given      ///< LiveProbeSettings::givenCircle, as the user marked it
};

enum class ProbeExposure {
    Fixed,    ///< radiance = exposure × the decoded sRGB value
    Automatic ///< the ball's mean luminance is brought to targetLuminance (smoothed, see below)
};

struct LiveProbeSettings {
    BallLocation location = BallLocation::Automatic;
    BallCircle givenCircle;                 ///< with BallLocation::Given; must lie inside the frame
    /// Radii (frame px) the automatic search accepts; 0: 4 % and 50 % of the frame's short side.
    double minRadius = 0, maxRadius = 0;
    /// The circle search runs on the grey frame reduced to this long side (px), then refines.
    int searchSize = 640;
    /// SH order of the light: that of render::ScenarioSceneOptions::lightOrder by default.
    int order = 6;
    /// Side (px) of the unwrapped ball, the mirror-ball image that is projected and shown.
    int probeSize = 128;
    /// The first frame and then every updateEvery-th frame given to update() is processed.
    int updateEvery = 5;
    /// Time constant (seconds, frame timestamps) of the light's exponential smoothing; 0: none.
    double smoothingSeconds = 0.5;
    ProbeExposure exposureMode = ProbeExposure::Fixed;
    double exposure = 1.0;                  ///< with Fixed
    double targetLuminance = 0.5;           ///< with Automatic: mean radiance over the sphere
    /// With Automatic: the exposure's own time constant, longer than the light's so that the
    /// camera's auto-exposure does not make the characters' light pump.
    double exposureSmoothingSeconds = 2.0;
    /// Clipped pixels (a channel ≥ 250) are taken as this many times as bright as they show.
    double clippedGain = 1.0;
};

/// Checks every setting, naming the first wrong one and its value.
Result<void> validateLiveProbeSettings(const LiveProbeSettings& settings);

/// Whether a ball circle lies inside a width × height frame; the error names the circle, the
/// frame and which side it crosses.
Result<void> checkBallCircle(const BallCircle& circle, int frameWidth, int frameHeight);

class LiveProbe {
public:
    /// A probe that follows a mirror ball in the frames given to update(). Errors: settings
    /// validateLiveProbeSettings() refuses.
    static Result<LiveProbe> create(const LiveProbeSettings& settings = {});
    /// A fixed probe read from an HDR / EXR file and projected at `order` (the light is final at
    /// once; update() leaves it). Errors: those of reading and projecting the file.
    static Result<LiveProbe> fromFile(const std::filesystem::path& path, lighting::ProbeLayout layout, int order = 6);

    LiveProbe(LiveProbe&&) noexcept;
    LiveProbe& operator=(LiveProbe&&) noexcept;
    ~LiveProbe();

    /// Takes the next frame: on the frames it processes, finds the ball, unwraps and projects it
    /// and smooths the light. Returns whether light() changed. A frame without the ball keeps
    /// the previous light (ball() says why). A frame whose time is not after the previous
    /// processed one (a new source, still pictures at time 0) starts the smoothing again.
    bool update(const VideoFrame& frame);
    /// Forgets the light, the ball and the smoothing (a new camera or video); keeps the last
    /// picture until the next ball replaces it.
    void reset();

    bool fromBall() const;
    const LiveProbeSettings& settings() const;
    /// The light, for render::RenderScene::setLight or render::ScenarioScene::setProbeLight
    /// (channel-major RGB, order² coefficients each, probe frame). order 0 before any light.
    const lighting::ShRgb& light() const;
    bool hasLight() const { return light().order > 0; }
    /// The ball in the last processed frame (fromFile: not found, the reason names the file).
    const BallSighting& ball() const;
    /// The exposure applied to the last light (Automatic: the smoothed one).
    double exposure() const;
    /// Fraction of the ball's samples that were clipped highlights in the last processed frame.
    double clippedFraction() const;
    /// The probe as radiance: the unwrapped ball (mirror-ball layout, probeSize², before the
    /// exposure), or the file's image in its layout. Empty before the first ball.
    const lighting::HdrImage& probeImage() const;
    lighting::ProbeLayout probeLayout() const;
    /// The probe as a lighting::LightProbe (a copy of probeImage(), exposed as the light is),
    /// for ScenarioScene::setProbeLight or a background.
    Result<lighting::LightProbe> probe() const;
    /// What the studio shows: the unwrapped ball as the camera saw it (sRGB, transparent outside
    /// the disc), or a file's lat-long preview. Empty before the first ball.
    const lighting::PreviewImage& picture() const;

private:
    struct State;
    explicit LiveProbe(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

} // namespace thespis::core::ar
