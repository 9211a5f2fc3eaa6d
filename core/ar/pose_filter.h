#pragma once
// The temporal filter of tracked poses: a constant-velocity Kalman filter on SE(3) (an error-state
// filter: translation and velocity, orientation and angular velocity about the target's own axes).
// Each frame's pose comes with its information matrix (tracker.h), so the filter trusts a whole
// board seen face-on more than one marker seen edge-on, and the usual coupling of a planar
// target's tilt with its sideways translation is weighed as it is, not axis by axis. That is what
// makes the filtered pose better than each frame's own estimate, not only smoother. A measurement
// far outside what the filter expects (a mirror-image pose, a wrong marker) is set aside; several
// in a row mean the target really moved, and the filter starts again from them.

#include <array>
#include <optional>

#include "ar/pose.h"

namespace thespis::core::ar {

struct PoseFilterSettings {
    /// How freely a hand-held target or camera changes speed: the strength of the white-noise
    /// acceleration (m/s² and rad/s² per √Hz). Larger follows sudden moves sooner; smaller
    /// averages more frames.
    double linearAcceleration = 0.5;
    double angularAcceleration = 2.0;
    /// Without a measurement for this long (seconds), the next one starts the filter again.
    double forgetAfter = 0.5;
    /// Squared Mahalanobis distance beyond which a measurement is an outlier (χ², 6 degrees
    /// of freedom: 22.5 is the 99.9 % point).
    double outlierDistance = 22.5;
    /// This many outliers in a row restart the filter from the last of them.
    int outliersBeforeRestart = 3;
};

class PoseFilter {
public:
    explicit PoseFilter(PoseFilterSettings settings = {});

    /// Folds in the pose measured at `time` (seconds, increasing) with its information matrix
    /// (row-major 6 × 6 over [translation, rotation]; all zero: unknown, a default is assumed).
    /// Returns the filtered pose.
    TargetPose update(double time, const TargetPose& measured, const std::array<double, 36>& information);
    /// The pose expected at `time` from the motion so far; empty before the first measurement or
    /// after `forgetAfter`.
    std::optional<TargetPose> predict(double time) const;
    void reset();

    bool running() const { return m_running; }
    /// Whether the last measurement was set aside as an outlier.
    bool lastWasOutlier() const { return m_lastOutlier; }
    const PoseFilterSettings& settings() const { return m_settings; }

private:
    void start(double time, const TargetPose& measured, const std::array<double, 36>& covariance);

    PoseFilterSettings m_settings;
    bool m_running = false, m_lastOutlier = false;
    int m_outliers = 0;
    double m_time = 0;
    // The nominal state: position, orientation (unit quaternion w x y z, target → camera),
    // velocity, angular velocity about the target's axes; and the 12 × 12 error covariance.
    std::array<double, 3> m_position{}, m_velocity{}, m_angularVelocity{};
    std::array<double, 4> m_orientation{1, 0, 0, 0};
    std::array<double, 144> m_covariance{};
};

} // namespace thespis::core::ar
