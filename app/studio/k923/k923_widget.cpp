#include "k923/k923_widget.h"

#include "k923/key_face.h"
#include "k923/key_map.h"
#include "k923/keyboard_map_dialog.h"
#include "k923/lcd_widget.h"
#include "k923/panel_key.h"

#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QLinearGradient>
#include <QMenu>
#include <QPainter>
#include <QRadialGradient>
#include <QSettings>
#include <cmath>

namespace k528::studio {

using panel::Key;
using panel::KeyPress;

namespace {
const char* const kThemeSetting = "k923/lcdTheme";

QFont plateFont(double pixelSize, int letterSpacingPercent = 100) {
    QFont f;
    f.setFamilies({"DejaVu Sans", "Liberation Sans", "Arial"});
    f.setStyleHint(QFont::SansSerif);
    f.setPixelSize(std::max(6, static_cast<int>(std::lround(pixelSize))));
    f.setBold(true);
    f.setLetterSpacing(QFont::PercentageSpacing, letterSpacingPercent);
    return f;
}
} // namespace

K923Widget::K923Widget(QWidget* parent) : QWidget(parent) {
    setObjectName("k923");
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);

    lcd_ = new LcdWidget(this);
    lcd_->setTheme(lcdThemeFromKey(QSettings().value(kThemeSetting).toString()));
    for (int i = 0; i < panel::kKeyCount; ++i) {
        const Key k = static_cast<Key>(i);
        auto* key = new PanelKey(k, this);
        keys_[static_cast<std::size_t>(i)] = key;
        if (repeatsWhenHeld(k)) {
            key->setAutoRepeat(true);
            key->setAutoRepeatDelay(450);
            key->setAutoRepeatInterval(110);
        }
        connect(key, &PanelKey::pressed, this, [this, k] {
            keyDown(k, QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier),
                    held_ && held_->key == k);
        });
        connect(key, &PanelKey::released, this, [this, key] {
            if (!key->isDown()) // not an auto-repeat's release
                held_.reset();
        });
    }
    display_ = blankDisplay();
    lcd_->setLcd(display_.lcd);
    applyLeds();
    retranslate();
}

panel::Display K923Widget::blankDisplay() {
    panel::Display d;
    for (auto& line : d.lcd.lines)
        line = std::string(panel::kLcdColumns, ' ');
    return d;
}

QRect K923Widget::keyRect(Key k) const {
    return key(k)->geometry();
}

QRect K923Widget::lcdRect() const {
    return lcd_->geometry();
}

std::optional<QPointF> K923Widget::ledCentre(Key k) const {
    const PanelKey* pk = key(k);
    const QRectF led = pk->ledRect();
    if (led.isEmpty())
        return std::nullopt;
    return QPointF(pk->geometry().topLeft()) + led.center();
}

LcdTheme K923Widget::lcdTheme() const {
    return lcd_->theme();
}

void K923Widget::setLcdTheme(LcdTheme theme) {
    lcd_->setTheme(theme);
    QSettings().setValue(kThemeSetting, lcdThemeKey(theme));
}

int K923Widget::heightForWidth(int width) const {
    return static_cast<int>(std::lround(width / K923Layout::aspect()));
}

QSize K923Widget::sizeHint() const {
    const double u = 48;
    return {static_cast<int>(K923Layout::kWidthU * u), static_cast<int>(K923Layout::kHeightU * u)};
}

QSize K923Widget::minimumSizeHint() const {
    const double u = 28;
    return {static_cast<int>(K923Layout::kWidthU * u), static_cast<int>(K923Layout::kHeightU * u)};
}

void K923Widget::setDisplay(const panel::Display& display) {
    if (display == display_)
        return;
    if (display.lcd != display_.lcd)
        lcd_->setLcd(display.lcd);
    const bool ledsChanged = display.leds != display_.leds;
    display_ = display;
    if (ledsChanged)
        applyLeds();
}

