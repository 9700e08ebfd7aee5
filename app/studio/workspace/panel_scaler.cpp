#include "workspace/panel_scaler.h"

#include <QEvent>
#include <QScrollArea>

namespace k528::studio {

PanelScaler::PanelScaler(QScrollArea* area, std::function<void(QSize)> fitTo)
    : QObject(area), area_(area), fitTo_(std::move(fitTo)) {
    area->installEventFilter(this);
    // Once the resizing settles (a resize inside a resize relayouts twice).
    later_.setSingleShot(true);
    later_.setInterval(0);
    connect(&later_, &QTimer::timeout, this, &PanelScaler::fit);
}

QSize PanelScaler::room() const { return area_->maximumViewportSize(); }

void PanelScaler::fit() {
    if (area_->isVisible())
        fitTo_(room());
}

bool PanelScaler::eventFilter(QObject* watched, QEvent* e) {
    if (watched == area_ && (e->type() == QEvent::Resize || e->type() == QEvent::Show))
        later_.start();
    return QObject::eventFilter(watched, e);
}

} // namespace k528::studio
