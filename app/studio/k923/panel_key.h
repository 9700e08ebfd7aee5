// One key of the K923: a membrane key with its printed legends, an LED
// window where the key has one, and a visible travel when pressed. It never
// takes the keyboard focus (the panel does).
#pragma once

#include "k923/key_face.h"
#include "k923/led.h"
#include "panel/keys.h"

#include <QAbstractButton>

namespace k528::studio {

class PanelKey : public QAbstractButton {
    Q_OBJECT
public:
    PanelKey(panel::Key key, QWidget* parent = nullptr);

    panel::Key key() const { return key_; }
    const KeyFace& face() const { return face_; }

    LedColor led() const { return led_; }
    void setLed(LedColor c);
    // The LED lens in key coordinates (empty if the key has no LED).
    QRectF ledRect() const;
    // The body of the key (where the legend is printed), key coordinates.
    QRectF bodyRect() const;

    QSize sizeHint() const override { return {48, 48}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void paintLegend(QPainter& p, const QRectF& body, const QColor& ink);
    void paintIcon(QPainter& p, const QRectF& area, KeyIcon icon, const QColor& ink);

    panel::Key key_;
    KeyFace face_;
    LedColor led_ = LedColor::Off;
};

} // namespace k528::studio
