#include "k923/panel_key.h"

#include <QFontMetricsF>
#include <QLinearGradient>
#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace k528::studio {

namespace {

struct KeyColours {
    QColor base;
    QColor ink;
};

KeyColours coloursOf(KeyStyle s) {
    switch (s) {
    case KeyStyle::Mode:
        return {{0x2e, 0x4c, 0x7e}, {0xf4, 0xf6, 0xfa}};
    case KeyStyle::Machine:
        return {{0x3b, 0x40, 0x46}, {0xf2, 0xf2, 0xee}};
    case KeyStyle::Control:
        return {{0x5a, 0x60, 0x67}, {0xf4, 0xf4, 0xf0}};
    case KeyStyle::Escape:
        return {{0x9a, 0x3a, 0x30}, {0xfb, 0xf4, 0xf0}};
    case KeyStyle::Enter:
        return {{0x2f, 0x6a, 0x45}, {0xf2, 0xfa, 0xf2}};
    case KeyStyle::Digit:
        return {{0xec, 0xea, 0xe1}, {0x1c, 0x1c, 0x1c}};
    case KeyStyle::Operator:
        return {{0xc9, 0xcd, 0xd1}, {0x1c, 0x1c, 0x1c}};
    }
    return {{0x5a, 0x60, 0x67}, {0xf4, 0xf4, 0xf0}};
}

// The colour of second functions (SHIFT's legend and the shifted legends).
const QColor kShiftInk(0xf2, 0xb6, 0x1f);

QFont legendFont(double pixelSize, bool bold) {
    QFont f;
    f.setFamilies({"DejaVu Sans Condensed", "Liberation Sans Narrow", "Arial Narrow", "DejaVu Sans",
                   "Arial"});
    f.setStyleHint(QFont::SansSerif);
    f.setPixelSize(std::max(6, static_cast<int>(std::lround(pixelSize))));
    f.setBold(bold);
    return f;
}

} // namespace

PanelKey::PanelKey(panel::Key key, QWidget* parent)
    : QAbstractButton(parent), key_(key), face_(keyFace(key)) {
    setObjectName(
        QStringLiteral("k923.key.%1")
            .arg(QString::fromLatin1(panel::keyName(key).data(),
                                     static_cast<qsizetype>(panel::keyName(key).size()))));
    setFocusPolicy(Qt::NoFocus);
    setCursor(Qt::PointingHandCursor);
    setAccessibleName(keyTitle(key));
}

void PanelKey::setLed(LedColor c) {
    if (c == led_)
        return;
    led_ = c;
    update();
}

QRectF PanelKey::bodyRect() const {
    // The key's travel: the body sits higher by `travel` when up, with its
    // shadow below it; pressed, it moves down onto the shadow.
    const double travel = std::max(1.0, height() * 0.045);
    const QRectF r = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    return isDown() ? r.adjusted(0, travel, 0, 0) : r.adjusted(0, 0, 0, -travel);
}

QRectF PanelKey::ledRect() const {
    if (face_.led == LedKind::None)
        return {};
    const QRectF body = bodyRect();
    const double d = std::max(4.0, std::min(body.width(), body.height()) * 0.2);
    const double inset = std::min(body.width(), body.height()) * 0.11;
    return {body.left() + inset, body.top() + inset, d, d};
}

void PanelKey::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setRenderHint(QPainter::TextAntialiasing, true);
    const KeyColours kc = coloursOf(face_.style);
    const QRectF full = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    const QRectF body = bodyRect();
    const double radius = std::min(full.width(), full.height()) * 0.12;

    // Shadow / the key's side, visible below an unpressed key.
    p.setPen(Qt::NoPen);
    p.setBrush(kc.base.darker(240));
    p.drawRoundedRect(full, radius, radius);

    // The key top: a soft dome, lit from above.
    const QColor base =
        isDown() ? kc.base.darker(112) : (underMouse() ? kc.base.lighter(106) : kc.base);
    QLinearGradient top(body.topLeft(), body.bottomLeft());
    top.setColorAt(0, base.lighter(isDown() ? 104 : 118));
    top.setColorAt(0.45, base);
    top.setColorAt(1, base.darker(118));
    p.setBrush(top);
    p.setPen(QPen(kc.base.darker(190), 1));
    p.drawRoundedRect(body, radius, radius);
    // Highlight along the top edge.
    if (!isDown()) {
        p.setPen(QPen(QColor(255, 255, 255, 60), 1));
        p.setBrush(Qt::NoBrush);
        p.drawRoundedRect(body.adjusted(1, 1, -1, -1), radius * 0.85, radius * 0.85);
    }

    if (face_.led != LedKind::None)
        paintLed(p, ledRect(), led_, 2.2);

    paintLegend(p, body, kc.ink);
}

