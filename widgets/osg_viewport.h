#pragma once
// OsgViewport: a QOpenGLWidget that draws an OpenSceneGraph scene (any osg::Node) with an
// orbiting camera. OSG renders through an embedded graphics window into the widget's own
// framebuffer object, which Qt composites with the other widgets; the default framebuffer is
// set before every frame because Qt may recreate that FBO on resize. The widget knows nothing
// of characters or lighting: editor/ builds the scene and hands its root node over.
//
// Needs an OpenGL 2.1+ compatibility context (Debian's OSG is a compatibility-profile build).
// When none can be made the widget paints a message instead of failing, and glError() says why.

#include <QOpenGLWidget>
#include <QPointF>
#include <QString>
#include <QVector3D>

#include <osg/ref_ptr>

namespace osg {
class Node;
}
namespace osgViewer {
class GraphicsWindowEmbedded;
class Viewer;
}
namespace osgGA {
class OrbitManipulator;
}

namespace thespis::widgets {

class OsgViewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit OsgViewport(QWidget* parent = nullptr);
    ~OsgViewport() override;

    /// Whether this platform can give the widget an OpenGL context at all (the "offscreen" Qt
    /// platform cannot, and Qt crashes flushing a window that holds a QOpenGLWidget there):
    /// callers show something else when it cannot.
    static bool isSupported();

    /// The scene to draw (shared, not copied); null shows only the clear colour. The camera
    /// stays where it is.
    void setSceneData(osg::Node* scene);
    /// Where the camera goes on "home" (double-click, or Home view): eye, target and up vector.
    void setHomeView(const QVector3D& eye, const QVector3D& centre, const QVector3D& up);
    /// Returns the camera to the home view.
    void home();
    /// Moves the camera to look from `eye` at `centre` now (the home view stays as it was).
    void lookAt(const QVector3D& eye, const QVector3D& centre, const QVector3D& up);
    /// Where the camera looks from and at now.
    QVector3D eye() const;
    QVector3D centre() const;
    void setClearColor(const QColor& color);
    /// Vertical field of view in degrees (default 30).
    void setFieldOfView(double degrees);
    double fieldOfView() const { return m_fieldOfView; }

    /// The world-space ray through `position` (widget coordinates, logical pixels) as the camera
    /// sees it now: `origin` on the near plane, `direction` unit length. False when the widget
    /// has no size yet.
    bool rayThrough(const QPointF& position, QVector3D& origin, QVector3D& direction) const;

    /// Empty while the GL context works; otherwise what went wrong, for the status bar.
    QString glErrorText() const { return m_glError; }
    osgViewer::Viewer* viewer() const { return m_viewer.get(); }

signals:
    /// After each drawn frame, with the time OSG took for it (milliseconds).
    void frameDrawn(double milliseconds);
    /// The GL context is missing or too old; the message says which.
    void glError(const QString& message);
    /// A left click (press and release within a few pixels, no orbit drag in between), as the
    /// world-space ray through the clicked point (see rayThrough) and the keys held at release.
    void clicked(const QVector3D& rayOrigin, const QVector3D& rayDirection, Qt::KeyboardModifiers modifiers);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void updateProjection(int width, int height);
    void failGl(const QString& message);

    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> m_window;
    osg::ref_ptr<osgViewer::Viewer> m_viewer;
    osg::ref_ptr<osgGA::OrbitManipulator> m_manipulator;
    QVector3D m_homeEye{0, 1, 4}, m_homeCentre{0, 1, 0}, m_homeUp{0, 1, 0};
    double m_fieldOfView = 30.0;
    QString m_glError;
    // A left press that may still become a click (until the mouse moves too far).
    QPointF m_pressPosition;
    bool m_clickPending = false;
};

} // namespace thespis::widgets
