#include "k923/lcd_widget.h"

#include "util/utf8.h"

#include <QLinearGradient>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace k528::studio {

LcdWidget::LcdWidget(QWidget* parent) : QWidget(parent) {
    setObjectName("k923.lcd");
    setAttribute(Qt::WA_OpaquePaintEvent);
    QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
    for (auto& row : cells_)
        row.fill(U' ');
    for (auto& line : lcd_.lines)
        line = std::string(panel::kLcdColumns, ' ');
    blinkTimer_.setInterval(kBlinkHalfPeriodMs);
    connect(&blinkTimer_, &QTimer::timeout, this, [this] {
        blinkPhase_ = !blinkPhase_;
        updateBlinkField(lcd_);
        emit blinkPhaseChanged(blinkPhase_);
    });
}

void LcdWidget::setLcd(const panel::Lcd& lcd) {
    for (int r = 0; r < panel::kLcdRows; ++r) {
        const std::vector<char32_t> cps = utf8::decode(lcd.lines[static_cast<std::size_t>(r)]);
        for (int c = 0; c < panel::kLcdColumns; ++c) {
            const char32_t cp =
                static_cast<std::size_t>(c) < cps.size() ? cps[static_cast<std::size_t>(c)] : U' ';
            char32_t& cell = cells_[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
            if (cell != cp) {
                cell = cp;
                updateCell(r, c);
            }
        }
    }
    const bool blinkMoved = lcd.blinkRow != lcd_.blinkRow || lcd.blinkColumn != lcd_.blinkColumn ||
                            lcd.blinkLength != lcd_.blinkLength;
    if (blinkMoved)
        updateBlinkField(lcd_);
    lcd_ = lcd;
    if (blinkMoved) {
        updateBlinkField(lcd_);
        restartBlinking();
    }
}

char32_t LcdWidget::character(int row, int column) const {
    if (row < 0 || row >= panel::kLcdRows || column < 0 || column >= panel::kLcdColumns)
        return 0;
    return cells_[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)];
}

QString LcdWidget::text() const {
    QStringList lines;
    for (const auto& row : cells_)
        lines << QString::fromUcs4(row.data(), static_cast<qsizetype>(row.size()));
    return lines.join('\n');
}

void LcdWidget::setTheme(LcdTheme theme) {
    if (theme == theme_)
        return;
    theme_ = theme;
    dotsFor_ = -1;
    update();
}

void LcdWidget::setBacklight(bool on) {
    if (on == backlight_)
        return;
    backlight_ = on;
    dotsFor_ = -1;
    update();
}

void LcdWidget::setBlinkStyle(BlinkStyle style) {
    if (style == blinkStyle_)
        return;
    blinkStyle_ = style;
    updateBlinkField(lcd_);
}

void LcdWidget::setBlinkFrozen(bool frozen) {
    blinkFrozen_ = frozen;
    if (frozen)
        blinkTimer_.stop();
    else if (lcd_.blinkLength > 0 && !blinkTimer_.isActive())
        blinkTimer_.start();
}

void LcdWidget::setBlinkPhase(bool alternate) {
    if (alternate == blinkPhase_)
        return;
    blinkPhase_ = alternate;
    updateBlinkField(lcd_);
    if (blinkTimer_.isActive())
        blinkTimer_.start(); // a full half period from now
    emit blinkPhaseChanged(blinkPhase_);
}

bool LcdWidget::isBlinking(int row, int column) const {
    return lcd_.blinkLength > 0 && row == lcd_.blinkRow && column >= lcd_.blinkColumn &&
           column < lcd_.blinkColumn + lcd_.blinkLength;
}

void LcdWidget::restartBlinking() {
    // A field that starts blinking (or moves) shows its characters first, so
    // what was just typed is seen at once.
    if (!blinkFrozen_ && blinkPhase_) {
        blinkPhase_ = false;
        emit blinkPhaseChanged(false);
    }
    if (lcd_.blinkLength > 0 && !blinkFrozen_)
        blinkTimer_.start();
    else
        blinkTimer_.stop();
}

void LcdWidget::updateCell(int row, int column) {
    const QRectF r = layout().cellRect(row, column);
    update(r.toAlignedRect().adjusted(-1, -1, 1, 1));
}

void LcdWidget::updateBlinkField(const panel::Lcd& lcd) {
    if (lcd.blinkLength <= 0 || lcd.blinkRow < 0 || lcd.blinkRow >= panel::kLcdRows)
        return;
    for (int c = std::max(0, lcd.blinkColumn);
         c < std::min(panel::kLcdColumns, lcd.blinkColumn + lcd.blinkLength); ++c)
        updateCell(lcd.blinkRow, c);
}

LcdLayout LcdWidget::layout() const {
    return LcdLayout(QRectF(rect()), devicePixelRatioF());
}

LcdColors LcdWidget::colors() const {
    return lcdColors(theme_, backlight_);
}

panel::Glyph LcdWidget::shownGlyph(int row, int column) const {
    if (isBlinking(row, column) && blinkPhase_)
        return blinkStyle_ == BlinkStyle::Block ? panel::lcdBlockGlyph() : panel::Glyph{};
    return panel::lcdGlyphOrPlaceholder(character(row, column));
}

bool LcdWidget::isDotLit(int row, int column, int x, int y) const {
    return shownGlyph(row, column).dot(x, y);
}

