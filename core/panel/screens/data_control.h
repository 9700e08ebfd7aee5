// УПРАВЛЕНИЕ ДАННЫМИ (2.6.8).
//
//   menu                     confirmation             PC
//   УПРАВЛЕНИЕ ДАННЫМИ  *    УПРАВЛЕНИЕ ДАННЫМИ  *    УПРАВЛЕНИЕ ДАННЫМИ  *
//   >ОЧИСТКА С-ПАРАМ         ОЧИСТКА С-ПАРАМ?         РАБОТА С ПЭВМ
//    ОЧИСТКА Р-ПАРАМ                                  ГОТОВ К ОБМЕНУ
//    РАБОТА С ПЭВМ           ENTER-ДА  ESC-НЕТ
//
// ▲▼ and ENTER. The two clearings ask for a confirmation (ENTER yes, ESC
// no) and go through the engine (clearCParameters / clearRParameters);
// РАБОТА С ПЭВМ makes the panel ready for the PC link (Panel::pcLinkReady)
// until ESC, MODE or another mode.
#pragma once

#include "panel/screen.h"

namespace k528::panel {

class DataControlScreens : public Screen {
public:
    enum class Page { Menu, Confirm, Pc };

    void enter(Context& ctx) override;
    void leave(Context& ctx) override;
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    void escape(Context& ctx) override { back(ctx); }
    void mode(Context& ctx) override { back(ctx); }

    Page page() const { return page_; }
    int marker() const { return marker_; }

private:
    void back(Context& ctx);

    Page page_ = Page::Menu;
    int marker_ = 0;
};

} // namespace k528::panel
