// The segment tag editor (SegmentPanel) on the demo scenario, next to a real 3D viewport on a
// virtual X display: the table lists each body's segments with their joints; three rows tagged
// Receiver at once are one undo step (undo brings the tags back, redo again); a Role cell edits
// through its combo box as one step; a click on a character's head in the viewport selects that
// row (switching the character) and tints the head orange in the picture, Ctrl toggles, a click
// on nothing clears, and an orbit drag selects nothing but still turns the camera. The panel
// also works with no viewport at all. Screenshots: segment_panel.png, segment_window.png.

#include <QComboBox>
#include <QDir>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <osg/Camera>
#include <osgViewer/Viewer>

#include <algorithm>
#include <memory>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/scene_preview.h"
#include "editor/session.h"
#include "editor/segment_panel.h"
#include "editor/segment_table_model.h"
#include "render/scenario_scene.h"
#include "scenario/scenario_character.h"
#include "widgets/osg_viewport.h"

using namespace thespis;
using core::scene::SegmentRole;
using core::scene::SegmentTag;
using editor::SegmentTableModel;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

std::unique_ptr<editor::Document> openDemo()
{
    auto document = editor::Document::open(demoPath());
    if (!document) {
        qWarning("%s", document.error().message.c_str());
        return nullptr;
    }
    return std::move(document).value();
}

// The panel next to a 3D view of the same document, in one shown window.
struct Studio {
    QWidget window;
    widgets::OsgViewport* viewport = nullptr;
    editor::SegmentPanel* panel = nullptr;
    editor::PlaybackClock clock;
    editor::Session session{&clock}; // owns the document, as the studio's does
    std::unique_ptr<editor::ScenePreview> preview;
    editor::Document* document = nullptr;

    bool open()
    {
        window.resize(1180, 640);
        auto* layout = new QHBoxLayout(&window);
        layout->setContentsMargins(0, 0, 0, 0);
        viewport = new widgets::OsgViewport(&window);
        layout->addWidget(viewport, 1);
        panel = new editor::SegmentPanel(&window);
        panel->setFixedWidth(540);
        layout->addWidget(panel);
        preview = std::make_unique<editor::ScenePreview>(viewport);
        auto opened = openDemo();
        if (!opened)
            return false;
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return false;
        // As the studio does: the view follows every document, edit, undo and redo.
        preview->setSession(&session);
        session.setDocument(std::move(opened));
        document = session.document();
        if (!preview->problem().isEmpty()) {
            qWarning("%s", qPrintable(preview->problem()));
            return false;
        }
        panel->setDocument(document);
        panel->setScenePreview(preview.get());
        QSignalSpy frames(viewport, &widgets::OsgViewport::frameDrawn);
        viewport->update();
        return frames.wait(5000);
    }

    core::render::CharacterNode& node(int character) const
    {
        return preview->scene()->scene().character(std::size_t(character));
    }
};

int segmentRow(const editor::SegmentPanel& panel, const char* name)
{
    return panel.model()->rowOf(QString::fromUtf8(name));
}

// Centre of a segment's posed bounding box.
// The centre of a segment's posed bounding box; with `lowerPart` < 1, of the box of its vertices
// in that lower part of its height (a head's face, below the hair).
QVector3D posedCentre(const core::render::CharacterNode& node, int segment, float lowerPart = 1.0f)
{
    const core::scene::Segment& s = node.character().mesh.segments[std::size_t(segment)];
    const auto box = [&](float below) {
        QVector3D low(1e9f, 1e9f, 1e9f), high(-1e9f, -1e9f, -1e9f);
        for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v) {
            const auto& p = node.posedPositions()[v];
            if (p.y > below)
                continue;
            low = QVector3D(std::min(low.x(), p.x), std::min(low.y(), p.y), std::min(low.z(), p.z));
            high = QVector3D(std::max(high.x(), p.x), std::max(high.y(), p.y), std::max(high.z(), p.z));
        }
        return std::pair{low, high};
    };
    const auto [low, high] = box(1e9f);
    if (lowerPart >= 1.0f)
        return (low + high) / 2;
    const auto [partLow, partHigh] = box(low.y() + lowerPart * (high.y() - low.y()));
    return (partLow + partHigh) / 2;
}