void K923Widget::applyLeds() {
    const panel::Leds& l = display_.leds;
    for (int k = 1; k <= 12; ++k) {
        const bool g = l.greenOn(k);
        const bool r = l.redOn(k);
        key(static_cast<Key>(static_cast<int>(Key::K1) + k - 1))
            ->setLed(g && r ? LedColor::Amber
                     : g    ? LedColor::Green
                     : r    ? LedColor::Red
                            : LedColor::Off);
    }
    for (int n = 1; n <= 4; ++n)
        key(static_cast<Key>(static_cast<int>(Key::L1) + n - 1))
            ->setLed(l.overrideOn(n) ? LedColor::Green : LedColor::Off);
    key(Key::Shift)->setLed(shiftLatched_ || l.shift ? LedColor::Yellow : LedColor::Off);
}

void K923Widget::setShiftLatched(bool latched) {
    if (latched == shiftLatched_)
        return;
    shiftLatched_ = latched;
    applyLeds();
    emit shiftLatchChanged(latched);
}

void K923Widget::press(KeyPress kp) {
    if (kp.key == Key::Shift) {
        setShiftLatched(!shiftLatched_);
        return;
    }
    if (shiftLatched_) {
        kp.shift = true;
        setShiftLatched(false);
    }
    emit keyPressed(kp);
}

void K923Widget::keyDown(Key k, bool shiftModifier, bool repeat) {
    if (repeat && held_ && held_->key == k) {
        emit keyPressed(*held_); // a held key repeats as it was first pressed
        return;
    }
    const bool latched = shiftLatched_;
    press(KeyPress{k, shiftModifier});
    held_ = k == Key::Shift ? std::nullopt
                            : std::optional<KeyPress>(KeyPress{k, shiftModifier || latched});
}

bool K923Widget::event(QEvent* e) {
    // While the panel has the focus, its keys win over the window's shortcuts.
    if (e->type() == QEvent::ShortcutOverride) {
        auto* ke = static_cast<QKeyEvent*>(e);
        if (mapPcKey(*ke)) {
            e->accept();
            return true;
        }
    }
    return QWidget::event(e);
}

void K923Widget::keyPressEvent(QKeyEvent* e) {
    const auto kp = mapPcKey(*e);
    if (!kp) {
        QWidget::keyPressEvent(e); // not ours: let the parents have it
        return;
    }
    e->accept();
    if (e->isAutoRepeat()) {
        if (repeatsWhenHeld(kp->key))
            keyDown(kp->key, kp->shift, true);
        return;
    }
    releasePcKey();
    if (kp->key != Key::Shift) {
        pcDown_ = kp->key;
        key(kp->key)->setDown(true);
    }
    held_.reset();
    keyDown(kp->key, kp->shift, false);
}

void K923Widget::keyReleaseEvent(QKeyEvent* e) {
    if (!e->isAutoRepeat() && mapPcKey(*e)) {
        releasePcKey();
        held_.reset();
        e->accept();
        return;
    }
    QWidget::keyReleaseEvent(e);
}

void K923Widget::releasePcKey() {
    if (pcDown_)
        key(*pcDown_)->setDown(false);
    pcDown_.reset();
}

void K923Widget::focusInEvent(QFocusEvent* e) {
    update();
    QWidget::focusInEvent(e);
}

void K923Widget::focusOutEvent(QFocusEvent* e) {
    releasePcKey();
    held_.reset();
    update();
    QWidget::focusOutEvent(e);
}

void K923Widget::resizeEvent(QResizeEvent* e) {
    placeChildren();
    QWidget::resizeEvent(e);
}

void K923Widget::placeChildren() {
    const K923Layout l(size());
    lcd_->setGeometry(l.lcd());
    for (int i = 0; i < panel::kKeyCount; ++i)
        keys_[static_cast<std::size_t>(i)]->setGeometry(l.key(static_cast<Key>(i)));
}

