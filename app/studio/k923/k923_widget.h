// The K923 operator panel on the desktop: the 4×20 LCD, the 26 function
// keys, the system keyboard and the 17 LEDs, drawn like the hardware.
//
// It only shows and reports: setDisplay() gives it what the panel model
// produced (LCD lines, blinking field, LEDs); a key pressed with the mouse or
// the PC keyboard is emitted as keyPressed(). It never talks to the engine.
//
// SHIFT latches on the panel: press SHIFT, then ▲, and keyPressed() carries
// SHIFT+UP; the SHIFT LED is lit while the latch is set (or while the model's
// Display says so). A lone SHIFT is never emitted. The PC keyboard acts only
// while the panel has the focus (click it, or Tab to it); see key_map.h.
#pragma once

#include "k923/k923_layout.h"
#include "k923/lcd_theme.h"
#include "panel/display.h"
#include "panel/keys.h"

#include <QMetaType>
#include <QWidget>
#include <array>
#include <optional>

Q_DECLARE_METATYPE(k528::panel::KeyPress)

namespace k528::studio {

class LcdWidget;
class PanelKey;

class K923Widget : public QWidget {
    Q_OBJECT
    Q_PROPERTY(bool shiftLatched READ shiftLatched WRITE setShiftLatched NOTIFY shiftLatchChanged)
public:
    explicit K923Widget(QWidget* parent = nullptr);

    // What the panel shows before the panel model gives it anything: the LCD
    // lit and empty, all LEDs off.
    static panel::Display blankDisplay();

    const panel::Display& display() const { return display_; }
    LcdWidget* lcd() const { return lcd_; }
    PanelKey* key(panel::Key k) const { return keys_[static_cast<std::size_t>(k)]; }
    // Geometry in widget coordinates (what the mouse and the tests use).
    QRect keyRect(panel::Key k) const;
    QRect lcdRect() const;
    // The centre of the LED of K1..K12, L1..L4 or SHIFT; nullopt for other keys.
    std::optional<QPointF> ledCentre(panel::Key k) const;
    K923Layout panelLayout() const { return K923Layout(size()); }

    bool shiftLatched() const { return shiftLatched_; }
    LcdTheme lcdTheme() const;
    // Sets the LCD colours and remembers them in the settings.
    void setLcdTheme(LcdTheme theme);

    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

public slots:
    // Shows `display`; only what changed is repainted (cheap at 50 Hz).
    void setDisplay(const k528::panel::Display& display);
    void setShiftLatched(bool latched);
    // Presses a key as the operator would (SHIFT toggles the latch; a latched
    // SHIFT is added to the next key and released).
    void press(k528::panel::KeyPress press);
    void showKeyboardMap();

signals:
    void keyPressed(k528::panel::KeyPress press);
    void shiftLatchChanged(bool latched);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void placeChildren();
    void applyLeds();
    void retranslate();
    // A key going down (first press or a repeat while held).
    void keyDown(panel::Key k, bool shiftModifier, bool repeat);
    void releasePcKey();

    LcdWidget* lcd_ = nullptr;
    std::array<PanelKey*, panel::kKeyCount> keys_{};
    panel::Display display_;
    bool shiftLatched_ = false;
    // The SHIFT state of the key being held, for its repeats.
    std::optional<panel::KeyPress> held_;
    // The key shown pressed by the PC keyboard.
    std::optional<panel::Key> pcDown_;
};

} // namespace k528::studio
