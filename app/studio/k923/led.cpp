#include "k923/led.h"

#include <QPainter>
#include <QRadialGradient>

namespace k528::studio {

QColor ledColor(LedColor c) {
    switch (c) {
    case LedColor::Green:
        return {0x5c, 0xf2, 0x4a};
    case LedColor::Red:
        return {0xff, 0x3b, 0x2a};
    case LedColor::Amber:
        return {0xff, 0xa8, 0x1c};
    case LedColor::Yellow:
        return {0xff, 0xe0, 0x2e};
    case LedColor::Off:
        break;
    }
    return {0x3a, 0x3b, 0x36};
}

void paintLed(QPainter& p, const QRectF& lens, LedColor c, double glow) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    const QPointF centre = lens.center();
    const double r = std::min(lens.width(), lens.height()) / 2;
    // The bezel ring of the LED window.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 110));
    p.drawEllipse(centre, r * 1.18, r * 1.18);
    if (c == LedColor::Off) {
        QRadialGradient lensGrad(centre - QPointF(r * 0.3, r * 0.35), r * 1.3);
        lensGrad.setColorAt(0, QColor(0x6a, 0x6b, 0x63));
        lensGrad.setColorAt(0.6, QColor(0x38, 0x39, 0x34));
        lensGrad.setColorAt(1, QColor(0x22, 0x23, 0x20));
        p.setBrush(lensGrad);
        p.drawEllipse(centre, r, r);
    } else {
        const QColor on = ledColor(c);
        QRadialGradient halo(centre, r * glow);
        QColor h = on;
        h.setAlpha(150);
        halo.setColorAt(0, h);
        h.setAlpha(60);
        halo.setColorAt(0.55, h);
        h.setAlpha(0);
        halo.setColorAt(1, h);
        p.setBrush(halo);
        p.drawEllipse(centre, r * glow, r * glow);
        QRadialGradient lensGrad(centre, r);
        lensGrad.setColorAt(0, on.lighter(135));
        lensGrad.setColorAt(0.45, on);
        lensGrad.setColorAt(1, on.darker(140));
        p.setBrush(lensGrad);
        p.drawEllipse(centre, r, r);
    }
    // The specular highlight of the dome.
    p.setBrush(QColor(255, 255, 255, c == LedColor::Off ? 70 : 120));
    p.drawEllipse(QPointF(centre.x() - r * 0.35, centre.y() - r * 0.4), r * 0.28, r * 0.2);
    p.restore();
}

} // namespace k528::studio
