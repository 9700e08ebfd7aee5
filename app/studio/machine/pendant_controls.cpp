#include "machine/pendant_controls.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QRadialGradient>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace k528::studio {

namespace {

constexpr double kPi = 3.14159265358979323846;

QFont plateFont(double px, bool bold = true) {
    QFont f;
    f.setFamilies(
        {"DejaVu Sans Condensed", "Liberation Sans Narrow", "Arial Narrow", "DejaVu Sans"});
    f.setStyleHint(QFont::SansSerif);
    f.setPixelSize(std::max(7, static_cast<int>(std::lround(px))));
    f.setBold(bold);
    return f;
}

// An engraved legend plate: black anodised with white letters.
void paintPlate(QPainter& p, const QRectF& r, const QString& text) {
    if (text.isEmpty())
        return;
    p.save();
    QLinearGradient g(r.topLeft(), r.bottomLeft());
    g.setColorAt(0, QColor(0x2a, 0x2c, 0x2e));
    g.setColorAt(1, QColor(0x16, 0x17, 0x18));
    p.setPen(QPen(QColor(0x6a, 0x6e, 0x72), 0.8));
    p.setBrush(g);
    p.drawRoundedRect(r, 2.5, 2.5);
    p.setPen(QColor(0xf2, 0xf1, 0xea));
    const PlateText t = plateText(r, text);
    p.setFont(t.font);
    if (t.xScale < 1) {
        const QPointF c = r.center();
        p.translate(c);
        p.scale(t.xScale, 1);
        p.translate(-c);
        QRectF wide(0, r.top(), t.room / t.xScale + 2, r.height());
        wide.moveCenter(c);
        p.drawText(wide, Qt::AlignCenter, text);
    } else {
        p.drawText(r.adjusted(2, 0, -2, 0), Qt::AlignCenter | Qt::TextWordWrap, text);
    }
    p.restore();
}

// A chrome bezel ring around a circle of radius `r`.
void paintBezel(QPainter& p, const QPointF& c, double r) {
    QRadialGradient g(c - QPointF(r * 0.3, r * 0.4), r * 1.4);
    g.setColorAt(0, QColor(0xf4, 0xf5, 0xf6));
    g.setColorAt(0.5, QColor(0x9b, 0xa0, 0xa6));
    g.setColorAt(1, QColor(0x4a, 0x4e, 0x53));
    p.setPen(QPen(QColor(0x30, 0x32, 0x35), 0.8));
    p.setBrush(g);
    p.drawEllipse(c, r, r);
}

QColor capColor(PendantButton::Cap cap) {
    switch (cap) {
    case PendantButton::Cap::Green:
        return {0x2a, 0x9a, 0x48};
    case PendantButton::Cap::Red:
        return {0xc6, 0x24, 0x2a};
    case PendantButton::Cap::Yellow:
        return {0xe6, 0xb4, 0x1e};
    case PendantButton::Cap::Blue:
        return {0x2c, 0x5c, 0xb0};
    case PendantButton::Cap::Black:
        return {0x2a, 0x2b, 0x2d};
    case PendantButton::Cap::White:
        return {0xe6, 0xe6, 0xe0};
    }
    return Qt::gray;
}

QColor lampColor(PilotLamp::Color c) {
    switch (c) {
    case PilotLamp::Color::Green:
        return {0x3c, 0xe0, 0x5a};
    case PilotLamp::Color::Red:
        return {0xff, 0x38, 0x30};
    case PilotLamp::Color::Amber:
        return {0xff, 0xb0, 0x1c};
    case PilotLamp::Color::White:
        return {0xfa, 0xf6, 0xe6};
    case PilotLamp::Color::Blue:
        return {0x4a, 0x9c, 0xff};
    }
    return Qt::white;
}

// A lens: dark tinted glass when off, bright with a glow when on.
void paintLens(QPainter& p, const QPointF& c, double r, QColor color, bool on) {
    p.save();
    if (on) {
        QRadialGradient glow(c, r * 2.1);
        QColor g0 = color;
        g0.setAlpha(150);
        QColor g1 = color;
        g1.setAlpha(0);
        glow.setColorAt(0.45, g0);
        glow.setColorAt(1, g1);
        p.setPen(Qt::NoPen);
        p.setBrush(glow);
        p.drawEllipse(c, r * 2.1, r * 2.1);
    }
    QRadialGradient g(c - QPointF(r * 0.35, r * 0.35), r * 1.3);
    if (on) {
        g.setColorAt(0, QColor(255, 255, 255));
        g.setColorAt(0.35, color.lighter(125));
        g.setColorAt(1, color.darker(115));
    } else {
        g.setColorAt(0, color.darker(220).lighter(140));
        g.setColorAt(0.5, color.darker(330));
        g.setColorAt(1, color.darker(520));
    }
    p.setPen(QPen(QColor(0, 0, 0, 140), 0.8));
    p.setBrush(g);
    p.drawEllipse(c, r, r);
    // Fresnel rings of the lens.
    p.setPen(QPen(QColor(255, 255, 255, on ? 70 : 28), 0.6));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(c, r * 0.62, r * 0.62);
    p.drawEllipse(c, r * 0.32, r * 0.32);
    p.restore();
}

} // namespace

