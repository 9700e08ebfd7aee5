// A 3 mm panel LED: a dark lens when off, a bright lens with a glow when on.
#pragma once

#include <QColor>
#include <QRectF>

class QPainter;

namespace k528::studio {

enum class LedColor { Off, Green, Red, Amber, Yellow };

// The colour of a lit LED (what a test samples at the lens centre).
QColor ledColor(LedColor c);

// Paints the LED lens in `lens`; a lit LED's glow reaches `glow` times the
// lens radius around it.
void paintLed(QPainter& p, const QRectF& lens, LedColor c, double glow = 1.9);

} // namespace k528::studio
