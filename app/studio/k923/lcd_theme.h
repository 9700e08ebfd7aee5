// Colours of the K923 LCD: the glass under its backlight, lit and unlit dots.
// Two modules are common on panels of this kind: the yellow-green STN
// (positive: dark dots on a yellow-green backlight) and the blue STN
// (negative: white dots on blue). The panel uses yellow-green by default.
#pragma once

#include <QColor>
#include <QString>

namespace k528::studio {

enum class LcdTheme { YellowGreen, Blue };

struct LcdColors {
    QColor glassTop;    // backlit glass, top edge
    QColor glassBottom; // backlit glass, bottom edge
    QColor lit;         // a dot that is on
    QColor unlit;       // a dot that is off: faintly visible on the glass
    QColor sheen;       // reflection on the glass (with alpha)
};

LcdColors lcdColors(LcdTheme theme, bool backlight);

// "yellow-green" / "blue": the names in the settings file.
QString lcdThemeKey(LcdTheme theme);
LcdTheme lcdThemeFromKey(const QString& key, LcdTheme fallback = LcdTheme::YellowGreen);

} // namespace k528::studio
