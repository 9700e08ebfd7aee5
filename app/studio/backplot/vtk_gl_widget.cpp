#include "backplot/vtk_gl_widget.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOpenGLState.h>

namespace k528::studio::backplot {

void VtkGlWidget::setDefaultSurfaceFormat() {
    QSurfaceFormat f;
    f.setRenderableType(QSurfaceFormat::OpenGL);
    f.setVersion(3, 2);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(8);
    f.setSamples(0);
    // Not forward-compatible: Qt asks GLX for a forward-compatible context
    // unless DeprecatedFunctions is set, and there glLineWidth(> 1) is an
    // error (Mesa: GL_INVALID_VALUE) while VTK, seeing the hardware range
    // (1..255 on llvmpipe), relies on it: every wide line came out 1 px.
    f.setOption(QSurfaceFormat::DeprecatedFunctions);
    QSurfaceFormat::setDefaultFormat(f);
}

VtkGlWidget::VtkGlWidget(QWidget* parent) : QOpenGLWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    window_ = vtkGenericOpenGLRenderWindow::New();
    window_->SetMultiSamples(0);
    window_->SetFrameBlitModeToNoBlit();
    window_->SetOwnContext(false);
    window_->SetReadyForRendering(false);
    interactor_ = vtkGenericRenderWindowInteractor::New();
    interactor_->SetRenderWindow(window_);
    interactor_->EnableRenderOff();
    callback_ = vtkCallbackCommand::New();
    callback_->SetClientData(this);
    callback_->SetCallback([](vtkObject*, unsigned long event, void* self, void*) {
        auto* w = static_cast<VtkGlWidget*>(self);
        switch (event) {
        case vtkCommand::WindowMakeCurrentEvent:
            w->makeCurrent();
            break;
        case vtkCommand::WindowIsCurrentEvent:
            break;
        case vtkCommand::RenderEvent:
            w->update();
            break;
        default:
            break;
        }
    });
    window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback_);
    interactor_->AddObserver(vtkCommand::RenderEvent, callback_);
}

VtkGlWidget::~VtkGlWidget() {
    makeCurrent();
    window_->Finalize();
    doneCurrent();
    interactor_->Delete();
    window_->Delete();
    callback_->Delete();
}

void VtkGlWidget::initializeGL() {
    window_->SetReadyForRendering(true);
    window_->SetIsCurrent(true);
    window_->OpenGLInitContext();
    const qreal dpr = devicePixelRatioF();
    window_->SetSize(static_cast<int>(width() * dpr), static_cast<int>(height() * dpr));
    interactor_->Initialize();
}

void VtkGlWidget::resizeGL(int w, int h) {
    const qreal dpr = devicePixelRatioF();
    const int pw = static_cast<int>(w * dpr), ph = static_cast<int>(h * dpr);
    window_->SetSize(pw, ph);
    interactor_->UpdateSize(pw, ph);
    emit sizeChanged(pw, ph);
}

void VtkGlWidget::paintGL() {
    vtkOpenGLState* state = window_->GetState();
    state->Reset(); // Qt changed the GL state behind VTK's cache
    state->Push();
    state->vtkglDisable(GL_SCISSOR_TEST);
    window_->Render();
    state->Pop();
    // VTK's framebuffer -> the widget's.
    QOpenGLFunctions* f = context()->functions();
    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const int* s = window_->GetSize();
    window_->BlitDisplayFramebuffer(0, 0, 0, s[0], s[1], 0, 0, s[0], s[1], GL_COLOR_BUFFER_BIT,
                                    GL_NEAREST);
    f->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    state->Reset();
    ++frames_;
}

void VtkGlWidget::forwardMouse(QMouseEvent* e, unsigned long event) {
    const qreal dpr = devicePixelRatioF();
    const QPointF p = e->position();
    interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr), static_cast<int>(p.y() * dpr),
                                          (e->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                          (e->modifiers() & Qt::ShiftModifier) ? 1 : 0);
    interactor_->InvokeEvent(event, e);
}

void VtkGlWidget::mousePressEvent(QMouseEvent* e) {
    emit interactionStarted();
    const unsigned long ev = e->button() == Qt::LeftButton     ? vtkCommand::LeftButtonPressEvent
                             : e->button() == Qt::MiddleButton ? vtkCommand::MiddleButtonPressEvent
                                                               : vtkCommand::RightButtonPressEvent;
    forwardMouse(e, ev);
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* e) {
    const unsigned long ev = e->button() == Qt::LeftButton     ? vtkCommand::LeftButtonReleaseEvent
                             : e->button() == Qt::MiddleButton ? vtkCommand::MiddleButtonReleaseEvent
                                                               : vtkCommand::RightButtonReleaseEvent;
    forwardMouse(e, ev);
    emit interactionEnded();
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* e) {
    forwardMouse(e, vtkCommand::MouseMoveEvent);
}

void VtkGlWidget::wheelEvent(QWheelEvent* e) {
    emit interactionStarted();
    const qreal dpr = devicePixelRatioF();
    const QPointF p = e->position();
    interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr), static_cast<int>(p.y() * dpr));
    interactor_->InvokeEvent(e->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                     : vtkCommand::MouseWheelBackwardEvent,
                             e);
    emit interactionEnded();
}

void VtkGlWidget::keyPressEvent(QKeyEvent* e) {
    QOpenGLWidget::keyPressEvent(e);
}

} // namespace k528::studio::backplot
