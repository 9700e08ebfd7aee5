// Our own bridge between Qt 6 and VTK 9.1 (Debian's libvtk9-qt is built for
// Qt 5: never used): a plain QWidget whose picture a vtkGenericOpenGLRenderWindow
// draws in an OpenGL context of its own (a QOffscreenSurface and a
// framebuffer object), read back into an image that paintEvent draws
// (shared/notes/platform.md, docs/backplot.md).
//
// Not a QOpenGLWidget on purpose: one of those in a window makes Qt compose
// the whole window with OpenGL on every repaint of any widget in it — a
// clock's second, the LCD's blink, the editor's cursor — which llvmpipe (a
// shop PC without a GPU driver) does on the CPU: an idle studio took 5 % of
// a core for its clock alone, 30 % with a program running. Here the window
// stays a raster window and VTK renders only when the scene changed
// (requestRender()), at the view's size, once per paint at most.
//
// VTK renders into its own framebuffer; it is blitted into ours (VTK's own
// blit is off); VTK's GL state cache is reset each render; mouse, wheel and
// key events go to a vtkGenericRenderWindowInteractor whose render requests
// call requestRender(). Call setDefaultSurfaceFormat() before QApplication.
#pragma once

#include <QImage>
#include <QWidget>

#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkCallbackCommand;
class QOpenGLContext;
class QOffscreenSurface;
class QOpenGLFramebufferObject;

namespace k528::studio::backplot {

class VtkGlWidget : public QWidget {
    Q_OBJECT
public:
    explicit VtkGlWidget(QWidget* parent = nullptr);
    ~VtkGlWidget() override;
    static void setDefaultSurfaceFormat(); // OpenGL 3.2 core, before QApplication

    vtkGenericOpenGLRenderWindow* renderWindow() const { return window_; }
    vtkGenericRenderWindowInteractor* interactor() const { return interactor_; }
    // The scene changed: render it again at the next paint.
    void requestRender();
    // Frames rendered so far (benchmarks, tests).
    long framesPainted() const { return frames_; }
    // The last frame (device pixels, top row first).
    const QImage& frame() const { return frame_; }
    // The OpenGL context VTK draws with (null before the first paint).
    QOpenGLContext* context() const { return context_.get(); }
    bool makeCurrent();
    void doneCurrent();

signals:
    void sizeChanged(int widthPx, int heightPx);
    void interactionStarted();
    void interactionEnded();

protected:
    void paintEvent(QPaintEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;

private:
    bool ensureContext();
    void render();
    QSize pixelSize() const;
    void forwardMouse(QMouseEvent* e, unsigned long event);
    vtkGenericOpenGLRenderWindow* window_ = nullptr;
    vtkGenericRenderWindowInteractor* interactor_ = nullptr;
    vtkCallbackCommand* callback_ = nullptr;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOffscreenSurface> surface_;
    std::unique_ptr<QOpenGLFramebufferObject> fbo_;
    QImage frame_;
    bool dirty_ = true;
    bool failed_ = false; // no OpenGL context: said in the view
    bool painted_ = false; // the first paint asked for the first picture
    long frames_ = 0;
};

} // namespace k528::studio::backplot
