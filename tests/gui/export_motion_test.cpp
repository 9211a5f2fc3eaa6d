// File ▸ Export ▸ Motion… as a user goes, on the demo: Creon (the built-in humanoid) written as a
// glTF character with his motion, with progress; the file read back as a character (as Add
// Character reads it) has his skeleton, a skinned body and his motion at the frame rate asked,
// posed as the studio poses him. "Animation only" with a .bvh name is refused, saying why.
// Screenshot: export_motion_dialog.png.

#include <QAction>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

#include "editor/export_motion_dialog.h"
#include "editor/translations.h"
#include "gui_support.h"
#include "main_window.h"
#include "runtime/stage.h"
#include "scene/gltf_character.h"

using namespace thespis;
using test::saveScreenshot;
using test::whenModal;

class ExportMotionTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void theBuiltInHumanoidGoesOutAsAGltfCharacter();

private:
    QTemporaryDir m_dir;
};

void ExportMotionTest::initTestCase()
{
    editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English));
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

void ExportMotionTest::theBuiltInHumanoidGoesOutAsAGltfCharacter()
{
    studio::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openScenario(QStringLiteral(THESPIS_RESOURCES "/demo.thespis")));
    const QString glb = m_dir.filePath(QStringLiteral("Creon.glb"));

    bool exported = false;
    whenModal<editor::ExportMotionDialog>([&](editor::ExportMotionDialog* dialog) {
        dialog->setCharacter(0);
        dialog->setFrameRate(25);
        dialog->setOutput(m_dir.filePath(QStringLiteral("Creon.bvh")));
        dialog->setAnimationOnly(true);
        QVERIFY(!dialog->exportMotion());
        QVERIFY(dialog->messageLabel()->text().contains(QStringLiteral(".glb")));
        dialog->setAnimationOnly(false);
        dialog->setOutput(glb);
        QTest::mouseClick(dialog->exportButton(), Qt::LeftButton);
        QVERIFY(dialog->isExporting() || dialog->progressBar()->text() == QStringLiteral("Exported"));
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isExporting(), 60000);
        QVERIFY2(dialog->messageLabel()->text().startsWith(QStringLiteral("Wrote ")), qPrintable(dialog->messageLabel()->text()));
        QVERIFY2(dialog->messageLabel()->text().contains(QStringLiteral("301 frames at 25 fps")), // 12 s
                 qPrintable(dialog->messageLabel()->text()));
        QCOMPARE(dialog->progressBar()->text(), QStringLiteral("Exported"));
        saveScreenshot(dialog, QStringLiteral("export_motion_dialog.png"));
        exported = true;
        dialog->reject();
    });
    window.findChild<QAction*>(QStringLiteral("exportMotion"))->trigger();
    QVERIFY(exported);

    // Read back as Add Character reads a model: Creon's joints, a skinned body, his motion.
    auto character = core::scene::loadGltfCharacter(glb.toStdString());
    QVERIFY2(character, character ? "" : character.error().message.c_str());
    const auto& creon = window.session()->stage()->runtime().characters[0];
    QCOMPARE(character->skeleton.jointCount(), creon.skeleton.jointCount());
    QVERIFY(!character->skin.empty());
    QVERIFY(character->mesh.vertexCount() > 1000);
    const core::anim::KeyframeClip* motion = nullptr;
    for (const auto& clip : character->clips)
        if (clip->name() == "Creon")
            motion = clip.get();
    QVERIFY(motion);
    // 12 s long, and at 2 s the pose the studio shows then, joint by joint.
    QVERIFY(std::abs(motion->domain().end - 12.0) < 1e-6);
    core::runtime::Stage stage(window.session()->stage()->runtimeCopy());
    core::runtime::PoseSet poses = stage.makePoseSet();
    stage.evaluate(2 * core::TicksPerSecond, poses);
    std::vector<float> frame(character->skeleton.frameLayout()->floatCount());
    motion->evaluate(2.0, frame);
    const auto joints = std::size_t(creon.skeleton.jointCount());
    std::vector<core::anim::Vec3d> mine(std::size_t(character->skeleton.jointCount())), shown(joints);
    std::vector<core::anim::Quatd> mineTurns(mine.size()), shownTurns(joints);
    character->skeleton.worldTransforms(frame, mine, mineTurns);
    creon.skeleton.worldTransforms(poses.characters[0].body, shown, shownTurns);
    for (std::size_t j = 0; j < joints; ++j) {
        const int k = character->skeleton.find(creon.skeleton.joint(int(j)).name);
        QVERIFY(k >= 0);
        const core::anim::Quatd& a = mineTurns[std::size_t(k)];
        const core::anim::Quatd& b = shownTurns[j];
        const double angle = 2 * std::acos(std::min(1.0, std::abs(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w)));
        QVERIFY2(angle < 1e-4, qPrintable(QString::fromStdString(creon.skeleton.joint(int(j)).name) + QStringLiteral(" ") +
                                          QString::number(angle)));
    }
}

QTEST_MAIN(ExportMotionTest)
#include "export_motion_test.moc"
