// Fits a panel that can be drawn at any scale (the machine's control panel)
// to the room its scroll area gives it: whenever the scroll area is resized
// (or shown), `fitTo` gets the room without scroll bars; the panel chooses its
// scale (and arrangement) from it, and scrolls when even its least is too big.
#pragma once

#include <QObject>
#include <QSize>
#include <QTimer>
#include <functional>

class QScrollArea;

namespace k528::studio {

class PanelScaler : public QObject {
public:
    PanelScaler(QScrollArea* area, std::function<void(QSize room)> fitTo);
    // The room the panel has now (the scroll area without its bars).
    QSize room() const;
    void fit();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QScrollArea* area_;
    std::function<void(QSize)> fitTo_;
    QTimer later_;
};

} // namespace k528::studio
