// OsgViewport: an OSG scene drawn in a QOpenGLWidget on a real (virtual) X display with Mesa's
// software GL: the scene shows where the camera looks, dragging orbits, double-click goes home.

#include <QImage>
#include <QTest>

#include <osg/Geode>
#include <osg/Material>
#include <osg/Shape>
#include <osg/ShapeDrawable>

#include "widgets/osg_viewport.h"

using thespis::widgets::OsgViewport;

namespace {

const QColor kClear(40, 44, 52);

// A red box (at the origin unless moved), drawn with fixed-function lighting off so its colour
// is exact.
osg::ref_ptr<osg::Node> redBox(const osg::Vec3& centre = osg::Vec3(0, 0, 0))
{
    osg::ref_ptr<osg::ShapeDrawable> box = new osg::ShapeDrawable(new osg::Box(centre, 1.0f));
    box->setColor(osg::Vec4(1, 0, 0, 1));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(box);
    geode->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return geode;
}

bool isRed(QRgb pixel)
{
    return qRed(pixel) > 200 && qGreen(pixel) < 40 && qBlue(pixel) < 40;
}

int redPixels(const QImage& image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += isRed(image.pixel(x, y)) ? 1 : 0;
    return count;
}

// 320 × 240, the box 5 m in front of the home view.
void showBoxFromTheFront(OsgViewport& viewport)
{
    viewport.resize(320, 240);
    viewport.setClearColor(kClear);
    viewport.setSceneData(redBox());
    viewport.setHomeView(QVector3D(0, 0, 5), QVector3D(0, 0, 0), QVector3D(0, 1, 0));
    viewport.show();
}

} // namespace

class OsgViewportTest : public QObject {
    Q_OBJECT
private slots:
    void drawsTheSceneInFrontOfTheCamera();
    void dragOrbitsAndDoubleClickGoesHome();
    void upIsUpInTheWidgetAndItsGrab();
};

void OsgViewportTest::drawsTheSceneInFrontOfTheCamera()
{
    OsgViewport viewport;
    showBoxFromTheFront(viewport);
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    QVERIFY2(viewport.glErrorText().isEmpty(), qPrintable(viewport.glErrorText()));
    const QImage image = viewport.grabFramebuffer();
    QCOMPARE(image.size(), QSize(320, 240) * viewport.devicePixelRatio());
    QVERIFY(isRed(image.pixel(image.width() / 2, image.height() / 2)));
    const QRgb corner = image.pixel(2, 2);
    QCOMPARE(QColor(corner).rgb(), kClear.rgb());
    // A 1 m box 5 m away in a 30° view covers about (1 / (2·5·tan 15°))² of the height squared.
    const int red = redPixels(image);
    QVERIFY2(red > 2500 && red < 12000, qPrintable(QString::number(red)));
}

void OsgViewportTest::dragOrbitsAndDoubleClickGoesHome()
{
    OsgViewport viewport;
    showBoxFromTheFront(viewport);
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    const QImage home = viewport.grabFramebuffer();

    // Orbit: a left drag turns the box, showing two faces; the red area changes.
    QTest::mousePress(&viewport, Qt::LeftButton, {}, QPoint(160, 120));
    for (int x = 165; x <= 220; x += 5)
        QTest::mouseMove(&viewport, QPoint(x, 110));
    QTest::mouseRelease(&viewport, Qt::LeftButton, {}, QPoint(220, 110));
    const QImage turned = viewport.grabFramebuffer();
    QVERIFY(turned != home);

    QTest::mouseDClick(&viewport, Qt::LeftButton, {}, QPoint(160, 120));
    QCOMPARE(viewport.grabFramebuffer(), home);
}

// A box above the centre of view must appear in the upper half, both in the framebuffer and in
// a grab of the window that holds the widget (what a screenshot shows).
void OsgViewportTest::upIsUpInTheWidgetAndItsGrab()
{
    QWidget window;
    window.resize(320, 240);
    auto* viewport = new OsgViewport(&window);
    viewport->setGeometry(0, 0, 320, 240);
    viewport->setClearColor(kClear);
    viewport->setSceneData(redBox(osg::Vec3(0, 1.8f, 0)));
    // Off the z axis and from above, where OSG's own home position rolls the view over.
    viewport->setHomeView(QVector3D(1.5f, 2.0f, 6), QVector3D(0, 0.5f, 0), QVector3D(0, 1, 0));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    for (const QImage& image : {viewport->grabFramebuffer(), window.grab().toImage()}) {
        int upper = 0, lower = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                (y < image.height() / 2 ? upper : lower) += isRed(image.pixel(x, y)) ? 1 : 0;
        QVERIFY2(upper > 1000 && lower < upper / 10, qPrintable(QStringLiteral("%1 above, %2 below").arg(upper).arg(lower)));
    }
}

QTEST_MAIN(OsgViewportTest)
#include "osg_viewport_test.moc"
