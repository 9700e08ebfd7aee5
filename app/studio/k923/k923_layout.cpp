#include "k923/k923_layout.h"

#include "k923/lcd_layout.h"

#include <algorithm>
#include <cmath>

namespace k528::studio {

using panel::Key;

namespace {
constexpr double kMargin = 0.35;  // plate edge to the content
constexpr double kContent = 8.4;  // content width: 8 pitches and a group gap
constexpr double kGroupGap = 0.4; // between key groups side by side
constexpr double kInset = 0.07;   // a key is its cell less this on each side
constexpr double kNameTop = 0.2;
constexpr double kNameHeight = 0.42;
constexpr double kLcdTop = 0.72;
constexpr double kFTop = 4.1; // the mode keys
constexpr double kFHeight = 0.78;
constexpr double kKTop = 5.12;   // K1..K12, L1..L4
constexpr double kSysTop = 7.47; // the system keyboard (5 rows)

Key plus(Key base, int n) {
    return static_cast<Key>(static_cast<int>(base) + n);
}
} // namespace

K923Layout::K923Layout(QSize size) {
    u_ = std::min(size.width() / kWidthU, size.height() / kHeightU);
    const double w = kWidthU * u_;
    const double h = kHeightU * u_;
    plate_ = QRectF(std::round((size.width() - w) / 2), std::round((size.height() - h) / 2), w, h);

    // Mode keys: eight across the content width, a little wider than square.
    const double fPitch = kContent / 8;
    for (int i = 0; i < 8; ++i)
        keys_[static_cast<std::size_t>(plus(Key::F1, i))] =
            snap(kMargin + i * fPitch + kInset, kFTop, fPitch - 2 * kInset, kFHeight - 2 * kInset);

    const auto cell = [this](Key k, double col, double yTop, double widthCells = 1) {
        keys_[static_cast<std::size_t>(k)] =
            snap(kMargin + col + kInset, yTop + kInset, widthCells - 2 * kInset, 1 - 2 * kInset);
    };
    // K1..K6 / K7..K12, then L1 L2 / L3 L4 after a gap.
    for (int i = 0; i < 6; ++i) {
        cell(plus(Key::K1, i), i, kKTop);
        cell(plus(Key::K7, i), i, kKTop + 1);
    }
    const double lCol = 6 + kGroupGap;
    cell(Key::L1, lCol, kKTop);
    cell(Key::L2, lCol + 1, kKTop);
    cell(Key::L3, lCol, kKTop + 1);
    cell(Key::L4, lCol + 1, kKTop + 1);

    // System keyboard, left: the word keys and the cursor diamond.
    const double r0 = kSysTop;
    cell(Key::Esc, 0, r0);
    cell(Key::Par, 1, r0);
    cell(Key::Ack, 2, r0);
    cell(Key::Mode, 3, r0);
    cell(Key::Shift, 0, r0 + 1);
    cell(Key::Ins, 1, r0 + 1);
    cell(Key::Del, 2, r0 + 1);
    cell(Key::Help, 3, r0 + 1);
    cell(Key::Up, 1.5, r0 + 2);
    cell(Key::Left, 0.5, r0 + 3);
    cell(Key::Right, 2.5, r0 + 3);
    cell(Key::Down, 1.5, r0 + 4);

    // System keyboard, right: the numeric pad.
    const double n0 = 4 + kGroupGap;
    const Key pad[4][4] = {
        {Key::Percent, Key::Exclamation, Key::Equals, Key::Divide},
        {Key::D7, Key::D8, Key::D9, Key::Multiply},
        {Key::D4, Key::D5, Key::D6, Key::Minus},
        {Key::D1, Key::D2, Key::D3, Key::Plus},
    };
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            cell(pad[r][c], n0 + c, r0 + r);
    cell(Key::D0, n0, r0 + 4);
    cell(Key::Point, n0 + 1, r0 + 4);
    cell(Key::Enter, n0 + 2, r0 + 4, 2);
}

QRect K923Layout::snap(double xu, double yu, double wu, double hu) const {
    // Position and size are rounded apart, so that keys of one size stay
    // exactly one size (the gaps between them may differ by a pixel).
    const QPointF a = at(xu, yu);
    const int x0 = static_cast<int>(std::lround(a.x()));
    const int y0 = static_cast<int>(std::lround(a.y()));
    const int w = static_cast<int>(std::lround(wu * u_));
    const int h = static_cast<int>(std::lround(hu * u_));
    return QRect(x0, y0, std::max(1, w), std::max(1, h));
}

QRectF K923Layout::unitsRect(double xu, double yu, double wu, double hu) const {
    return QRectF(at(xu, yu), at(xu + wu, yu + hu));
}

QRectF K923Layout::nameplate() const {
    return unitsRect(kMargin, kNameTop, kContent, kNameHeight);
}

QRect K923Layout::lcd() const {
    return snap(kMargin, kLcdTop, kContent, kContent / LcdLayout::aspect());
}

std::vector<QRectF> K923Layout::groupFrames() const {
    const double pad = 0.08;
    const auto frame = [&](double x, double y, double w, double h) {
        return unitsRect(kMargin + x - pad, y - pad, w + 2 * pad, h + 2 * pad);
    };
    return {
        frame(0, kFTop, kContent, kFHeight), // mode keys
        frame(0, kKTop, 6, 2),               // K1..K12
        frame(6 + kGroupGap, kKTop, 2, 2),   // L1..L4
        frame(0, kSysTop, 4, 5),             // word keys and cursor keys
        frame(4 + kGroupGap, kSysTop, 4, 5), // numeric pad
    };
}

std::array<QPointF, 4> K923Layout::screws() const {
    const double d = 0.18;
    return {at(d, d), at(kWidthU - d, d), at(d, kHeightU - d), at(kWidthU - d, kHeightU - d)};
}

} // namespace k528::studio