// Where a world point appears in the widget (logical pixels), through the OSG camera as it last
// drew: view × projection × the viewport's window matrix (y up, device pixels).
QPoint toWidget(const widgets::OsgViewport& viewport, const QVector3D& point)
{
    const osg::Camera* camera = viewport.viewer()->getCamera();
    const osg::Matrixd matrix =
        camera->getViewMatrix() * camera->getProjectionMatrix() * camera->getViewport()->computeWindowMatrix();
    const osg::Vec3d window = osg::Vec3d(point.x(), point.y(), point.z()) * matrix;
    const double ratio = viewport.devicePixelRatio();
    return QPoint(int(std::lround(window.x() / ratio)), int(std::lround((camera->getViewport()->height() - window.y()) / ratio)));
}

// Distance from a point to a ray's line.
double distanceToRay(const QVector3D& point, const QVector3D& origin, const QVector3D& direction)
{
    const QVector3D d = direction.normalized();
    const QVector3D offset = point - origin;
    return double((offset - d * QVector3D::dotProduct(offset, d)).length());
}

std::vector<SegmentTag> tagsOf(const editor::Document& document, int character)
{
    return document.scenario().characters[std::size_t(character)].segmentTags;
}

QRgb framebufferPixel(widgets::OsgViewport& viewport, QPoint at)
{
    const QImage image = viewport.grabFramebuffer();
    const qreal ratio = viewport.devicePixelRatio();
    return image.pixel(int(at.x() * ratio), int(at.y() * ratio));
}

} // namespace

class SegmentPanelTest : public QObject {
    Q_OBJECT
private slots:
    void listsTheBodysSegmentsWithTheirJoints();
    void bulkTagIsOneUndoableEdit();
    void cellEditThroughTheComboIsOneEdit();
    void clickInTheViewportSelectsAndHighlights();
    void dragOrbitsAndSelectsNothing();
    void worksWithoutAViewport();
};

void SegmentPanelTest::listsTheBodysSegmentsWithTheirJoints()
{
    Studio studio;
    QVERIFY(studio.open());
    editor::SegmentPanel& panel = *studio.panel;
    QCOMPARE(panel.characterCombo()->count(), 2);
    QCOMPARE(panel.characterCombo()->itemText(0), QStringLiteral("Creon"));
    QCOMPARE(panel.currentCharacter(), 0);
    QVERIFY(panel.message().isEmpty());

    // The rows are the rendered body's segments, in order, with their joints and sizes.
    const core::scene::Character& body = studio.node(0).character();
    const QAbstractItemModel* model = panel.table()->model();
    QCOMPARE(model->rowCount(), int(body.mesh.segments.size()));
    QVERIFY(model->rowCount() > 15);
    for (int row = 0; row < model->rowCount(); ++row) {
        const core::scene::Segment& segment = body.mesh.segments[std::size_t(row)];
        QCOMPARE(model->index(row, SegmentTableModel::SegmentColumn).data().toString(), QString::fromStdString(segment.name));
        QCOMPARE(model->index(row, SegmentTableModel::JointColumn).data().toString(),
                 segment.joint.empty() ? QStringLiteral("(root)") : QString::fromStdString(segment.joint));
        QCOMPARE(model->index(row, SegmentTableModel::TrianglesColumn).data(Qt::EditRole).toULongLong(),
                 qulonglong(segment.triangleCount));
        QCOMPARE(model->index(row, SegmentTableModel::RoleColumn).data().toString(), QStringLiteral("None"));
    }
    const int skull = segmentRow(panel, "skull");
    QVERIFY(skull >= 0);
    QCOMPARE(model->index(skull, SegmentTableModel::JointColumn).data().toString(), QStringLiteral("skullbase"));
    // No column the bake would not read: segment, joint, role and the two sizes.
    QCOMPARE(model->columnCount(), 5);
    QCOMPARE(model->headerData(SegmentTableModel::RoleColumn, Qt::Horizontal).toString(), QStringLiteral("Role"));

    // The other character, and the filter.
    panel.setCurrentCharacter(1);
    QCOMPARE(panel.currentCharacter(), 1);
    QCOMPARE(model->rowCount(), int(studio.node(1).character().mesh.segments.size()));
    panel.filterEdit()->setText(QStringLiteral("forearm"));
    int shown = 0;
    for (int row = 0; row < model->rowCount(); ++row)
        shown += panel.table()->isRowHidden(row) ? 0 : 1;
    QCOMPARE(shown, 2);
    panel.filterEdit()->clear();

    // Losing the document empties everything.
    panel.setDocument(nullptr);
    QCOMPARE(model->rowCount(), 0);
    QCOMPARE(panel.characterCombo()->count(), 0);
    QCOMPARE(panel.currentCharacter(), -1);
}