PlateText plateText(const QRectF& plate, const QString& text) {
    PlateText t;
    t.room = plate.width() - 4;
    double px = plate.height() * 0.62;
    t.font = plateFont(px);
    // Shrink to fit down to the smallest legible size; a legend still wider
    // (ШПИНДЕЛЬ on a small panel) is set narrower on one line rather than
    // cut or wrapped onto a plate of one line's height.
    while (px > 7 && QFontMetricsF(t.font).horizontalAdvance(text) > t.room &&
           !text.contains('\n')) {
        px -= 0.5;
        t.font.setPixelSize(static_cast<int>(px));
    }
    const double advance = QFontMetricsF(t.font).horizontalAdvance(text);
    if (advance > t.room && !text.contains('\n') && t.room > 0)
        t.xScale = t.room / advance;
    return t;
}

// ---------------------------------------------------------------------------
// PendantButton

PendantButton::PendantButton(Cap cap, QWidget* parent) : QAbstractButton(parent), cap_(cap) {
    setFocusPolicy(Qt::NoFocus);
    setCursor(Qt::PointingHandCursor);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void PendantButton::setLegend(const QString& legend) {
    legend_ = legend;
    setAccessibleName(legend);
    setToolTip(legend);
    update();
}

void PendantButton::setSymbol(const QString& symbol) {
    if (symbol == symbol_)
        return;
    symbol_ = symbol;
    update();
}

void PendantButton::setLit(bool lit) {
    if (lit == lit_)
        return;
    lit_ = lit;
    update();
}

namespace {
QSize scaled(double w, double h, double s) {
    return {static_cast<int>(std::lround(w * s)), static_cast<int>(std::lround(h * s))};
}
} // namespace

QSize PendantButton::sizeHint() const {
    return scaled(68, legend_.isEmpty() ? 52 : 72, scale_);
}

QSize PendantButton::minimumSizeHint() const {
    return scaled(52, legend_.isEmpty() ? 48 : 68, scale_);
}

void PendantButton::setScale(double scale) {
    scale_ = scale;
    updateGeometry();
    update();
}

QRectF PendantButton::capRect() const {
    const double plate = legend_.isEmpty() ? 0 : 18 * scale_;
    const double side = std::min<double>(width(), height() - plate - 4);
    const double r = side / 2 - 2;
    const QPointF c(width() / 2.0, 2 + side / 2);
    return {c.x() - r * 0.74, c.y() - r * 0.74, r * 1.48, r * 1.48};
}

bool PendantButton::hitButton(const QPoint& pos) const {
    const double m = 6 * scale_;
    const QRectF cap = capRect().adjusted(-m, -m, m, m);
    const QPointF d = QPointF(pos) - cap.center();
    return std::hypot(d.x(), d.y()) <= cap.width() / 2;
}

void PendantButton::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double plate = legend_.isEmpty() ? 0 : 18 * scale_;
    const double side = std::min<double>(width(), height() - plate - 4);
    const double r = side / 2 - 2;
    const QPointF c(width() / 2.0, 2 + side / 2);
    paintBezel(p, c, r);
    // The collar: dark gap between bezel and cap.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x14, 0x15, 0x16));
    p.drawEllipse(c, r * 0.8, r * 0.8);
    // The cap: a dome; pressed it sinks and darkens; lit it glows.
    const bool down = isDown();
    const double cr = r * (down ? 0.70 : 0.74);
    const QPointF cc = c + QPointF(0, down ? 1.2 : 0);
    QColor base = capColor(cap_);
    if (illuminated_ && lit_)
        base = base.lighter(cap_ == Cap::Yellow || cap_ == Cap::White ? 112 : 165);
    else if (illuminated_)
        base = base.darker(125);
    if (down)
        base = base.darker(118);
    if (illuminated_ && lit_) {
        QRadialGradient glow(cc, cr * 1.5);
        QColor g0 = base;
        g0.setAlpha(120);
        QColor g1 = base;
        g1.setAlpha(0);
        glow.setColorAt(0.6, g0);
        glow.setColorAt(1, g1);
        p.setBrush(glow);
        p.drawEllipse(cc, cr * 1.5, cr * 1.5);
    }
    QRadialGradient g(cc - QPointF(cr * 0.35, cr * 0.45), cr * 1.5);
    g.setColorAt(0, base.lighter(lit_ && illuminated_ ? 150 : 160));
    g.setColorAt(0.45, base);
    g.setColorAt(1, base.darker(170));
    p.setPen(QPen(base.darker(220), 0.9));
    p.setBrush(g);
    p.drawEllipse(cc, cr, cr);
    // Specular highlight.
    QRadialGradient hl(cc - QPointF(cr * 0.3, cr * 0.38), cr * 0.55);
    hl.setColorAt(0, QColor(255, 255, 255, down ? 70 : 130));
    hl.setColorAt(1, QColor(255, 255, 255, 0));
    p.setPen(Qt::NoPen);
    p.setBrush(hl);
    p.drawEllipse(cc - QPointF(cr * 0.3, cr * 0.38), cr * 0.55, cr * 0.45);
    if (!symbol_.isEmpty()) {
        const bool darkInk = cap_ == Cap::Yellow || cap_ == Cap::White;
        p.setPen(darkInk ? QColor(0x1a, 0x1a, 0x1a) : QColor(0xf6, 0xf6, 0xf2));
        p.setFont(plateFont(cr * (symbol_.size() > 2 ? 0.55 : 0.9)));
        p.drawText(QRectF(cc.x() - cr, cc.y() - cr, 2 * cr, 2 * cr), Qt::AlignCenter, symbol_);
    }
    if (!legend_.isEmpty())
        paintPlate(p, legendPlate(), legend_);
}