void PanelKey::paintLegend(QPainter& p, const QRectF& body, const QColor& ink) {
    const double h = body.height();
    const double w = body.width();
    p.setPen(ink);
    if (face_.icon != KeyIcon::None && face_.icon != KeyIcon::Enter) {
        const double s = std::min(w, h) * 0.36;
        paintIcon(p, QRectF(body.center().x() - s / 2, body.center().y() - s / 2 + h * 0.04, s, s),
                  face_.icon, ink);
        if (face_.shiftedLegend) {
            // The second function, in SHIFT's colour: a double arrow (fast).
            const double t = std::min(w, h) * 0.16;
            const QRectF a(body.right() - t * 1.6, body.top() + t * 0.55, t, t * 0.8);
            const KeyIcon i = face_.icon;
            paintIcon(p, a, i, kShiftInk);
            paintIcon(p, a.translated(0, i == KeyIcon::Up ? t * 0.55 : -t * 0.55), i, kShiftInk);
        }
        return;
    }
    if (!face_.corner.isEmpty()) {
        p.setFont(legendFont(h * 0.22, true));
        p.setPen(ink);
        p.drawText(body.adjusted(w * 0.1, h * 0.06, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                   face_.corner);
    }
    const bool single = face_.legend.size() == 1;
    double size = single ? h * 0.46 : h * 0.27;
    if (face_.style == KeyStyle::Mode)
        size = face_.corner.isEmpty() ? h * 0.34 : h * 0.34;
    QFont f = legendFont(size, !single || face_.style != KeyStyle::Digit);
    // Shrink long words until they fit the key with a margin.
    QFontMetricsF fm(f);
    const double room = w * 0.84;
    while (fm.horizontalAdvance(face_.legend) > room && f.pixelSize() > 6) {
        f.setPixelSize(f.pixelSize() - 1);
        fm = QFontMetricsF(f);
    }
    p.setFont(f);
    p.setPen(key_ == panel::Key::Shift ? kShiftInk : ink);
    QRectF text = body;
    if (face_.led != LedKind::None || !face_.corner.isEmpty())
        text.adjust(0, h * 0.18, 0, 0); // below the LED / the corner print
    if (face_.icon == KeyIcon::Enter)
        text.adjust(0, 0, -w * 0.22, 0);
    if (!face_.sub.isEmpty()) {
        const QFont subFont = legendFont(size * 0.62, true);
        const double subW = QFontMetricsF(subFont).horizontalAdvance(face_.sub);
        const double mainW = fm.horizontalAdvance(face_.legend);
        const double gap = w * 0.06;
        const double x0 = body.center().x() - (mainW + gap + subW) / 2;
        p.drawText(QRectF(x0, text.top(), mainW + 1, text.height()),
                   Qt::AlignLeft | Qt::AlignVCenter, face_.legend);
        p.setFont(subFont);
        p.drawText(QRectF(x0 + mainW + gap, text.top(), subW + 1, text.height() * 0.9),
                   Qt::AlignLeft | Qt::AlignVCenter, face_.sub);
        return;
    }
    p.drawText(text, Qt::AlignCenter, face_.legend);
    if (face_.icon == KeyIcon::Enter) {
        const double s = h * 0.34;
        paintIcon(p, QRectF(body.right() - w * 0.2 - s * 0.5, body.center().y() - s / 2, s, s),
                  KeyIcon::Enter, ink);
    }
}

void PanelKey::paintIcon(QPainter& p, const QRectF& a, KeyIcon icon, const QColor& ink) {
    p.save();
    p.setPen(Qt::NoPen);
    p.setBrush(ink);
    QPolygonF tri;
    switch (icon) {
    case KeyIcon::Up:
        tri << QPointF(a.center().x(), a.top()) << a.bottomRight() << a.bottomLeft();
        break;
    case KeyIcon::Down:
        tri << a.topLeft() << a.topRight() << QPointF(a.center().x(), a.bottom());
        break;
    case KeyIcon::Left:
        tri << QPointF(a.left(), a.center().y()) << a.topRight() << a.bottomRight();
        break;
    case KeyIcon::Right:
        tri << a.topLeft() << QPointF(a.right(), a.center().y()) << a.bottomLeft();
        break;
    case KeyIcon::Enter: {
        // ↵: down from the top right, then left to an arrow head.
        const double lw = std::max(1.2, a.width() * 0.13);
        QPainterPath path;
        path.moveTo(a.right() - lw / 2, a.top());
        path.lineTo(a.right() - lw / 2, a.center().y() + a.height() * 0.1);
        path.lineTo(a.left() + a.width() * 0.3, a.center().y() + a.height() * 0.1);
        p.setPen(QPen(ink, lw, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setPen(Qt::NoPen);
        p.setBrush(ink);
        const double y = a.center().y() + a.height() * 0.1;
        tri << QPointF(a.left(), y) << QPointF(a.left() + a.width() * 0.36, y - a.height() * 0.24)
            << QPointF(a.left() + a.width() * 0.36, y + a.height() * 0.24);
        break;
    }
    case KeyIcon::None:
        break;
    }
    if (!tri.isEmpty())
        p.drawPolygon(tri);
    p.restore();
}

} // namespace k528::studio