void SegmentPanelTest::bulkTagIsOneUndoableEdit()
{
    Studio studio;
    QVERIFY(studio.open());
    editor::SegmentPanel& panel = *studio.panel;
    editor::Document& document = *studio.document;
    QTableView* table = panel.table();
    const std::vector<SegmentTag> before = tagsOf(document, 0);
    const int steps = document.undoStack()->count();

    // Three rows picked with the mouse: a click, then two Ctrl-clicks.
    const int rows[] = {segmentRow(panel, "skull"), segmentRow(panel, "l_forearm"), segmentRow(panel, "r_forearm")};
    for (int row : rows)
        QVERIFY(row >= 0);
    auto rowPoint = [&](int row) {
        table->scrollTo(table->model()->index(row, 0));
        return table->visualRect(table->model()->index(row, SegmentTableModel::SegmentColumn)).center();
    };
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, rowPoint(rows[0]));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::ControlModifier, rowPoint(rows[1]));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::ControlModifier, rowPoint(rows[2]));
    std::vector<int> expected(std::begin(rows), std::end(rows));
    std::sort(expected.begin(), expected.end());
    QCOMPARE(panel.selectedSegments(), expected);
    // Selected rows are highlighted in the view, and only those.
    for (std::size_t s = 0; s < studio.node(0).segmentCount(); ++s)
        QCOMPARE(studio.node(0).segmentHighlighted(s), std::find(expected.begin(), expected.end(), int(s)) != expected.end());

    auto* receiver = panel.findChild<QToolButton*>(QStringLiteral("tagReceiver"));
    QVERIFY(receiver && receiver->isEnabled());
    QVERIFY(!receiver->isChecked());
    QTest::mouseClick(receiver, Qt::LeftButton);
    QCOMPARE(document.undoStack()->count(), steps + 1);
    QVERIFY(receiver->isChecked());
    std::vector<SegmentTag> tags = tagsOf(document, 0);
    QCOMPARE(tags.size(), std::size_t(3));
    for (int row : rows) {
        const std::string name = panel.model()->segmentName(row).toStdString();
        const auto tag = std::find_if(tags.begin(), tags.end(), [&](const SegmentTag& t) { return t.segment == name; });
        QVERIFY2(tag != tags.end(), name.c_str());
        QCOMPARE(tag->role, SegmentRole::Receiver);
        QCOMPARE(table->model()->index(row, SegmentTableModel::RoleColumn).data().toString(), QStringLiteral("Receiver"));
    }
    QCOMPARE(panel.selectedSegments(), expected); // the selection survives the edit
    // … and so does its highlight, whether or not the view rebuilt the scene for the new tags.
    for (std::size_t s = 0; s < studio.node(0).segmentCount(); ++s)
        QCOMPARE(studio.node(0).segmentHighlighted(s), std::find(expected.begin(), expected.end(), int(s)) != expected.end());

    // Applying what is already there pushes nothing.
    panel.applyRole(SegmentRole::Receiver);
    QCOMPARE(document.undoStack()->count(), steps + 1);

    document.undoStack()->undo();
    QCOMPARE(tagsOf(document, 0), before);
    for (int row : rows)
        QCOMPARE(table->model()->index(row, SegmentTableModel::RoleColumn).data().toString(), QStringLiteral("None"));
    QVERIFY(!receiver->isChecked());
    document.undoStack()->redo();
    QCOMPARE(tagsOf(document, 0), tags);
    QCOMPARE(table->model()->index(rows[0], SegmentTableModel::RoleColumn).data().toString(), QStringLiteral("Receiver"));

    // Tagging back to None removes the tags.
    panel.applyRole(SegmentRole::None);
    QVERIFY(tagsOf(document, 0).empty());
    saveScreenshot(&panel, QStringLiteral("segment_panel_none.png"));
}