QRectF PendantButton::legendPlate() const {
    const double plate = 18 * scale_;
    return QRectF(2, height() - plate - 1, width() - 4, plate);
}

// ---------------------------------------------------------------------------
// MushroomButton

MushroomButton::MushroomButton(QWidget* parent) : QAbstractButton(parent) {
    setCheckable(true);
    setFocusPolicy(Qt::NoFocus);
    setCursor(Qt::PointingHandCursor);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void MushroomButton::setLegend(const QString& legend) {
    legend_ = legend;
    setAccessibleName(legend);
    setToolTip(legend);
    update();
}

QSize MushroomButton::sizeHint() const {
    return scaled(104, 104, scale_);
}

QSize MushroomButton::minimumSizeHint() const {
    return scaled(96, 96, scale_);
}

void MushroomButton::setScale(double scale) {
    scale_ = scale;
    updateGeometry();
    update();
}

bool MushroomButton::hitButton(const QPoint& pos) const {
    const QPointF d = QPointF(pos) - QPointF(width() / 2.0, height() / 2.0);
    return std::hypot(d.x(), d.y()) <= std::min(width(), height()) * 0.36;
}

void MushroomButton::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double R = std::min(width(), height()) / 2.0 - 1;
    const QPointF c(width() / 2.0, height() / 2.0);
    // The yellow emergency disc with its legend around.
    QRadialGradient disc(c, R);
    disc.setColorAt(0, QColor(0xf6, 0xcc, 0x2a));
    disc.setColorAt(1, QColor(0xd8, 0xa8, 0x10));
    p.setPen(QPen(QColor(0x6e, 0x55, 0x08), 1));
    p.setBrush(disc);
    p.drawEllipse(c, R, R);
    if (!legend_.isEmpty()) {
        p.save();
        QFont f = plateFont(R * 0.15);
        p.setFont(f);
        p.setPen(QColor(0x1c, 0x1a, 0x12));
        const QFontMetricsF fm(f);
        const double textR = R * 0.86;
        const double total = fm.horizontalAdvance(legend_);
        double a = -total / textR / 2; // centred at the top
        for (const QChar ch : legend_) {
            const double w = fm.horizontalAdvance(ch);
            p.save();
            p.translate(c);
            p.rotate((a + w / textR / 2) * 180 / kPi);
            p.drawText(QPointF(-w / 2, -textR + fm.ascent() / 2), QString(ch));
            p.restore();
            a += w / textR;
        }
        p.restore();
    }
    paintBezel(p, c, R * 0.64);
    // The mushroom head: pressed (latched) it sits lower and smaller.
    const bool latched = isChecked() || isDown();
    const double hr = R * (latched ? 0.5 : 0.56);
    const QPointF hc = c + QPointF(0, latched ? 2 : -1);
    if (!latched) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0, 0, 0, 90));
        p.drawEllipse(hc + QPointF(2, 4), hr, hr);
    }
    QRadialGradient g(hc - QPointF(hr * 0.35, hr * 0.45), hr * 1.5);
    const QColor red = latched ? QColor(0xa8, 0x16, 0x1c) : QColor(0xd6, 0x22, 0x28);
    g.setColorAt(0, red.lighter(160));
    g.setColorAt(0.5, red);
    g.setColorAt(1, red.darker(180));
    p.setPen(QPen(red.darker(240), 1));
    p.setBrush(g);
    p.drawEllipse(hc, hr, hr);
    QRadialGradient hl(hc - QPointF(hr * 0.3, hr * 0.4), hr * 0.5);
    hl.setColorAt(0, QColor(255, 255, 255, latched ? 60 : 140));
    hl.setColorAt(1, QColor(255, 255, 255, 0));
    p.setPen(Qt::NoPen);
    p.setBrush(hl);
    p.drawEllipse(hc - QPointF(hr * 0.3, hr * 0.4), hr * 0.55, hr * 0.42);
    if (latched) {
        // «Pull to release»: the twist arrow on the head.
        p.setPen(QPen(QColor(255, 230, 230, 200), std::max(1.5, hr * 0.07), Qt::SolidLine,
                      Qt::RoundCap));
        p.setBrush(Qt::NoBrush);
        const QRectF arc(hc.x() - hr * 0.5, hc.y() - hr * 0.5, hr, hr);
        p.drawArc(arc, 30 * 16, 240 * 16);
        const double a = 30 * kPi / 180;
        const QPointF tip(hc.x() + hr * 0.5 * std::cos(a), hc.y() - hr * 0.5 * std::sin(a));
        p.drawLine(tip, tip + QPointF(-hr * 0.18, -hr * 0.02));
        p.drawLine(tip, tip + QPointF(hr * 0.02, hr * 0.18));
    }
}

