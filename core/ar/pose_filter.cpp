#include "ar/pose_filter.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace thespis::core::ar {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Gain = Eigen::Matrix<double, 12, 6>;

// Assumed when a tracker gives no information matrix: 2 mm and 0.5° per frame.
constexpr double DefaultPositionNoise = 0.002;
constexpr double DefaultRotationNoise = 0.5 * 3.14159265358979323846 / 180;
// The speeds a newly found target may have: it starts at rest, this uncertain.
constexpr double StartSpeedNoise = 0.5;        // m/s
constexpr double StartAngularSpeedNoise = 2.0; // rad/s

Eigen::Quaterniond fromRodrigues(const std::array<double, 3>& r)
{
    const Eigen::Vector3d axis(r[0], r[1], r[2]);
    const double angle = axis.norm();
    if (angle < 1e-12)
        return Eigen::Quaterniond::Identity();
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis / angle));
}

std::array<double, 3> toRodrigues(const Eigen::Quaterniond& q)
{
    const Eigen::AngleAxisd a(q.normalized());
    const Eigen::Vector3d r = a.axis() * a.angle();
    return {r.x(), r.y(), r.z()};
}

Eigen::Quaterniond expMap(const Eigen::Vector3d& v)
{
    const double angle = v.norm();
    if (angle < 1e-12)
        return Eigen::Quaterniond(1, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z()).normalized();
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

Eigen::Vector3d logMap(const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond shortest = q.w() < 0 ? Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()) : q;
    const Eigen::AngleAxisd a(shortest.normalized());
    return a.axis() * a.angle();
}

// The measurement's covariance from its information matrix (or the default).
Matrix6 measurementCovariance(const std::array<double, 36>& information)
{
    const Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> info(information.data());
    if (info.isZero()) {
        Vector6 variances;
        variances << Eigen::Vector3d::Constant(DefaultPositionNoise * DefaultPositionNoise),
            Eigen::Vector3d::Constant(DefaultRotationNoise * DefaultRotationNoise);
        return variances.asDiagonal();
    }
    // A tiny ridge keeps a nearly singular matrix (few points on a line) invertible.
    const Matrix6 ridged = info + Matrix6::Identity() * (1e-9 * info.diagonal().maxCoeff());
    return ridged.ldlt().solve(Matrix6::Identity());
}

} // namespace

PoseFilter::PoseFilter(PoseFilterSettings settings) : m_settings(settings) {}

void PoseFilter::reset()
{
    m_running = false;
    m_lastOutlier = false;
    m_outliers = 0;
}

void PoseFilter::start(double time, const TargetPose& measured, const std::array<double, 36>& information)
{
    m_running = true;
    m_outliers = 0;
    m_time = time;
    m_position = measured.translation;
    const Eigen::Quaterniond q = fromRodrigues(measured.rotation);
    m_orientation = {q.w(), q.x(), q.y(), q.z()};
    m_velocity = {};
    m_angularVelocity = {};
    Matrix12 p = Matrix12::Zero();
    p.topLeftCorner<6, 6>() = measurementCovariance(information);
    p.block<3, 3>(6, 6) = Eigen::Matrix3d::Identity() * (StartSpeedNoise * StartSpeedNoise);
    p.block<3, 3>(9, 9) = Eigen::Matrix3d::Identity() * (StartAngularSpeedNoise * StartAngularSpeedNoise);
    Eigen::Map<Matrix12>(m_covariance.data()) = p;
}

std::optional<TargetPose> PoseFilter::predict(double time) const
{
    if (!m_running || time - m_time > m_settings.forgetAfter)
        return std::nullopt;
    const double dt = std::max(0.0, time - m_time);
    const Eigen::Quaterniond q(m_orientation[0], m_orientation[1], m_orientation[2], m_orientation[3]);
    const Eigen::Vector3d w(m_angularVelocity.data());
    TargetPose pose;
    pose.rotation = toRodrigues(q * expMap(w * dt));
    for (int i = 0; i < 3; ++i)
        pose.translation[std::size_t(i)] = m_position[std::size_t(i)] + m_velocity[std::size_t(i)] * dt;
    return pose;
}