void SegmentPanelTest::cellEditThroughTheComboIsOneEdit()
{
    Studio studio;
    QVERIFY(studio.open());
    editor::SegmentPanel& panel = *studio.panel;
    editor::Document& document = *studio.document;
    const int steps = document.undoStack()->count();
    const int hair = segmentRow(panel, "hair");
    QVERIFY(hair >= 0);
    const QModelIndex cell = panel.table()->model()->index(hair, SegmentTableModel::RoleColumn);
    panel.table()->scrollTo(cell);
    panel.table()->edit(cell);
    auto* combo = panel.table()->findChild<QComboBox*>(QStringLiteral("segmentTagEditor"));
    QVERIFY(combo);
    QCOMPARE(combo->currentText(), QStringLiteral("None"));
    const int occluder = combo->findData(int(SegmentRole::Occluder));
    QVERIFY(occluder >= 0);
    combo->setCurrentIndex(occluder);
    emit combo->activated(occluder);
    QCOMPARE(document.undoStack()->count(), steps + 1);
    QCOMPARE(tagsOf(document, 0), (std::vector<SegmentTag>{{"hair", SegmentRole::Occluder}}));
    QCOMPARE(cell.data().toString(), QStringLiteral("Occluder"));
    QTRY_VERIFY(!panel.table()->findChild<QComboBox*>(QStringLiteral("segmentTagEditor")));
    QCOMPARE(document.undoStack()->count(), steps + 1); // closing the editor added nothing
    // And the model itself, as a script or another view would.
    QVERIFY(panel.table()->model()->setData(cell, int(SegmentRole::Receiver)));
    QCOMPARE(document.undoStack()->count(), steps + 2);
    QCOMPARE(tagsOf(document, 0), (std::vector<SegmentTag>{{"hair", SegmentRole::Receiver}}));
    // Only the role is editable.
    QVERIFY(!(panel.table()->model()->flags(panel.table()->model()->index(hair, SegmentTableModel::JointColumn))
              & Qt::ItemIsEditable));
}

