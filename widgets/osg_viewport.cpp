#include "widgets/osg_viewport.h"

#include <QColor>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <osg/Camera>
#include <osg/Node>
#include <osgGA/OrbitManipulator>
#include <osgViewer/GraphicsWindow>
#include <osgViewer/Viewer>

#include <chrono>
#include <cmath>

namespace thespis::widgets {

namespace {

// How far (logical pixels, Manhattan) the mouse may move between press and release of a click;
// further, it is an orbit drag.
constexpr qreal kClickSlop = 4.0;

// OSG numbers mouse buttons 1 (left), 2 (middle), 3 (right).
unsigned osgButton(Qt::MouseButton button)
{
    switch (button) {
    case Qt::LeftButton: return 1;
    case Qt::MiddleButton: return 2;
    case Qt::RightButton: return 3;
    default: return 0;
    }
}

// The rotation taking the camera's axes (x right, y up, z backwards) onto s, u and −f: the
// orbit manipulator's orientation for a camera at `eye` looking at `centre`. Computed here
// (Shepperd's method on the matrix with columns s, u, −f) because OrbitManipulator's own
// setTransformation, through Debian's osg::Matrixd::getRotate, rolls views off the z axis
// upside down.
osg::Quat lookRotation(const osg::Vec3d& eye, const osg::Vec3d& centre, const osg::Vec3d& upHint)
{
    osg::Vec3d f = centre - eye;
    f.normalize();
    osg::Vec3d s = f ^ upHint;
    s.normalize();
    osg::Vec3d u = s ^ f;
    const osg::Vec3d b = -f;
    // m[row][column] with columns s, u, b.
    const double m[3][3] = {{s.x(), u.x(), b.x()}, {s.y(), u.y(), b.y()}, {s.z(), u.z(), b.z()}};
    const double trace = m[0][0] + m[1][1] + m[2][2];
    double x, y, z, w;
    if (trace > 0) {
        const double k = 0.5 / std::sqrt(trace + 1.0);
        w = 0.25 / k;
        x = (m[2][1] - m[1][2]) * k;
        y = (m[0][2] - m[2][0]) * k;
        z = (m[1][0] - m[0][1]) * k;
    } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        const double k = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        w = (m[2][1] - m[1][2]) / k;
        x = 0.25 * k;
        y = (m[0][1] + m[1][0]) / k;
        z = (m[0][2] + m[2][0]) / k;
    } else if (m[1][1] > m[2][2]) {
        const double k = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        w = (m[0][2] - m[2][0]) / k;
        x = (m[0][1] + m[1][0]) / k;
        y = 0.25 * k;
        z = (m[1][2] + m[2][1]) / k;
    } else {
        const double k = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        w = (m[1][0] - m[0][1]) / k;
        x = (m[0][2] + m[2][0]) / k;
        y = (m[1][2] + m[2][1]) / k;
        z = 0.25 * k;
    }
    return osg::Quat(x, y, z, w);
}

} // namespace

OsgViewport::OsgViewport(QWidget* parent) : QOpenGLWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    m_window = new osgViewer::GraphicsWindowEmbedded(0, 0, width(), height());
    // Qt's y grows downwards; OSG's manipulators expect to be told.
    m_window->getEventQueue()->getCurrentEventState()->setMouseYOrientation(
        osgGA::GUIEventAdapter::Y_INCREASING_DOWNWARDS);
    m_viewer = new osgViewer::Viewer;
    m_viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    // Frames are drawn when Qt asks (paintGL), never by the viewer's own loop.
    m_viewer->setRunFrameScheme(osgViewer::ViewerBase::ON_DEMAND);
    m_viewer->setKeyEventSetsDone(0);
    osg::Camera* camera = m_viewer->getCamera();
    camera->setGraphicsContext(m_window.get());
    camera->setViewport(0, 0, width(), height());
    camera->setClearColor(osg::Vec4(0.16f, 0.17f, 0.19f, 1.0f));
    m_manipulator = new osgGA::OrbitManipulator;
    m_manipulator->setAllowThrow(false);
    m_viewer->setCameraManipulator(m_manipulator.get(), false);
    updateProjection(width(), height());
}

