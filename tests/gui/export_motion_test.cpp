// File ▸ Export Motion… as a user goes, on the demo: Creon (the built-in humanoid) written as a
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
    for (int j = 0; j < creon.skeleton.jointCount(); ++j) {
        const int mine = character->skeleton.find(creon.skeleton.joint(j).name);
        QVERIFY(mine >= 0);
        const auto& a = core::anim::rotationAt(std::span<const float>(frame), mine);
        const auto& b = core::anim::rotationAt(std::span<const float>(poses.characters[0].body), j);
        const double dot = std::abs(double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z + double(a.w) * b.w);
        // The bake evaluates the schedule as thespis-cli does (the CLI test holds the file to it
        // within 1e-4 rad); the stage's blend differs from it by under a milliradian at the pelvis.
        QVERIFY2(2 * std::acos(std::min(1.0, dot)) < 2e-3, qPrintable(QString::fromStdString(creon.skeleton.joint(j).name) + QStringLiteral(" ") + QString::number(2 * std::acos(std::min(1.0, dot)))));
    }
}

QTEST_MAIN(ExportMotionTest)
#include "export_motion_test.moc"
