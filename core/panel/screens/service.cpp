#include "panel/screens/service.h"

#include "panel/screens/messages.h"

#include <array>
#include <cmath>

namespace k528::panel {

namespace {
// «СООБШЕНИЯ» is an OCR slip for СООБЩЕНИЯ; the dash is printed «–».
constexpr std::array<std::string_view, 4> kMenu = {"1 - СООБЩЕНИЯ", "2 - НЕИСПРАВНОСТИ",
                                                   "3 - СИСТЕМА", "4 - ДИАГНОСТИКА"};

int firstPresentAxis(const engine::Positioner& e) {
    return !e.axisView(engine::AxisId::X).present && e.axisView(engine::AxisId::Z).present ? 1 : 0;
}
} // namespace

void ServiceScreens::open() {
    page_ = Page::Menu;
}

int ServiceScreens::count(const Context& ctx) const {
    return static_cast<int>(serviceEntries(ctx.engine(), static_cast<ServiceList>(list_)).size());
}

int ServiceScreens::entry(const Context& ctx) const {
    return std::min(index_, count(ctx));
}

void ServiceScreens::choose(int item, const Context& ctx) {
    marker_ = item - 1;
    if (item == 4) {
        page_ = Page::Diagnostics;
        axis_ = firstPresentAxis(ctx.engine());
        return;
    }
    page_ = Page::List;
    list_ = item;
    index_ = 0;
}

void ServiceScreens::render(Canvas& c, const Context& ctx) const {
    const engine::Positioner& e = ctx.engine();
    switch (page_) {
    case Page::Menu:
        for (int i = 0; i < 4; ++i)
            c.put(i, 1,
                  std::string(i == marker_ ? ">" : " ") +
                      std::string(kMenu[static_cast<std::size_t>(i)]));
        return;
    case Page::List: {
        const auto entries = serviceEntries(e, static_cast<ServiceList>(list_));
        const int n = static_cast<int>(entries.size());
        const int i = std::min(index_, n);
        c.put(0, 1, serviceListTitle(static_cast<ServiceList>(list_)));
        if (i == n)
            return; // the empty screen
        c.putRight(0, 20, std::to_string(i + 1) + "/" + std::to_string(n));
        const auto lines = wrapText(entries[static_cast<std::size_t>(i)], kLcdColumns);
        for (std::size_t k = 0; k < lines.size() && k < 3; ++k)
            c.put(1 + static_cast<int>(k), 1, lines[k]);
        return;
    }
    case Page::Diagnostics: {
        const engine::AxisView v = e.axisView(engine::axisAt(axis_));
        const std::string a = axis_ == 0 ? "X" : "Z";
        // ABS and ERR in internal units, with the point of the axis' discrete (2.6: «12.346»,
        // «-0.024»).
        c.put(0, 1, "ABS_" + a + " " + formatCoordinate(std::llround(v.absInternal), v.scale));
        c.put(1, 1, "ERR_" + a + " " + formatCoordinate(std::llround(v.errorInternal), v.scale));
        c.put(2, 1, "DAC_" + a + " " + std::to_string(v.dac));
        c.put(3, 1, "PLS_" + a + " " + std::to_string(v.pulsesPerTick));
        return;
    }
    }
}

void ServiceScreens::key(KeyPress k, Context& ctx) {
    switch (page_) {
    case Page::Menu: {
        const int d = digitOf(k.key);
        if (d >= 1 && d <= 4)
            choose(d, ctx);
        else if (k.key == Key::Up || k.key == Key::Down)
            marker_ = moveMarker(marker_, k.key == Key::Up ? -1 : 1, 4);
        else if (k.key == Key::Enter)
            choose(marker_ + 1, ctx);
        return;
    }
    case Page::List: {
        const int slots = count(ctx) + 1; // the entries and the empty screen
        index_ = std::min(index_, slots - 1);
        if (k.key == Key::Down)
            index_ = (index_ + 1) % slots;
        else if (k.key == Key::Up)
            index_ = (index_ + slots - 1) % slots;
        return;
    }
    case Page::Diagnostics:
        if (k.key == Key::Left || k.key == Key::Right) {
            const int other = 1 - axis_;
            if (ctx.engine().axisView(engine::axisAt(other)).present)
                axis_ = other;
        }
        return;
    }
}

} // namespace k528::panel
