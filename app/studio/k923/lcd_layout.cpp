#include "k923/lcd_layout.h"

#include <algorithm>
#include <cmath>

namespace k528::studio {

namespace {
constexpr int kCols = panel::kLcdColumns;
constexpr int kRows = panel::kLcdRows;
constexpr int kDotsX = panel::kLcdColumns * panel::kGlyphColumns; // 100
constexpr int kDotsY = panel::kLcdRows * panel::kGlyphRows;       // 32
} // namespace

LcdLayout::LcdLayout(const QRectF& area, double dpr) {
    bezel_ = area;
    dpr = dpr > 0 ? dpr : 1.0;
    const double wPx = area.width() * dpr;
    const double hPx = area.height() * dpr;

    // Crisp dots: the largest whole-pixel pitch for which the characters,
    // gaps between cells of at least a third of a pitch and thin margins
    // fit. The gaps between cells then grow up to one pitch, as designed.
    int pPx = 0;
    for (int p = static_cast<int>(std::floor(std::min(wPx / kDotsX, hPx / kDotsY))); p >= 2; --p) {
        const double gapMin = std::max(1.0, std::ceil(p / 3.0));
        const double margin = (kMinGlassMargin + kMinBezel) * p;
        if (kDotsX * p + (kCols - 1) * gapMin + 2 * margin <= wPx &&
            kDotsY * p + (kRows - 1) * gapMin + 2 * margin <= hPx) {
            pPx = p;
            break;
        }
    }
    aligned_ = pPx >= 2;
    double gapX = 0;
    double gapY = 0;
    if (aligned_) {
        const double margin = (kMinGlassMargin + kMinBezel) * pPx;
        gapX = std::min<double>(pPx, std::floor((wPx - 2 * margin - kDotsX * pPx) / (kCols - 1)));
        gapY = std::min<double>(pPx, std::floor((hPx - 2 * margin - kDotsY * pPx) / (kRows - 1)));
        const double dotGapPx = std::max(1.0, std::round(0.14 * pPx));
        pitch_ = pPx / dpr;
        dotSize_ = (pPx - dotGapPx) / dpr;
        gapX /= dpr;
        gapY /= dpr;
    } else {
        // Too small for whole pixels: the designed proportions, smoothed.
        pitch_ = std::max(0.0, std::min(area.width() / kUnitsWide, area.height() / kUnitsHigh));
        dotSize_ = 0.8 * pitch_;
        gapX = gapY = kCellGap * pitch_;
    }
    cellPitchX_ = panel::kGlyphColumns * pitch_ + gapX;
    cellPitchY_ = panel::kGlyphRows * pitch_ + gapY;

    const QPointF centre = area.center();
    const QSizeF dots = dotArea().size();
    double ox = centre.x() - dots.width() / 2;
    double oy = centre.y() - dots.height() / 2;
    if (aligned_) {
        ox = std::round(ox * dpr) / dpr;
        oy = std::round(oy * dpr) / dpr;
    }
    origin_ = {ox, oy};
    // The bezel is up to kBezel pitches thick; the glass fills the rest.
    const double leftover =
        std::min(area.width() - dots.width(), area.height() - dots.height()) / 2;
    const double bezel = std::clamp(leftover * 0.45, std::min(1.0, leftover), kBezel * pitch_);
    glass_ = area.adjusted(bezel, bezel, -bezel, -bezel);
}

QRectF LcdLayout::dotArea() const {
    return {origin_,
            QSizeF((kCols - 1) * cellPitchX_ + (panel::kGlyphColumns - 1) * pitch_ + dotSize_,
                   (kRows - 1) * cellPitchY_ + (panel::kGlyphRows - 1) * pitch_ + dotSize_)};
}

QRectF LcdLayout::cellRect(int row, int column) const {
    const double x = origin_.x() + column * cellPitchX_;
    const double y = origin_.y() + row * cellPitchY_;
    return {x, y, (panel::kGlyphColumns - 1) * pitch_ + dotSize_,
            (panel::kGlyphRows - 1) * pitch_ + dotSize_};
}

QRectF LcdLayout::dotRect(int row, int column, int x, int y) const {
    const QRectF cell = cellRect(row, column);
    return {cell.x() + x * pitch_, cell.y() + y * pitch_, dotSize_, dotSize_};
}

std::optional<std::pair<int, int>> LcdLayout::cellAt(QPointF p) const {
    for (int r = 0; r < panel::kLcdRows; ++r)
        for (int c = 0; c < panel::kLcdColumns; ++c)
            if (cellRect(r, c).contains(p))
                return std::make_pair(r, c);
    return std::nullopt;
}

} // namespace k528::studio
