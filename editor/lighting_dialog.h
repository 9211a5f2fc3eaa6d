#pragma once
// LightingDialog: Scene ▸ Lighting… The scenario's light: no probe (the default sky) or an HDR
// light probe file in one of its layouts, turned about the vertical axis and scaled. Two
// pictures show the choice as it will light the scene: the probe itself and the band-limited
// light the characters receive (its SH projection), both turned and exposed alike. A probe that
// cannot be read says why and the light stays as it was. lighting() is the light to set.
// Reading and projecting a probe runs as a job off the GUI thread (ProbeProjectionJob in a
// JobRunner): the dialog stays responsive, and closing it cancels the job.

#include <QDialog>

#include <memory>
#include <optional>

#include "lighting/probe.h"
#include "lighting/sh.h"
#include "scenario/scenario.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSlider;

namespace thespis::editor {

class JobRunner;

class LightingDialog : public QDialog {
    Q_OBJECT
public:
    /// `baseDir`: the scenario's folder, which probe paths are relative to.
    LightingDialog(const QString& baseDir, const core::scenario::LightingSpec& current, QWidget* parent = nullptr);

    /// Uses this probe file (what Browse… does after its file dialog). It is read off the GUI
    /// thread; loaded() tells whether it could be used (if not, the one before stays).
    void setProbeFile(const QString& path);
    /// A probe is being read and projected.
    bool isLoading() const;
    core::scenario::LightingSpec lighting() const;

    QRadioButton* skyChoice() const { return m_sky; }
    QRadioButton* probeChoice() const { return m_probeChoice; }
    QComboBox* layoutChoice() const { return m_layout; }
    QSlider* rotationSlider() const { return m_rotation; }
    QDoubleSpinBox* intensityEdit() const { return m_intensity; }
    QLabel* probePicture() const { return m_probePicture; }
    QLabel* lightPicture() const { return m_lightPicture; }
    QLabel* messageLabel() const { return m_message; }

signals:
    /// A probe finished loading: whether it can be used.
    void loaded(bool ok);

private:
    void load();
    void onProjected(const core::Result<void>& result);
    void updatePictures();

    QString m_baseDir;
    QString m_probePath; ///< absolute; empty: none
    std::optional<QString> m_fallbackPath; ///< the probe to go back to when the one loading fails
    JobRunner* m_projection = nullptr;      ///< child
    bool m_reloadWanted = false;            ///< the choice changed while a probe was loading
    std::optional<core::lighting::LightProbe> m_probe;
    core::lighting::ShRgb m_light;
    double m_exposure = 1;
    QRadioButton* m_sky = nullptr;
    QRadioButton* m_probeChoice = nullptr;
    QLabel* m_file = nullptr;
    QPushButton* m_browse = nullptr;
    QComboBox* m_layout = nullptr;
    QSlider* m_rotation = nullptr;
    QDoubleSpinBox* m_intensity = nullptr;
    QLabel* m_probePicture = nullptr;
    QLabel* m_lightPicture = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
};

} // namespace thespis::editor
