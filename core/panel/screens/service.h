// The service screens of HELP (2.6): common to all modes, they do not
// change the mode. HELP enters and leaves them; F1..F7 leave them for a mode.
//
//   menu                 a list entry             the empty screen
//   >1 - СООБЩЕНИЯ       НЕИСПРАВНОСТИ     1/2    НЕИСПРАВНОСТИ
//    2 - НЕИСПРАВНОСТИ   8.Контроль полож/
//    3 - СИСТЕМА         зажима оси X
//    4 - ДИАГНОСТИКА
//
//   ДИАГНОСТИКА: ABS_X 12.346 / ERR_X -0.024 / DAC_X 1026 / PLS_X 0
//
// Menu: a digit 1..4, or ▲▼ and ENTER. A list shows one message per screen
// (lines 2–4, wrapped at blanks) with ▲▼; after the last one and before
// the first comes the empty screen. ◀ ► switch the axis of ДИАГНОСТИКА.
// MODE goes back to the menu. The lists come from the engine each time
// (screens/messages.h).
#pragma once

#include "panel/screen.h"

namespace k528::panel {

class ServiceScreens : public Screen {
public:
    enum class Page { Menu, List, Diagnostics };

    // HELP pressed: the menu.
    void open();
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    void mode(Context&) override { page_ = Page::Menu; }
    bool titleLine() const override { return false; }

    Page page() const { return page_; }
    // 1..3 on a list.
    int list() const { return list_; }
    // The entry shown; == the number of entries on the empty screen.
    int entry(const Context& ctx) const;

private:
    void choose(int item, const Context& ctx);
    int count(const Context& ctx) const;

    Page page_ = Page::Menu;
    int marker_ = 0;
    int list_ = 1;
    int index_ = 0;
    int axis_ = 0;
};

} // namespace k528::panel
