// Our own bridge between Qt 6 and VTK 9.1 (Debian's libvtk9-qt is built for
// Qt 5: never used): a QOpenGLWidget driving a vtkGenericOpenGLRenderWindow
// (shared/notes/platform.md). VTK renders into its own framebuffer; paintGL
// blits it into the widget's defaultFramebufferObject() (VTK's own blit is
// off); VTK's GL state cache is reset each paint; mouse, wheel and key events
// go to a vtkGenericRenderWindowInteractor whose render requests call
// update(). Call setDefaultSurfaceFormat() before QApplication exists.
#pragma once

#include <QOpenGLWidget>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkCallbackCommand;

namespace k528::studio::backplot {

class VtkGlWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit VtkGlWidget(QWidget* parent = nullptr);
    ~VtkGlWidget() override;
    static void setDefaultSurfaceFormat(); // OpenGL 3.2 core, before QApplication

    vtkGenericOpenGLRenderWindow* renderWindow() const { return window_; }
    vtkGenericRenderWindowInteractor* interactor() const { return interactor_; }
    // Frames painted so far (benchmarks).
    long framesPainted() const { return frames_; }

signals:
    void sizeChanged(int widthPx, int heightPx);
    void interactionStarted();
    void interactionEnded();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    void forwardMouse(QMouseEvent* e, unsigned long event);
    vtkGenericOpenGLRenderWindow* window_ = nullptr;
    vtkGenericRenderWindowInteractor* interactor_ = nullptr;
    vtkCallbackCommand* callback_ = nullptr;
    long frames_ = 0;
};

} // namespace k528::studio::backplot