// ---------------------------------------------------------------------------
// PilotLamp

PilotLamp::PilotLamp(Color color, QWidget* parent) : QWidget(parent), color_(color) {
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void PilotLamp::setLegend(const QString& legend) {
    legend_ = legend;
    setAccessibleName(legend);
    setToolTip(legend);
    update();
}

void PilotLamp::setOn(bool on) {
    if (on == on_)
        return;
    on_ = on;
    update();
}

QSize PilotLamp::sizeHint() const {
    return scaled(60, 52, scale_);
}

QSize PilotLamp::minimumSizeHint() const {
    return scaled(50, 50, scale_);
}

void PilotLamp::setScale(double scale) {
    scale_ = scale;
    updateGeometry();
    update();
}

void PilotLamp::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double plate = 15 * scale_;
    const double r = std::min<double>(width(), height() - plate - 4) / 2 - 2;
    const QPointF c(width() / 2.0, 2 + r + 1);
    paintBezel(p, c, r);
    paintLens(p, c, r * 0.72, lampColor(color_), on_);
    paintPlate(p, legendPlate(), legend_);
}

QRectF SelectorSwitch::captionPlate() const {
    return QRectF(4, 1, width() - 8, 15 * scale_);
}

QRectF PilotLamp::legendPlate() const {
    const double plate = 15 * scale_;
    return QRectF(1, height() - plate - 1, width() - 2, plate);
}

// ---------------------------------------------------------------------------
// HandwheelDial

HandwheelDial::HandwheelDial(QWidget* parent) : QWidget(parent) {
    setCursor(Qt::OpenHandCursor);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    setMinimumSize(120, 120);
}

void HandwheelDial::setDetentsPerTurn(int n) {
    detents_ = std::max(1, n);
    update();
}

void HandwheelDial::setEnabledLook(bool active) {
    if (active == active_)
        return;
    active_ = active;
    update();
}

