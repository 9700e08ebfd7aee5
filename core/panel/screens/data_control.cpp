#include "panel/screens/data_control.h"

#include <array>
#include <string_view>

namespace k528::panel {

namespace {
// As printed; «ЛАННЫМИ» is an OCR slip for ДАННЫМИ. «С-ПАРАМ» and «Р-ПАРАМ»
// are printed with Cyrillic С and Р (and an en dash, which the LCD shows as '-').
constexpr std::string_view kTitle = "УПРАВЛЕНИЕ ДАННЫМИ";
constexpr std::array<std::string_view, 3> kItems = {"ОЧИСТКА С-ПАРАМ", "ОЧИСТКА Р-ПАРАМ",
                                                    "РАБОТА С ПЭВМ"};
} // namespace

void DataControlScreens::enter(Context& ctx) {
    page_ = Page::Menu;
    ctx.setPcLinkReady(false);
}

void DataControlScreens::leave(Context& ctx) {
    page_ = Page::Menu;
    ctx.setPcLinkReady(false);
}

void DataControlScreens::back(Context& ctx) {
    page_ = Page::Menu;
    ctx.setPcLinkReady(false);
}

void DataControlScreens::render(Canvas& c, const Context&) const {
    c.put(0, 1, kTitle);
    switch (page_) {
    case Page::Menu:
        for (int i = 0; i < 3; ++i)
            c.put(1 + i, 1,
                  std::string(i == marker_ ? ">" : " ") +
                      std::string(kItems[static_cast<std::size_t>(i)]));
        break;
    case Page::Confirm:
        c.put(1, 1, std::string(kItems[static_cast<std::size_t>(marker_)]) + "?");
        c.put(3, 1, "ENTER-ДА  ESC-НЕТ");
        break;
    case Page::Pc:
        c.put(1, 1, kItems[2]);
        c.put(2, 1, "ГОТОВ К ОБМЕНУ");
        break;
    }
}

void DataControlScreens::key(KeyPress k, Context& ctx) {
    switch (page_) {
    case Page::Menu:
        if (k.key == Key::Up || k.key == Key::Down) {
            marker_ = moveMarker(marker_, k.key == Key::Up ? -1 : 1, 3);
        } else if (k.key == Key::Enter) {
            if (marker_ == 2) {
                page_ = Page::Pc;
                ctx.setPcLinkReady(true);
            } else {
                page_ = Page::Confirm;
            }
        }
        return;
    case Page::Confirm:
        if (k.key == Key::Enter) {
            const engine::OpResult r =
                marker_ == 0 ? ctx.engine().clearCParameters() : ctx.engine().clearRParameters();
            page_ = Page::Menu;
            if (!r.ok())
                ctx.inputError();
        }
        return;
    case Page::Pc:
        return;
    }
}

} // namespace k528::panel
