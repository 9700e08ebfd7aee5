// ПРЕДУСТАНОВКИ (2.6.5): the menu of the nine groups and the group screens.
//
//   menu                    group (1, 2, 4..9)         group 3 (no hint line)
//   УСТ ПРЕДУСТАНОВКИ   *   УСТ1 КООРД.И СМЕЩ.X*       УСТ3 ПОДНАЛАДКА   X*
//   >1-КООРД.И СМЕЩЕНИЯ     СУММА ПРАВОК               >R218=12
//    2-ИСХОДНОЕ                X=1205.124               R219=21
//    3-ПОДНАЛАДКА           >R224=-12.356
//
// Menu: ▲▼ (SHIFT: 3 at a time), a digit 1..9 or ENTER opens a group; the
// marker stays on the group chosen last. In a group: ▲▼ move the marker
// (the window of two — three in group 3 — lines follows), ► ◀ switch X/Z
// (groups 1, 7, 8) or ПЕРИФ./ТОРЦА (group 4), digits and + - * / . = type
// a value in the parameter's format, ENTER writes it (engine setR; «X=» of
// group 1 is «установка фактического значения», engine setCurrentValue),
// MODE goes back to the menu.
#pragma once

#include "panel/screen.h"

#include <optional>
#include <string>
#include <string_view>

namespace k528::panel {

// How an R-parameter is shown and typed on the preset screens (docs/panel.md).
enum class RFormat {
    Integer, // as it is: «12», «-1», «2»
    DiscX,   // display discretes of X with the axis' decimal point: «-12.356»
    DiscZ,
    FeedX, // discretes of X per minute as mm/min with 2 decimals: «100.00»
    FeedZ,
    Seconds, // milliseconds as seconds with 3 decimals: «1.000»
    HundredthsZ, // display discretes of Z as mm with 2 decimals: «1.00» (R167 ДОПУСК)
};

// Digits after the point for the format on this machine.
int rFormatDecimals(RFormat f, const engine::Positioner& c);
std::string formatR(std::int64_t value, RFormat f, const engine::Positioner& c);
// The value of a typed text (digits, point, + - * /) in the format; nullopt
// if malformed or with more decimals than the format has.
std::optional<std::int64_t> parseR(std::string_view typed, RFormat f, const engine::Positioner& c);

class PresetScreens : public Screen {
public:
    static constexpr int kGroups = 9;

    void enter(Context& ctx) override;
    void leave(Context& ctx) override;
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    bool editing() const override { return entry_.active(); }
    void cancelEdit() override { entry_.stop(); }
    void mode(Context& ctx) override;

    // 0 = the menu, else the group shown.
    int group() const { return group_; }
    int menuMarker() const { return menuMarker_; }

private:
    void openGroup(int g);
    void renderMenu(Canvas& c) const;
    void renderGroup(Canvas& c, const Context& ctx) const;
    void store(Context& ctx);

    int menuMarker_ = 0, menuTop_ = 0;
    int group_ = 0;
    int page_ = 0;
    int marker_ = 0, top_ = 0;
    Entry entry_;
};

} // namespace k528::panel