bool OsgViewport::isSupported()
{
    QOpenGLContext probe;
    return probe.create();
}

OsgViewport::~OsgViewport()
{
    // Release OSG's GL objects while the widget's context still exists.
    if (context() && m_glError.isEmpty()) {
        makeCurrent();
        m_viewer->setSceneData(nullptr);
        m_viewer = nullptr;
        doneCurrent();
    }
}

void OsgViewport::setSceneData(osg::Node* scene)
{
    // OSG sends the manipulator home on a new scene; the user's view stays where it was.
    const osg::Vec3d centre = m_manipulator->getCenter();
    const double distance = m_manipulator->getDistance();
    const osg::Quat rotation = m_manipulator->getRotation();
    m_viewer->setSceneData(scene);
    m_manipulator->setCenter(centre);
    m_manipulator->setDistance(distance);
    m_manipulator->setRotation(rotation);
    update();
}

void OsgViewport::setHomeView(const QVector3D& eye, const QVector3D& centre, const QVector3D& up)
{
    m_homeEye = eye;
    m_homeCentre = centre;
    m_homeUp = up;
    home();
}

void OsgViewport::home()
{
    lookAt(m_homeEye, m_homeCentre, m_homeUp);
}

void OsgViewport::lookAt(const QVector3D& eyeAt, const QVector3D& centreAt, const QVector3D& up)
{
    const osg::Vec3d eye(eyeAt.x(), eyeAt.y(), eyeAt.z());
    const osg::Vec3d centre(centreAt.x(), centreAt.y(), centreAt.z());
    m_manipulator->setCenter(centre);
    m_manipulator->setDistance((centre - eye).length());
    m_manipulator->setRotation(lookRotation(eye, centre, osg::Vec3d(up.x(), up.y(), up.z())));
    update();
}

QVector3D OsgViewport::eye() const
{
    osg::Vec3d eye, centre, up;
    m_manipulator->getInverseMatrix().getLookAt(eye, centre, up);
    return QVector3D(float(eye.x()), float(eye.y()), float(eye.z()));
}

QVector3D OsgViewport::centre() const
{
    const osg::Vec3d centre = m_manipulator->getCenter();
    return QVector3D(float(centre.x()), float(centre.y()), float(centre.z()));
}

void OsgViewport::setClearColor(const QColor& color)
{
    m_viewer->getCamera()->setClearColor(
        osg::Vec4(float(color.redF()), float(color.greenF()), float(color.blueF()), 1.0f));
    update();
}

void OsgViewport::setFieldOfView(double degrees)
{
    m_fieldOfView = degrees;
    updateProjection(width(), height());
    update();
}

bool OsgViewport::rayThrough(const QPointF& position, QVector3D& origin, QVector3D& direction) const
{
    const osg::Camera* camera = m_viewer->getCamera();
    const osg::Viewport* viewport = camera->getViewport();
    if (!viewport || viewport->width() <= 0 || viewport->height() <= 0)
        return false;
    // The GL viewport covers the widget in device pixels; OSG's y grows upwards.
    const qreal ratio = devicePixelRatio();
    const double x = 2.0 * (position.x() * ratio - viewport->x()) / viewport->width() - 1.0;
    const double y = 1.0 - 2.0 * (position.y() * ratio - viewport->y()) / viewport->height();
    // The manipulator's view is what the camera shows (the viewer copies it every frame); it is
    // also right between a home() and the next frame. The projection's near and far planes,
    // which OSG adjusts while culling, do not move the ray.
    const osg::Matrixd inverse =
        osg::Matrixd::inverse(m_manipulator->getInverseMatrix() * camera->getProjectionMatrix());
    const osg::Vec3d nearPoint = osg::Vec3d(x, y, -1.0) * inverse;
    const osg::Vec3d farPoint = osg::Vec3d(x, y, 1.0) * inverse;
    osg::Vec3d along = farPoint - nearPoint;
    if (!(along.length() > 0) || !nearPoint.valid())
        return false;
    along.normalize();
    origin = QVector3D(float(nearPoint.x()), float(nearPoint.y()), float(nearPoint.z()));
    direction = QVector3D(float(along.x()), float(along.y()), float(along.z()));
    return true;
}