int LcdWidget::heightForWidth(int width) const {
    return static_cast<int>(std::lround(width / LcdLayout::aspect()));
}

QSize LcdWidget::sizeHint() const {
    return {560, heightForWidth(560)};
}

QSize LcdWidget::minimumSizeHint() const {
    return {200, heightForWidth(200)};
}

void LcdWidget::resizeEvent(QResizeEvent* event) {
    dotsFor_ = -1;
    QWidget::resizeEvent(event);
}

void LcdWidget::rebuildDots() {
    const LcdLayout l = layout();
    const double dpr = devicePixelRatioF();
    const LcdColors col = colors();
    const int px = std::max(1, static_cast<int>(std::lround(l.dotSize() * dpr)));
    const auto draw = [&](const QColor& colour) {
        QImage img(px, px, QImage::Format_ARGB32_Premultiplied);
        img.fill(Qt::transparent);
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing, px >= 4);
        p.setPen(Qt::NoPen);
        p.setBrush(colour);
        const double radius = px >= 4 ? 0.22 * px : 0.0;
        p.drawRoundedRect(QRectF(0, 0, px, px), radius, radius);
        p.end();
        img.setDevicePixelRatio(dpr);
        return img;
    };
    litDot_ = draw(col.lit);
    unlitDot_ = draw(col.unlit);
    dotsFor_ = l.dotSize() * dpr;
}

void LcdWidget::paintEvent(QPaintEvent* event) {
    QPainter p(this);
    const LcdLayout l = layout();
    const LcdColors col = colors();
    const QRectF bezel = l.bezel();
    const QRectF glass = l.glass();

    // The bezel: black moulded frame around the module's window.
    p.setRenderHint(QPainter::Antialiasing, true);
    p.fillRect(rect(), palette().window());
    const double radius = std::min(bezel.height() * 0.06, l.pitch() * 2.5);
    QLinearGradient frame(bezel.topLeft(), bezel.bottomLeft());
    frame.setColorAt(0, QColor(0x34, 0x36, 0x38));
    frame.setColorAt(0.5, QColor(0x1d, 0x1e, 0x20));
    frame.setColorAt(1, QColor(0x2b, 0x2c, 0x2e));
    p.setPen(QPen(QColor(0x0c, 0x0c, 0x0d), 1));
    p.setBrush(frame);
    p.drawRoundedRect(bezel.adjusted(0.5, 0.5, -0.5, -0.5), radius, radius);

    // The glass, lit from behind.
    QLinearGradient light(glass.topLeft(), glass.bottomLeft());
    light.setColorAt(0, col.glassTop);
    light.setColorAt(1, col.glassBottom);
    p.setPen(Qt::NoPen);
    p.fillRect(glass, light);
    // Shade along the top and left edges: the glass sits below the bezel.
    const double edge = std::max(1.5, l.pitch() * 1.2);
    QLinearGradient topShade(glass.topLeft(), glass.topLeft() + QPointF(0, edge));
    topShade.setColorAt(0, QColor(0, 0, 0, 90));
    topShade.setColorAt(1, QColor(0, 0, 0, 0));
    p.fillRect(QRectF(glass.topLeft(), QSizeF(glass.width(), edge)), topShade);
    QLinearGradient leftShade(glass.topLeft(), glass.topLeft() + QPointF(edge, 0));
    leftShade.setColorAt(0, QColor(0, 0, 0, 60));
    leftShade.setColorAt(1, QColor(0, 0, 0, 0));
    p.fillRect(QRectF(glass.topLeft(), QSizeF(edge, glass.height())), leftShade);

    // The dots.
    const double dpr = devicePixelRatioF();
    if (l.pixelAligned() && dotsFor_ != l.dotSize() * dpr)
        rebuildDots();
    p.setRenderHint(QPainter::Antialiasing, false);
    const QRect dirty = event->rect();
    for (int r = 0; r < panel::kLcdRows; ++r) {
        for (int c = 0; c < panel::kLcdColumns; ++c) {
            if (!l.cellRect(r, c).toAlignedRect().intersects(dirty))
                continue;
            const panel::Glyph g = shownGlyph(r, c);
            for (int y = 0; y < panel::kGlyphRows; ++y) {
                for (int x = 0; x < panel::kGlyphColumns; ++x) {
                    const QRectF d = l.dotRect(r, c, x, y);
                    const bool on = g.dot(x, y);
                    if (l.pixelAligned())
                        p.drawImage(d.topLeft(), on ? litDot_ : unlitDot_);
                    else
                        p.fillRect(d, on ? col.lit : col.unlit);
                }
            }
        }
    }

    // A faint reflection across the upper part of the glass.
    p.setRenderHint(QPainter::Antialiasing, true);
    QLinearGradient sheen(glass.topLeft(),
                          QPointF(glass.left() + glass.width() * 0.35, glass.bottom()));
    sheen.setColorAt(0, col.sheen);
    sheen.setColorAt(
        0.55, QColor(col.sheen.red(), col.sheen.green(), col.sheen.blue(), col.sheen.alpha() / 3));
    sheen.setColorAt(1, QColor(col.sheen.red(), col.sheen.green(), col.sheen.blue(), 0));
    p.fillRect(glass, sheen);
}

} // namespace k528::studio