void SegmentPanelTest::clickInTheViewportSelectsAndHighlights()
{
    Studio studio;
    QVERIFY(studio.open());
    editor::SegmentPanel& panel = *studio.panel;
    widgets::OsgViewport& viewport = *studio.viewport;
    QCOMPARE(panel.currentCharacter(), 0);

    // Antigone's face, where the camera shows it (below the hair, whichever way the idle tilts
    // her head): a click there selects her skull.
    const int character = 1;
    const int skull = segmentRow(panel, "skull"); // same body layout for both characters
    const QVector3D head = posedCentre(studio.node(character), skull, 0.5f);
    const QPoint at = toWidget(viewport, head);
    QVERIFY2(viewport.rect().contains(at), qPrintable(QStringLiteral("%1, %2").arg(at.x()).arg(at.y())));
    const QRgb plain = framebufferPixel(viewport, at);

    QSignalSpy clicks(&viewport, &widgets::OsgViewport::clicked);
    QTest::mouseClick(&viewport, Qt::LeftButton, {}, at);
    QCOMPARE(clicks.count(), 1);
    // The ray goes through the head's centre (within the half pixel of rounding).
    const QVector3D origin = clicks.at(0).at(0).value<QVector3D>();
    const QVector3D direction = clicks.at(0).at(1).value<QVector3D>();
    QVERIFY2(distanceToRay(head, origin, direction) < 0.01, qPrintable(QString::number(distanceToRay(head, origin, direction))));
    QVERIFY(std::abs(direction.length() - 1.0f) < 1e-4f);

    QCOMPARE(panel.currentCharacter(), character);
    QCOMPARE(panel.characterCombo()->currentIndex(), character);
    QCOMPARE(panel.selectedSegments(), std::vector<int>{skull});
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(skull)));
    for (std::size_t s = 0; s < studio.node(0).segmentCount(); ++s)
        QVERIFY(!studio.node(0).segmentHighlighted(s));

    // The picture shows it: the head turned towards orange.
    QTest::qWait(50);
    const QRgb tinted = framebufferPixel(viewport, at);
    QVERIFY2(qRed(tinted) - qBlue(tinted) > qRed(plain) - qBlue(plain) + 25,
             qPrintable(QStringLiteral("before %1, after %2").arg(QColor(plain).name(), QColor(tinted).name())));
    saveScreenshot(&studio.window, QStringLiteral("segment_window.png"));
    {
        // A close-up of the highlighted head, for people to judge the tint.
        const qreal ratio = viewport.devicePixelRatio();
        const QImage frame = viewport.grabFramebuffer();
        const QRect around(int((at.x() - 60) * ratio), int((at.y() - 60) * ratio), int(120 * ratio), int(120 * ratio));
        QVERIFY(frame.copy(around).scaled(360, 360).save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/segment_highlight_closeup.png")));
    }
    saveScreenshot(studio.panel, QStringLiteral("segment_panel.png"));

    // Ctrl adds another segment (the chest), Ctrl on the head again takes it away.
    const int chest = segmentRow(panel, "t1") >= 0 ? segmentRow(panel, "t1") : segmentRow(panel, "l1");
    QVERIFY(chest >= 0);
    const QPoint chestAt = toWidget(viewport, posedCentre(studio.node(character), chest));
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, chestAt);
    {
        QTest::qWait(50);
        const qreal ratio = viewport.devicePixelRatio();
        const QImage frame = viewport.grabFramebuffer();
        const QRect around(int((at.x() - 80) * ratio), int((at.y() - 30) * ratio), int(160 * ratio), int(160 * ratio));
        QVERIFY(frame.copy(around).scaled(400, 400).save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/segment_highlight_two.png")));
    }
    const auto hit = studio.preview->pickSegment(origin, direction);
    QVERIFY(hit && hit->character == character && hit->segment == skull);
    QCOMPARE(panel.selectedSegments().size(), std::size_t(2));
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(skull)));
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, at);
    QCOMPARE(panel.selectedSegments().size(), std::size_t(1));
    QVERIFY(!studio.node(character).segmentHighlighted(std::size_t(skull)));

    // A click on nothing (the top corner, above everyone) clears the selection.
    QTest::mouseClick(&viewport, Qt::LeftButton, {}, QPoint(5, 5));
    QVERIFY(panel.selectedSegments().empty());
    for (std::size_t s = 0; s < studio.node(character).segmentCount(); ++s)
        QVERIFY(!studio.node(character).segmentHighlighted(s));

    // Hiding the panel takes the tint away; showing it again brings the selection back.
    panel.selectSegments({skull});
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(skull)));
    panel.hide();
    QVERIFY(!studio.node(character).segmentHighlighted(std::size_t(skull)));
    panel.show();
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(skull)));
    // A rebuilt scene keeps the highlight: the session says its stage was made anew (as after
    // an edit of the cast), and the 3D view builds its scene again.
    QSignalSpy built(studio.preview.get(), &editor::ScenePreview::sceneBuilt);
    emit studio.session.edited(true);
    QCOMPARE(built.count(), 1);
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(skull)));

    // The paper's example (Fig. 14): the hair a receiver; then the left arm selected, for the picture.
    panel.selectSegments({segmentRow(panel, "hair")});
    panel.applyRole(SegmentRole::Receiver);
    panel.selectSegments({segmentRow(panel, "l_upperarm"), segmentRow(panel, "l_forearm"), segmentRow(panel, "l_carpal")});
    QCOMPARE(tagsOf(*studio.document, character).size(), std::size_t(1));
    QVERIFY(studio.node(character).segmentHighlighted(std::size_t(segmentRow(panel, "l_forearm"))));
    saveScreenshot(&studio.window, QStringLiteral("segment_window_tagged.png"));
}