QSize HandwheelDial::sizeHint() const {
    return scaled(170, 170, scale_);
}

QSize HandwheelDial::minimumSizeHint() const {
    return scaled(120, 120, scale_);
}

void HandwheelDial::setScale(double scale) {
    scale_ = scale;
    setMinimumSize(minimumSizeHint());
    updateGeometry();
    update();
}

double HandwheelDial::pointerAngle(const QPointF& pos) const {
    const QPointF d = pos - QPointF(width() / 2.0, height() / 2.0);
    return std::atan2(d.x(), -d.y()) * 180 / kPi; // clockwise from the top
}

void HandwheelDial::rotateBy(double degrees) {
    angle_ = std::fmod(angle_ + degrees + 360.0, 360.0);
    pending_ += degrees;
    const double step = 360.0 / detents_;
    const int whole = static_cast<int>(pending_ / step);
    if (whole != 0) {
        pending_ -= whole * step;
        emit turned(whole);
    }
    update();
}

void HandwheelDial::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton)
        return;
    dragging_ = true;
    grabAngle_ = pointerAngle(e->position());
    setCursor(Qt::ClosedHandCursor);
}

void HandwheelDial::mouseMoveEvent(QMouseEvent* e) {
    if (!dragging_)
        return;
    const double a = pointerAngle(e->position());
    double d = a - grabAngle_;
    if (d > 180)
        d -= 360;
    if (d < -180)
        d += 360;
    grabAngle_ = a;
    rotateBy(d);
}

void HandwheelDial::mouseReleaseEvent(QMouseEvent*) {
    dragging_ = false;
    setCursor(Qt::OpenHandCursor);
}

void HandwheelDial::wheelEvent(QWheelEvent* e) {
    // One notch of the mouse wheel (120) turns one detent.
    const int notches = e->angleDelta().y() / 120;
    if (notches != 0)
        rotateBy(notches * 360.0 / detents_);
    e->accept();
}

void HandwheelDial::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double R = std::min(width(), height()) / 2.0 - 2;
    const QPointF c(width() / 2.0, height() / 2.0);
    // The fixed scale ring with 0..100 graduations (it stays; the wheel turns).
    QRadialGradient ring(c, R);
    ring.setColorAt(0.8, QColor(0xc8, 0xcb, 0xcf));
    ring.setColorAt(1, QColor(0x80, 0x85, 0x8b));
    p.setPen(QPen(QColor(0x3a, 0x3d, 0x40), 1));
    p.setBrush(ring);
    p.drawEllipse(c, R, R);
    p.save();
    p.translate(c);
    p.setPen(QPen(QColor(0x16, 0x16, 0x16), 1));
    p.setFont(plateFont(R * 0.1));
    for (int i = 0; i < 100; ++i) {
        const double a = i * 3.6 * kPi / 180;
        const double outer = R - 2;
        const double inner = R - (i % 10 == 0 ? R * 0.13 : (i % 5 == 0 ? R * 0.09 : R * 0.06));
        p.drawLine(QPointF(outer * std::sin(a), -outer * std::cos(a)),
                   QPointF(inner * std::sin(a), -inner * std::cos(a)));
    }
    p.restore();
    // The wheel: knurled black rim, turning with the angle.
    const double W = R * 0.78;
    p.save();
    p.translate(c);
    p.rotate(angle_);
    QRadialGradient body(QPointF(-W * 0.3, -W * 0.35), W * 1.5);
    body.setColorAt(0, active_ ? QColor(0x5a, 0x5e, 0x63) : QColor(0x70, 0x72, 0x74));
    body.setColorAt(0.6, active_ ? QColor(0x24, 0x26, 0x28) : QColor(0x4a, 0x4b, 0x4c));
    body.setColorAt(1, QColor(0x0c, 0x0c, 0x0d));
    p.setPen(QPen(QColor(0x05, 0x05, 0x05), 1));
    p.setBrush(body);
    p.drawEllipse(QPointF(0, 0), W, W);
    p.setPen(QPen(QColor(0x70, 0x74, 0x78, 150), 1));
    for (int i = 0; i < 72; ++i) {
        const double a = i * 5 * kPi / 180;
        p.drawLine(QPointF(W * std::sin(a), -W * std::cos(a)),
                   QPointF((W - 5) * std::sin(a), -(W - 5) * std::cos(a)));
    }
    // Its own 100-division scale and index.
    p.setPen(QPen(QColor(0xe8, 0xe8, 0xe2), 1));
    for (int i = 0; i < 100; ++i) {
        const double a = i * 3.6 * kPi / 180;
        const double o = W * 0.84, in = W * (i % 10 == 0 ? 0.72 : 0.78);
        p.drawLine(QPointF(o * std::sin(a), -o * std::cos(a)),
                   QPointF(in * std::sin(a), -in * std::cos(a)));
    }
    p.setFont(plateFont(W * 0.13, false));
    for (int i = 0; i < 10; ++i) {
        const double a = i * 36 * kPi / 180;
        const double tr = W * 0.6;
        p.save();
        p.translate(tr * std::sin(a), -tr * std::cos(a));
        p.rotate(i * 36);
        p.drawText(QRectF(-W * 0.15, -W * 0.08, W * 0.3, W * 0.16), Qt::AlignCenter,
                   QString::number(i * 10));
        p.restore();
    }
    // Hub and crank knob.
    QRadialGradient hub(QPointF(-W * 0.08, -W * 0.1), W * 0.4);
    hub.setColorAt(0, QColor(0xee, 0xef, 0xf0));
    hub.setColorAt(1, QColor(0x70, 0x74, 0x78));
    p.setPen(QPen(QColor(0x30, 0x30, 0x30), 0.8));
    p.setBrush(hub);
    p.drawEllipse(QPointF(0, 0), W * 0.22, W * 0.22);
    const QPointF knob(0, -W * 0.42);
    QRadialGradient kg(knob - QPointF(W * 0.04, W * 0.05), W * 0.16);
    kg.setColorAt(0, QColor(0x8a, 0x8e, 0x92));
    kg.setColorAt(1, QColor(0x10, 0x10, 0x10));
    p.setBrush(kg);
    p.drawEllipse(knob, W * 0.11, W * 0.11);
    p.restore();
    // The fixed index mark at the top.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0xd0, 0x20, 0x20));
    QPainterPath tri;
    tri.moveTo(c.x(), c.y() - W - 1);
    tri.lineTo(c.x() - 5, c.y() - R + 1);
    tri.lineTo(c.x() + 5, c.y() - R + 1);
    tri.closeSubpath();
    p.drawPath(tri);
}

