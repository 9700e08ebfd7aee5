#include "backplot/vtk_gl_widget.h"

#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOpenGLState.h>

#include <cmath>

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

VtkGlWidget::VtkGlWidget(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent); // the frame covers every pixel
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
            w->requestRender();
            break;
        default:
            break;
        }
    });
    window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback_);
    interactor_->AddObserver(vtkCommand::RenderEvent, callback_);
}

VtkGlWidget::~VtkGlWidget() {
    if (context_ && makeCurrent()) {
        fbo_.reset();
        window_->Finalize();
        doneCurrent();
    }
    interactor_->Delete();
    window_->Delete();
    callback_->Delete();
}

bool VtkGlWidget::makeCurrent() {
    return context_ && surface_ && context_->makeCurrent(surface_.get());
}

void VtkGlWidget::doneCurrent() {
    if (context_)
        context_->doneCurrent();
}

QSize VtkGlWidget::pixelSize() const {
    const qreal dpr = devicePixelRatioF();
    return {std::max(1, static_cast<int>(std::lround(width() * dpr))),
            std::max(1, static_cast<int>(std::lround(height() * dpr)))};
}

bool VtkGlWidget::ensureContext() {
    if (context_ || failed_)
        return context_ != nullptr;
    auto context = std::make_unique<QOpenGLContext>();
    context->setFormat(QSurfaceFormat::defaultFormat());
    auto surface = std::make_unique<QOffscreenSurface>(screen());
    if (!context->create()) {
        failed_ = true;
        return false;
    }
    surface->setFormat(context->format());
    surface->create();
    if (!surface->isValid() || !context->makeCurrent(surface.get())) {
        failed_ = true;
        return false;
    }
    context_ = std::move(context);
    surface_ = std::move(surface);
    window_->SetReadyForRendering(true);
    window_->SetIsCurrent(true);
    window_->OpenGLInitContext();
    const QSize px = pixelSize();
    window_->SetSize(px.width(), px.height());
    interactor_->Initialize();
    interactor_->UpdateSize(px.width(), px.height());
    return true;
}

void VtkGlWidget::requestRender() {
    dirty_ = true;
    update();
}

void VtkGlWidget::render() {
    if (!ensureContext() || !makeCurrent())
        return;
    const QSize px = pixelSize();
    const int* s = window_->GetSize();
    if (s[0] != px.width() || s[1] != px.height()) {
        window_->SetSize(px.width(), px.height());
        interactor_->UpdateSize(px.width(), px.height());
    }
    if (!fbo_ || fbo_->size() != px)
        fbo_ = std::make_unique<QOpenGLFramebufferObject>(px);
    vtkOpenGLState* state = window_->GetState();
    state->Reset(); // Qt may have changed the GL state behind VTK's cache
    state->Push();
    state->vtkglDisable(GL_SCISSOR_TEST);
    window_->Render();
    state->Pop();
    // VTK's framebuffer -> ours -> the image painted.
    QOpenGLFunctions* f = context_->functions();
    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_->handle());
    window_->BlitDisplayFramebuffer(0, 0, 0, px.width(), px.height(), 0, 0, px.width(), px.height(),
                                    GL_COLOR_BUFFER_BIT, GL_NEAREST);
    f->glBindFramebuffer(GL_FRAMEBUFFER, fbo_->handle());
    frame_ = fbo_->toImage(); // top row first
    if (frame_.format() == QImage::Format_ARGB32_Premultiplied)
        frame_.reinterpretAsFormat(QImage::Format_RGB32); // an opaque picture (no blending)
    frame_.setDevicePixelRatio(devicePixelRatioF());
    f->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    state->Reset();
    dirty_ = false;
    ++frames_;
}

void VtkGlWidget::paintEvent(QPaintEvent*) {
    if (!painted_) {
        // The window's first frame does not wait for the OpenGL context and
        // the first picture (0.3-1.5 s under llvmpipe): they follow at once.
        painted_ = true;
        QTimer::singleShot(0, this, [this] {
            if (dirty_ || frame_.isNull())
                render();
            update();
        });
    } else if (dirty_ || frame_.isNull()) {
        render();
    }
    QPainter p(this);
    if (frame_.isNull()) {
        p.fillRect(rect(), palette().window());
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                   failed_ ? tr("No OpenGL context for the backplot") : QString());
        return;
    }
    p.drawImage(QPointF(0, 0), frame_);
}

void VtkGlWidget::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    const QSize px = pixelSize();
    window_->SetSize(px.width(), px.height());
    interactor_->UpdateSize(px.width(), px.height());
    dirty_ = true;
    emit sizeChanged(px.width(), px.height());
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

} // namespace k528::studio::backplot