TargetPose PoseFilter::update(double time, const TargetPose& measured, const std::array<double, 36>& information)
{
    m_lastOutlier = false;
    if (!m_running || time - m_time > m_settings.forgetAfter || time < m_time) {
        start(time, measured, information);
        return measured;
    }
    // Predict: constant velocity over dt, white-noise acceleration feeding the uncertainty.
    const double dt = time - m_time;
    Eigen::Map<Eigen::Vector3d> position(m_position.data()), velocity(m_velocity.data()),
        angularVelocity(m_angularVelocity.data());
    Eigen::Quaterniond orientation(m_orientation[0], m_orientation[1], m_orientation[2], m_orientation[3]);
    Eigen::Map<Matrix12> covariance(m_covariance.data());
    const Eigen::Vector3d predictedPosition = position + velocity * dt;
    const Eigen::Quaterniond predictedOrientation = (orientation * expMap(angularVelocity * dt)).normalized();
    Matrix12 transition = Matrix12::Identity();
    transition.topRightCorner<6, 6>() = Matrix6::Identity() * dt;
    Matrix12 noise = Matrix12::Zero();
    const double a = m_settings.linearAcceleration * m_settings.linearAcceleration;
    const double alpha = m_settings.angularAcceleration * m_settings.angularAcceleration;
    for (int axis = 0; axis < 6; ++axis) {
        const double q = axis < 3 ? a : alpha;
        noise(axis, axis) = q * dt * dt * dt / 3;
        noise(axis, axis + 6) = noise(axis + 6, axis) = q * dt * dt / 2;
        noise(axis + 6, axis + 6) = q * dt;
    }
    const Matrix12 predicted = transition * covariance * transition.transpose() + noise;

    // Update with the measurement: its difference from the prediction, in the error state.
    const Matrix6 r = measurementCovariance(information);
    Vector6 innovation;
    innovation.head<3>() = Eigen::Vector3d(measured.translation.data()) - predictedPosition;
    innovation.tail<3>() = logMap(predictedOrientation.conjugate() * fromRodrigues(measured.rotation));
    const Matrix6 s = predicted.topLeftCorner<6, 6>() + r;
    const Eigen::LDLT<Matrix6> sSolver(s);
    const double distance = innovation.dot(sSolver.solve(innovation));
    if (distance > m_settings.outlierDistance) {
        m_lastOutlier = true;
        if (++m_outliers >= m_settings.outliersBeforeRestart) {
            start(time, measured, information);
            return measured;
        }
        // Keep the prediction; the measurement is set aside.
        m_time = time;
        position = predictedPosition;
        orientation = predictedOrientation;
        m_orientation = {orientation.w(), orientation.x(), orientation.y(), orientation.z()};
        covariance = predicted;
        return *predict(time);
    }
    m_outliers = 0;
    const Gain gain = sSolver.solve(predicted.leftCols<6>().transpose()).transpose(); // P Hᵀ S⁻¹
    const Eigen::Matrix<double, 12, 1> correction = gain * innovation;
    position = predictedPosition + correction.segment<3>(0);
    orientation = (predictedOrientation * expMap(correction.segment<3>(3))).normalized();
    velocity += correction.segment<3>(6);
    angularVelocity += correction.segment<3>(9);
    // Joseph form: stays symmetric and positive definite.
    Matrix12 keep = Matrix12::Identity();
    keep.leftCols<6>() -= gain;
    covariance = keep * predicted * keep.transpose() + gain * r * gain.transpose();
    m_orientation = {orientation.w(), orientation.x(), orientation.y(), orientation.z()};
    m_time = time;
    TargetPose filtered;
    filtered.rotation = toRodrigues(orientation);
    filtered.translation = m_position;
    return filtered;
}

} // namespace thespis::core::ar