// ---------------------------------------------------------------------------
// SelectorSwitch

SelectorSwitch::SelectorSwitch(QWidget* parent) : QWidget(parent) {
    setCursor(Qt::PointingHandCursor);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void SelectorSwitch::setPositions(const QStringList& legends, double spanDegrees) {
    legends_ = legends;
    span_ = spanDegrees;
    position_ = std::clamp(position_, 0, std::max<int>(0, static_cast<int>(legends_.size()) - 1));
    update();
}

void SelectorSwitch::setCaption(const QString& caption) {
    caption_ = caption;
    setAccessibleName(caption);
    update();
}

void SelectorSwitch::setPosition(int index) {
    index = std::clamp(index, 0, std::max<int>(0, static_cast<int>(legends_.size()) - 1));
    if (index == position_)
        return;
    position_ = index;
    update();
    emit positionChanged(index);
}

QSize SelectorSwitch::sizeHint() const {
    return scaled(130, 92, scale_);
}

QSize SelectorSwitch::minimumSizeHint() const {
    return scaled(110, 86, scale_);
}

void SelectorSwitch::setScale(double scale) {
    scale_ = scale;
    updateGeometry();
    update();
}

// Geometry: the caption plate on top (16 px), the legends on a circle of
// 1.9 knob radii around the knob, the lowest legend (for spans beyond 180°)
// inside the widget.
namespace {
constexpr double kCaptionH = 18, kLegendR = 1.9, kLegendH = 9;
double below(double span) { // how far the lowest point reaches below the centre, in radii
    const double half = span / 2 * kPi / 180;
    return std::max(1.15, half > kPi / 2 ? -kLegendR * std::cos(half) + 0.4 : 1.15);
}
} // namespace

double SelectorSwitch::knobRadius() const {
    const double top = (caption_.isEmpty() ? 2 : kCaptionH * scale_) + kLegendH * scale_ + 2;
    const double byHeight = (height() - top - kLegendH * scale_ - 2) / (kLegendR + below(span_));
    const double byWidth = width() / (2 * kLegendR + 1.6);
    return std::max(8.0, std::min(byHeight, byWidth));
}

QPointF SelectorSwitch::centre() const {
    const double top = (caption_.isEmpty() ? 2 : kCaptionH * scale_) + kLegendH * scale_ + 2;
    return {width() / 2.0, top + kLegendR * knobRadius()};
}

double SelectorSwitch::angleOf(int index) const {
    const int n = static_cast<int>(legends_.size());
    if (n <= 1)
        return 0;
    return -span_ / 2 + span_ * index / (n - 1);
}

QPointF SelectorSwitch::legendCentre(int index) const {
    const double a = angleOf(index) * kPi / 180;
    const double r = knobRadius() * kLegendR;
    return centre() + QPointF(r * std::sin(a), -r * std::cos(a));
}

void SelectorSwitch::mousePressEvent(QMouseEvent* e) {
    const QPointF pos = e->position();
    int best = -1;
    double bestD = 1e9;
    for (int i = 0; i < legends_.size(); ++i) {
        const QPointF d = pos - legendCentre(i);
        const double dist = std::hypot(d.x(), d.y());
        if (dist < bestD) {
            bestD = dist;
            best = i;
        }
    }
    const QPointF dk = pos - centre();
    if (std::hypot(dk.x(), dk.y()) <= knobRadius() * 1.1) {
        // A click on the knob steps on (back to the start after the last).
        setPosition((position_ + 1) % std::max<int>(1, static_cast<int>(legends_.size())));
        return;
    }
    if (best >= 0 && bestD < knobRadius() * 1.2)
        setPosition(best);
}

void SelectorSwitch::wheelEvent(QWheelEvent* e) {
    const int notches = e->angleDelta().y() / 120;
    if (notches != 0)
        setPosition(position_ - notches);
    e->accept();
}

void SelectorSwitch::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF c = centre();
    const double r = knobRadius();
    if (!caption_.isEmpty())
        paintPlate(p, captionPlate(), caption_);
    // Legends and index dots around.
    p.setFont(plateFont(std::clamp(r * 0.42, 8.0 * scale_, 12.0 * scale_)));
    for (int i = 0; i < legends_.size(); ++i) {
        const double a = angleOf(i) * kPi / 180;
        const QPointF dot = c + QPointF(r * 1.35 * std::sin(a), -r * 1.35 * std::cos(a));
        p.setPen(Qt::NoPen);
        p.setBrush(i == position_ ? QColor(0xf2, 0xf1, 0xea) : QColor(0x8a, 0x8d, 0x90));
        p.drawEllipse(dot, 1.8, 1.8);
        const QPointF lc = legendCentre(i);
        p.setPen(i == position_ ? QColor(0xff, 0xff, 0xff) : QColor(0xb8, 0xbb, 0xbe));
        p.drawText(QRectF(lc.x() - r * 1.2, lc.y() - 9 * scale_, r * 2.4, 18 * scale_), Qt::AlignCenter,
                   legends_[i]);
    }
    paintBezel(p, c, r * 1.08);
    // The knob: black with a white pointer bar.
    QRadialGradient g(c - QPointF(r * 0.3, r * 0.35), r * 1.4);
    g.setColorAt(0, QColor(0x5c, 0x60, 0x64));
    g.setColorAt(1, QColor(0x0e, 0x0e, 0x0f));
    p.setPen(QPen(Qt::black, 0.8));
    p.setBrush(g);
    p.drawEllipse(c, r * 0.92, r * 0.92);
    p.save();
    p.translate(c);
    p.rotate(angleOf(position_));
    QPainterPath bar;
    bar.addRoundedRect(QRectF(-r * 0.2, -r * 0.95, r * 0.4, r * 1.9), r * 0.15, r * 0.15);
    QLinearGradient bg(QPointF(-r * 0.2, 0), QPointF(r * 0.2, 0));
    bg.setColorAt(0, QColor(0x30, 0x32, 0x34));
    bg.setColorAt(0.5, QColor(0x62, 0x66, 0x6a));
    bg.setColorAt(1, QColor(0x22, 0x24, 0x26));
    p.setBrush(bg);
    p.drawPath(bar);
    p.setPen(QPen(QColor(0xf6, 0xf6, 0xf0), std::max(1.5, r * 0.1), Qt::SolidLine, Qt::RoundCap));
    p.drawLine(QPointF(0, -r * 0.85), QPointF(0, -r * 0.45));
    p.restore();
}

} // namespace k528::studio