void K923Widget::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.fillRect(rect(), palette().window());
    const K923Layout l(size());
    const double u = l.unit();
    const QRectF plate = l.plate().adjusted(0.5, 0.5, -0.5, -0.5);
    const double radius = 0.16 * u;

    // The front plate: powder-coated light grey aluminium.
    QLinearGradient metal(plate.topLeft(), plate.bottomLeft());
    metal.setColorAt(0, QColor(0xc9, 0xcb, 0xc7));
    metal.setColorAt(1, QColor(0xb0, 0xb2, 0xae));
    p.setPen(QPen(QColor(0x6f, 0x71, 0x6e), 1));
    p.setBrush(metal);
    p.drawRoundedRect(plate, radius, radius);
    p.setPen(QPen(QColor(255, 255, 255, 90), 1));
    p.setBrush(Qt::NoBrush);
    p.drawRoundedRect(plate.adjusted(1.5, 1.5, -1.5, -1.5), radius * 0.9, radius * 0.9);

    // Keyboard focus: a ring round the plate says the PC keyboard is on it.
    if (hasFocus()) {
        QColor ring = palette().color(QPalette::Highlight);
        p.setPen(QPen(ring, std::max(2.0, 0.04 * u)));
        p.drawRoundedRect(plate.adjusted(2.5, 2.5, -2.5, -2.5), radius * 0.85, radius * 0.85);
    }

    // The screws.
    for (const QPointF& c : l.screws()) {
        const double r = l.screwRadius();
        QRadialGradient head(c - QPointF(r * 0.35, r * 0.35), r * 1.4);
        head.setColorAt(0, QColor(0xee, 0xee, 0xea));
        head.setColorAt(1, QColor(0x7c, 0x7e, 0x7b));
        p.setPen(QPen(QColor(0x5c, 0x5e, 0x5b), 1));
        p.setBrush(head);
        p.drawEllipse(c, r, r);
        p.setPen(QPen(QColor(0x4a, 0x4b, 0x49), std::max(1.0, r * 0.22)));
        p.drawLine(c + QPointF(-r * 0.6, -r * 0.3), c + QPointF(r * 0.6, r * 0.3));
    }

    // The nameplate print.
    const QRectF name = l.nameplate();
    p.setPen(QColor(0x24, 0x34, 0x52));
    p.setFont(plateFont(name.height() * 0.62, 112));
    p.drawText(name, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("КОНСТАР"));
    p.setFont(plateFont(name.height() * 0.62, 104));
    p.drawText(name, Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("K923"));

    // The window the LCD sits in: a dark recess a little larger than it.
    const QRectF win = QRectF(l.lcd()).adjusted(-0.05 * u, -0.05 * u, 0.05 * u, 0.05 * u);
    QLinearGradient recess(win.topLeft(), win.bottomLeft());
    recess.setColorAt(0, QColor(0x5a, 0x5c, 0x59));
    recess.setColorAt(1, QColor(0xe2, 0xe3, 0xe0));
    p.setPen(Qt::NoPen);
    p.setBrush(recess);
    p.drawRoundedRect(win, 0.08 * u, 0.08 * u);

    // Printed frames round the key groups.
    p.setPen(QPen(QColor(0x62, 0x65, 0x62), std::max(1.0, 0.025 * u)));
    p.setBrush(QColor(0, 0, 0, 14));
    for (const QRectF& f : l.groupFrames())
        p.drawRoundedRect(f, 0.1 * u, 0.1 * u);
}

void K923Widget::contextMenuEvent(QContextMenuEvent* e) {
    QMenu menu(this);
    menu.addAction(tr("Keyboard map…"), this, &K923Widget::showKeyboardMap);
    menu.addAction(tr("Copy the LCD text"), this,
                   [this] { QGuiApplication::clipboard()->setText(lcd_->text()); });
    menu.addSeparator();
    auto* group = new QActionGroup(&menu);
    const auto themeAction = [&](const QString& text, LcdTheme theme) {
        QAction* a = menu.addAction(text, this, [this, theme] { setLcdTheme(theme); });
        a->setCheckable(true);
        a->setChecked(lcdTheme() == theme);
        group->addAction(a);
    };
    themeAction(tr("LCD: yellow-green backlight"), LcdTheme::YellowGreen);
    themeAction(tr("LCD: blue backlight"), LcdTheme::Blue);
    menu.exec(e->globalPos());
}

void K923Widget::showKeyboardMap() {
    auto* dialog = findChild<KeyboardMapDialog*>();
    if (!dialog) {
        dialog = new KeyboardMapDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void K923Widget::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void K923Widget::retranslate() {
    setToolTip(
        tr("The K923 operator panel. Click it to work it from the PC keyboard too (each key's "
           "tooltip names its PC key; Tab leaves the panel). Right-click for the keyboard map."));
    setAccessibleName(tr("K923 operator panel"));
    for (PanelKey* k : keys_)
        k->setToolTip(keyToolTip(k->key()));
}

} // namespace k528::studio
