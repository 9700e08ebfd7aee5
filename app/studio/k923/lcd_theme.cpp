#include "k923/lcd_theme.h"

namespace k528::studio {

namespace {
QColor mix(const QColor& a, const QColor& b, double t) {
    return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                            static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                            static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t));
}
} // namespace

LcdColors lcdColors(LcdTheme theme, bool backlight) {
    LcdColors c;
    if (theme == LcdTheme::Blue) {
        c.glassTop = QColor(0x2a, 0x4c, 0xe8);
        c.glassBottom = QColor(0x1b, 0x35, 0xc4);
        c.lit = QColor(0xf2, 0xf6, 0xff);
        c.unlit = mix(QColor(0x22, 0x40, 0xd6), QColor(0xff, 0xff, 0xff), 0.10);
        c.sheen = QColor(255, 255, 255, 26);
    } else {
        c.glassTop = QColor(0xbf, 0xd6, 0x52);
        c.glassBottom = QColor(0xa4, 0xc0, 0x34);
        c.lit = QColor(0x1f, 0x2b, 0x0c);
        c.unlit = mix(QColor(0xb2, 0xcb, 0x43), QColor(0x1f, 0x2b, 0x0c), 0.06);
        c.sheen = QColor(255, 255, 240, 30);
    }
    if (!backlight) {
        // Without the backlight the glass is grey-dark and only reflects.
        const QColor dark(0x3c, 0x40, 0x36);
        c.glassTop = mix(c.glassTop, dark, 0.75);
        c.glassBottom = mix(c.glassBottom, dark, 0.8);
        c.unlit = mix(c.unlit, dark, 0.78);
        c.lit = theme == LcdTheme::Blue ? mix(c.lit, dark, 0.7) : c.lit;
    }
    return c;
}

QString lcdThemeKey(LcdTheme theme) {
    return theme == LcdTheme::Blue ? "blue" : "yellow-green";
}

LcdTheme lcdThemeFromKey(const QString& key, LcdTheme fallback) {
    if (key == "blue")
        return LcdTheme::Blue;
    if (key == "yellow-green")
        return LcdTheme::YellowGreen;
    return fallback;
}

} // namespace k528::studio
