// The geometry of the K923's 4×20 dot-matrix LCD inside a rectangle: the
// bezel, the glass, and every dot of every 5×8 cell. The widget paints with
// it and the tests measure with it, so what is drawn and what is checked are
// the same numbers.
//
// Sizes are in dot pitches p: a cell is 5×8 dots with one pitch between
// cells (as on a real 2004 module), the dot area 119p × 35p; designed with
// the glass 4p / 3.5p wider on each side and a bezel of 3p. When p can be at
// least two device pixels, p and the gaps between cells are whole numbers of
// device pixels (p as large as fits with thinner margins and cell gaps of at
// least p/3) and the dot area starts on a device pixel, so every dot has the
// same crisp size; the glass and bezel take the rest.
#pragma once

#include "panel/display.h"
#include "panel/lcd_font.h"

#include <QPointF>
#include <QRectF>
#include <optional>

namespace k528::studio {

class LcdLayout {
public:
    // Dot-pitch units.
    static constexpr int kCellGap = 1;
    static constexpr int kDotsWide =
        panel::kLcdColumns * panel::kGlyphColumns + (panel::kLcdColumns - 1) * kCellGap;
    static constexpr int kDotsHigh =
        panel::kLcdRows * panel::kGlyphRows + (panel::kLcdRows - 1) * kCellGap;
    static constexpr double kGlassMarginX = 4.0;
    static constexpr double kGlassMarginY = 3.5;
    static constexpr double kBezel = 3.0;
    // The thinnest margins the pitch may grow into, to keep it a whole number
    // of pixels without shrinking the characters much.
    static constexpr double kMinGlassMargin = 2.0;
    static constexpr double kMinBezel = 1.5;
    static constexpr double kUnitsWide = kDotsWide + 2 * (kGlassMarginX + kBezel);
    static constexpr double kUnitsHigh = kDotsHigh + 2 * (kGlassMarginY + kBezel);

    // Width / height of the whole module with its bezel.
    static constexpr double aspect() { return kUnitsWide / kUnitsHigh; }

    LcdLayout() = default;
    // The layout filling `area` (the bezel takes all of it; the glass and the
    // dots are centred) for a device pixel ratio `dpr`.
    LcdLayout(const QRectF& area, double dpr);

    QRectF bezel() const { return bezel_; }
    QRectF glass() const { return glass_; }
    QRectF dotArea() const;
    double pitch() const { return pitch_; }
    // From a cell to the next one (5 pitches and the gap between cells).
    double cellPitchX() const { return cellPitchX_; }
    double cellPitchY() const { return cellPitchY_; }
    double dotSize() const { return dotSize_; }
    bool pixelAligned() const { return aligned_; }

    // The 5×8-dot box of cell (row, column).
    QRectF cellRect(int row, int column) const;
    // The dot (x 0..4, y 0..7) of cell (row, column).
    QRectF dotRect(int row, int column, int x, int y) const;
    // The cell under `p`, if any (gaps between cells belong to no cell).
    std::optional<std::pair<int, int>> cellAt(QPointF p) const;

private:
    QRectF bezel_;
    QRectF glass_;
    QPointF origin_; // top-left of dot (0,0) of cell (0,0)
    double pitch_ = 0;
    double dotSize_ = 0;
    double cellPitchX_ = 0;
    double cellPitchY_ = 0;
    bool aligned_ = false;
};

} // namespace k528::studio