void OsgViewport::failGl(const QString& message)
{
    m_glError = message;
    emit glError(message);
}

void OsgViewport::initializeGL()
{
    QOpenGLContext* gl = context();
    if (!gl || !gl->isValid()) {
        failGl(tr("No OpenGL context could be created for the 3D view."));
        return;
    }
    const QSurfaceFormat format = gl->format();
    if (format.profile() == QSurfaceFormat::CoreProfile) {
        failGl(tr("The 3D view got a core-profile OpenGL context; it needs a compatibility profile."));
        return;
    }
    if (!gl->isOpenGLES() && format.version() < qMakePair(2, 1)) {
        failGl(tr("The 3D view needs OpenGL 2.1 or newer; this system offers %1.%2.")
                   .arg(format.majorVersion())
                   .arg(format.minorVersion()));
        return;
    }
    m_viewer->realize();
}

void OsgViewport::updateProjection(int width, int height)
{
    const double aspect = height > 0 ? double(width) / height : 1.0;
    m_viewer->getCamera()->setProjectionMatrixAsPerspective(m_fieldOfView, aspect, 0.05, 200.0);
}

void OsgViewport::resizeGL(int width, int height)
{
    const qreal ratio = devicePixelRatio();
    const int pixelWidth = int(width * ratio);
    const int pixelHeight = int(height * ratio);
    m_window->resized(0, 0, pixelWidth, pixelHeight);
    m_window->getEventQueue()->windowResize(0, 0, pixelWidth, pixelHeight);
    m_viewer->getCamera()->setViewport(0, 0, pixelWidth, pixelHeight);
    updateProjection(pixelWidth, pixelHeight);
}

void OsgViewport::paintGL()
{
    if (!m_glError.isEmpty())
        return;
    // Qt may have recreated its framebuffer object since the last frame.
    m_window->setDefaultFboId(defaultFramebufferObject());
    const auto start = std::chrono::steady_clock::now();
    m_viewer->frame();
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    emit frameDrawn(spent.count());
}

void OsgViewport::paintEvent(QPaintEvent* event)
{
    if (m_glError.isEmpty()) {
        QOpenGLWidget::paintEvent(event);
        return;
    }
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    painter.setPen(palette().text().color());
    painter.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, m_glError);
}

void OsgViewport::mousePressEvent(QMouseEvent* event)
{
    // A click is the left button alone; any other button pressed meanwhile makes it a drag.
    m_clickPending = event->button() == Qt::LeftButton && event->buttons() == Qt::LeftButton;
    m_pressPosition = event->position();
    const qreal ratio = devicePixelRatio();
    m_window->getEventQueue()->mouseButtonPress(float(event->position().x() * ratio),
                                                float(event->position().y() * ratio), osgButton(event->button()));
    update();
}

void OsgViewport::mouseReleaseEvent(QMouseEvent* event)
{
    const qreal ratio = devicePixelRatio();
    m_window->getEventQueue()->mouseButtonRelease(float(event->position().x() * ratio),
                                                  float(event->position().y() * ratio), osgButton(event->button()));
    update();
    const bool click = m_clickPending && event->button() == Qt::LeftButton
                       && (event->position() - m_pressPosition).manhattanLength() <= kClickSlop;
    m_clickPending = false;
    QVector3D origin, direction;
    if (click && rayThrough(event->position(), origin, direction))
        emit clicked(origin, direction, event->modifiers());
}

void OsgViewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_clickPending && (event->position() - m_pressPosition).manhattanLength() > kClickSlop)
        m_clickPending = false;
    const qreal ratio = devicePixelRatio();
    m_window->getEventQueue()->mouseMotion(float(event->position().x() * ratio), float(event->position().y() * ratio));
    update();
}

void OsgViewport::mouseDoubleClickEvent(QMouseEvent*)
{
    home();
}

void OsgViewport::wheelEvent(QWheelEvent* event)
{
    m_window->getEventQueue()->mouseScroll(event->angleDelta().y() > 0 ? osgGA::GUIEventAdapter::SCROLL_UP
                                                                       : osgGA::GUIEventAdapter::SCROLL_DOWN);
    update();
}

} // namespace thespis::widgets