void SegmentPanelTest::dragOrbitsAndSelectsNothing()
{
    Studio studio;
    QVERIFY(studio.open());
    editor::SegmentPanel& panel = *studio.panel;
    widgets::OsgViewport& viewport = *studio.viewport;
    const int skull = segmentRow(panel, "skull");
    const QPoint at = toWidget(viewport, posedCentre(studio.node(1), skull));
    const osg::Matrixd viewBefore = viewport.viewer()->getCamera()->getViewMatrix();

    QSignalSpy clicks(&viewport, &widgets::OsgViewport::clicked);
    QTest::mousePress(&viewport, Qt::LeftButton, {}, at);
    for (int i = 1; i <= 8; ++i)
        QTest::mouseMove(&viewport, at + QPoint(8 * i, 2 * i));
    QTest::mouseRelease(&viewport, Qt::LeftButton, {}, at + QPoint(64, 16));
    QTest::qWait(50);
    QCOMPARE(clicks.count(), 0);
    QVERIFY(panel.selectedSegments().empty());
    QCOMPARE(panel.currentCharacter(), 0);
    QVERIFY(viewport.viewer()->getCamera()->getViewMatrix() != viewBefore); // it orbited

    // A press and release a few pixels apart is still a click.
    QTest::mousePress(&viewport, Qt::LeftButton, {}, QPoint(5, 5));
    QTest::mouseMove(&viewport, QPoint(7, 6));
    QTest::mouseRelease(&viewport, Qt::LeftButton, {}, QPoint(7, 6));
    QCOMPARE(clicks.count(), 1);
}

void SegmentPanelTest::worksWithoutAViewport()
{
    auto document = openDemo();
    QVERIFY(document);
    editor::SegmentPanel panel;
    panel.resize(540, 600);
    panel.setDocument(document.get());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto body = core::scenario::loadCharacterBody(document->scenario(), 1, editor::toFsPath(document->baseDir()));
    QVERIFY(body.ok());
    panel.setCurrentCharacter(1);
    QCOMPARE(panel.table()->model()->rowCount(), int(body->mesh.segments.size()));
    panel.selectSegments({0, 1});
    QCOMPARE(panel.selectedSegments(), (std::vector<int>{0, 1}));
    panel.applyRole(SegmentRole::Occluder);
    QCOMPARE(tagsOf(*document, 1).size(), std::size_t(2));
    QCOMPARE(tagsOf(*document, 1)[0].role, SegmentRole::Occluder);
    QVERIFY(tagsOf(*document, 0).empty());
    QVERIFY(panel.message().isEmpty());
}

QTEST_MAIN(SegmentPanelTest)
#include "segment_panel_test.moc"
