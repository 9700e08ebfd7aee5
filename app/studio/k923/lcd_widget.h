// The K923's 4×20 character LCD: paints a panel::Lcd as 5×8 dots per cell,
// computed from the widget size (crisp at any scale, no scaled bitmap), with
// the gaps between cells of a real module, faintly visible unlit dots, the
// backlight and the bezel.
//
// The blinking field (Lcd::blinkRow/blinkColumn/blinkLength) alternates
// between its characters and the all-dots block (or nothing) twice a second,
// driven by a timer here; freeze it for tests and screenshots.
#pragma once

#include "k923/lcd_layout.h"
#include "k923/lcd_theme.h"
#include "panel/display.h"

#include <QImage>
#include <QTimer>
#include <QWidget>
#include <array>

namespace k528::studio {

class LcdWidget : public QWidget {
    Q_OBJECT
    Q_PROPERTY(bool blinkFrozen READ blinkFrozen WRITE setBlinkFrozen)
    Q_PROPERTY(bool blinkPhase READ blinkPhase WRITE setBlinkPhase NOTIFY blinkPhaseChanged)
    Q_PROPERTY(bool backlight READ backlight WRITE setBacklight)
public:
    // What the blinking field shows in its second phase.
    enum class BlinkStyle { Block, Blank };
    // Half a blink period: the field changes every 250 ms (2 Hz).
    static constexpr int kBlinkHalfPeriodMs = 250;

    explicit LcdWidget(QWidget* parent = nullptr);

    // Shows `lcd`; repaints only the cells that changed.
    void setLcd(const panel::Lcd& lcd);
    const panel::Lcd& lcd() const { return lcd_; }
    // The code point shown (without blinking) in cell (row, column).
    char32_t character(int row, int column) const;
    // The four lines as text (for copying).
    QString text() const;

    LcdTheme theme() const { return theme_; }
    void setTheme(LcdTheme theme);
    bool backlight() const { return backlight_; }
    void setBacklight(bool on);
    BlinkStyle blinkStyle() const { return blinkStyle_; }
    void setBlinkStyle(BlinkStyle style);

    // Frozen: the timer stops and the phase stays where it is (or is set).
    bool blinkFrozen() const { return blinkFrozen_; }
    void setBlinkFrozen(bool frozen);
    // false: the blinking field shows its characters; true: the block/blank.
    bool blinkPhase() const { return blinkPhase_; }
    void setBlinkPhase(bool alternate);
    bool isBlinking(int row, int column) const;

    // The geometry of the current size; dotRect() and friends are in widget
    // coordinates.
    LcdLayout layout() const;
    // Whether dot (x, y) of cell (row, column) is drawn lit right now.
    bool isDotLit(int row, int column, int x, int y) const;
    LcdColors colors() const;

    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void blinkPhaseChanged(bool alternate);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void updateCell(int row, int column);
    void updateBlinkField(const panel::Lcd& lcd);
    void restartBlinking();
    void rebuildDots();
    panel::Glyph shownGlyph(int row, int column) const;

    panel::Lcd lcd_;
    std::array<std::array<char32_t, panel::kLcdColumns>, panel::kLcdRows> cells_{};
    LcdTheme theme_ = LcdTheme::YellowGreen;
    bool backlight_ = true;
    BlinkStyle blinkStyle_ = BlinkStyle::Block;
    bool blinkFrozen_ = false;
    bool blinkPhase_ = false;
    QTimer blinkTimer_;
    // One lit and one unlit dot, drawn once per size in device pixels.
    QImage litDot_;
    QImage unlitDot_;
    double dotsFor_ = -1; // the dot size the images were drawn for
};

} // namespace k528::studio
