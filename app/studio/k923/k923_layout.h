// Where everything of the K923 front plate is, for a widget of a given size:
// the plate, the nameplate, the LCD window, every key and the printed group
// frames. The panel is designed on a grid of key pitches u and scaled to fit
// (keeping its proportions, centred):
//
//   КОНСТАР                                    K923
//   ┌──────────────── LCD 4×20 ────────────────┐
//   └──────────────────────────────────────────┘
//   [F1 АВТ][F2 РУЧ][F3 ПБТ][F4 УСТ][F5 ПАР][F6 УП][F7 ДАН][F8]
//   [K1 ][K2 ][K3 ][K4 ][K5 ][K6 ]    [L1 ][L2 ]
//   [K7 ][K8 ][K9 ][K10][K11][K12]    [L3 ][L4 ]
//   [ESC ][PAR ][ACK ][MODE]    [% R][ ! ][ = ][ / ]
//   [SHIFT][INS][DEL ][HELP]    [ 7 ][ 8 ][ 9 ][ * ]
//         [ ▲ ]                 [ 4 ][ 5 ][ 6 ][ − ]
//   [ ◀ ]       [ ► ]           [ 1 ][ 2 ][ 3 ][ + ]
//         [ ▼ ]                 [ 0 ][ . ][ ENTER  ]
#pragma once

#include "panel/keys.h"

#include <QRect>
#include <QRectF>
#include <QSize>
#include <array>
#include <vector>

namespace k528::studio {

class K923Layout {
public:
    // The plate in key pitches.
    static constexpr double kWidthU = 9.1;
    static constexpr double kHeightU = 12.8;
    static constexpr double aspect() { return kWidthU / kHeightU; }

    K923Layout() = default;
    explicit K923Layout(QSize widgetSize);

    double unit() const { return u_; }
    QRectF plate() const { return plate_; }
    QRectF nameplate() const;
    QRect lcd() const;
    QRect key(panel::Key k) const { return keys_[static_cast<std::size_t>(k)]; }
    // The printed frames around the key groups.
    std::vector<QRectF> groupFrames() const;
    // The screws in the plate's corners (centres) and their radius.
    std::array<QPointF, 4> screws() const;
    double screwRadius() const { return 0.1 * u_; }

private:
    QPointF at(double xu, double yu) const {
        return {plate_.left() + xu * u_, plate_.top() + yu * u_};
    }
    QRect snap(double xu, double yu, double wu, double hu) const;
    QRectF unitsRect(double xu, double yu, double wu, double hu) const;

    double u_ = 0;
    QRectF plate_;
    std::array<QRect, panel::kKeyCount> keys_{};
};

} // namespace k528::studio
