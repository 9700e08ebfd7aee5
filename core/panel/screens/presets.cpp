#include "panel/screens/presets.h"

#include "catalog/rparams.h"

#include <array>
#include <vector>

namespace k528::panel {

namespace {

using engine::AxisId;

// A parameter line of a group: R number (kCurrent = the current coordinate
// of the page's axis, «установка фактического значения»), its format and
// the axis letter line 1 shows while the marker is on it (0: the page's).
constexpr int kCurrent = -1;
struct Item {
    int r;
    RFormat format;
    char letter = 0;
};
struct Page {
    std::string_view title; // after «УСТn »
    char letter;            // 'X' / 'Z' in column 19, 0 = none or from the item
    AxisId axis;            // of the current coordinate (group 1)
    std::vector<Item> items;
};
struct Group {
    std::string_view menuName; // the menu line
    bool hint;                 // line 2 explains the parameter under the marker
    std::vector<Page> pages;   // ► ◀ switch between two pages
};

// The groups as 2.6.5 prints them. OCR fixes: «ПРЕЛУСТАНОВКИ» ПРЕДУСТАНОВКИ,
// «КООРЛ» КООРД, «СМЕШ» СМЕЩ, «ИСХОЛНОЕ» ИСХОДНОЕ, «ПОЛНАЛАЛКА» ПОДНАЛАДКА,
// «ОСЦИЛЛЯПИЯ» ОСЦИЛЛЯЦИЯ, «ЛОП.СКОРОСТИ» ДОП.СКОРОСТИ; the Cyrillic «Х» of
// screen 3 is the letter X of the other screens.
// clang-format off
const std::array<Group, PresetScreens::kGroups>& groups() {
    using F = RFormat;
    static const std::array<Group, PresetScreens::kGroups> g = {{
        {"КООРД.И СМЕЩЕНИЯ", true,
         {{"КООРД.И СМЕЩ.", 'X', AxisId::X,
           {{kCurrent, F::DiscX}, {224, F::DiscX}, {226, F::DiscX}, {228, F::DiscX}, {230, F::DiscX}}},
          {"КООРД.И СМЕЩ.", 'Z', AxisId::Z,
           {{kCurrent, F::DiscZ}, {225, F::DiscZ}, {227, F::DiscZ}, {229, F::DiscZ}, {231, F::DiscZ}}}}},
        {"ИСХОДНОЕ", true, {{"ИСХОДНОЕ", 0, AxisId::X, {{220, F::DiscX, 'X'}, {221, F::DiscZ, 'Z'}}}}},
        // Printed «R218 = 12», «R219 = 21»: whole discretes, no point.
        {"ПОДНАЛАДКА", false, {{"ПОДНАЛАДКА", 0, AxisId::X, {{218, F::Integer, 'X'}, {219, F::Integer, 'Z'}}}}},
        {"ПРАВКА", true,
         {{"ПРАВКА ПЕРИФ.", 0, AxisId::X, {{210, F::DiscX}, {211, F::DiscX}, {212, F::FeedZ}, {213, F::FeedZ}}},
          {"ПРАВКА ТОРЦА", 0, AxisId::Z, {{214, F::DiscZ}, {215, F::DiscZ}, {216, F::FeedX}, {217, F::FeedX}}}}},
        {"ШЛИФ.КРУГ", true,
         {{"ШЛИФ.КРУГ", 0, AxisId::X, {{204, F::DiscX}, {205, F::DiscX}, {206, F::DiscX}, {207, F::DiscX}}}}},
        // R202 «NZ АЛМАЗА» is printed «100.00», like the speeds of the screens.
        {"АЛМАЗ", true, {{"АЛМАЗ", 0, AxisId::X, {{200, F::DiscX}, {201, F::DiscZ}, {202, F::FeedZ}}}}},
        {"ОСЦИЛЛЯЦИЯ", true,
         {{"ОСЦИЛЛЯЦИЯ", 'X', AxisId::X,
           {{184, F::DiscX}, {185, F::DiscX}, {186, F::FeedX}, {187, F::Seconds}, {188, F::Integer},
            {189, F::Integer}, {190, F::Integer}, {191, F::Integer}}},
          {"ОСЦИЛЛЯЦИЯ", 'Z', AxisId::Z,
           {{192, F::DiscZ}, {193, F::DiscZ}, {194, F::FeedZ}, {195, F::Seconds}, {196, F::Integer},
            {197, F::Integer}, {198, F::Integer}, {199, F::Integer}}}}},
        {"СКОРОСТИ", true,
         {{"ДОП.СКОРОСТИ", 'X', AxisId::X, {{174, F::FeedX}, {175, F::FeedX}, {176, F::FeedX}, {177, F::FeedX}}},
          {"ДОП.СКОРОСТИ", 'Z', AxisId::Z, {{179, F::FeedZ}, {180, F::FeedZ}, {181, F::FeedZ}, {182, F::FeedZ}}}}},
        {"ОСЕВАЯ", true,
         {{"ОСЕВ.ОРИЕНТАЦИЯ", 0, AxisId::Z,
           // R167 ДОПУСК is printed «R167 = 1.00»: two decimals.
           {{164, F::DiscZ}, {165, F::Integer}, {166, F::DiscZ}, {167, F::HundredthsZ}, {168, F::FeedZ},
            {169, F::FeedZ}, {170, F::DiscX}, {171, F::DiscZ}}}}},
    }};
    return g;
}
// clang-format on

const Group& groupDef(int g) {
    return groups()[static_cast<std::size_t>(g - 1)];
}

// The explanatory line of a parameter (2.6.5 «Поясняющий текст», the
// catalog's panel hint). «ЗАДЕРЖКА РЕВЕРСА, СЕК» is printed with 21
// characters: the blank after the comma goes so that it fits the line.
// «MX: координата X» (R220, R200, R184 …) shows the machine coordinate of
// the axis there, as the manual's example «MX: -123.456» does: «это значение
// координаты в системе станка с учетом программирования на радиус/диаметр».
std::string hintOf(const Item& it, const engine::Positioner& c) {
    if (it.r == kCurrent)
        return "ТЕКУЩАЯ КООРДИНАТА";
    std::string h(catalog::rParam(it.r).panelHint);
    for (const AxisId a : {AxisId::X, AxisId::Z}) {
        const std::string placeholder = a == AxisId::X ? ": координата X" : ": координата Z";
        if (const auto p = h.find(placeholder); p != std::string::npos) {
            const engine::AxisView v = c.axisView(a);
            h = h.substr(0, p) + ": " + formatCoordinate(v.machineDisc, v.scale);
            break;
        }
    }
    if (textWidth(h) > kLcdColumns)
        if (const auto p = h.find(", "); p != std::string::npos)
            h.erase(p + 1, 1);
    return h;
}

units::AxisScale scaleOf(const engine::Positioner& c, AxisId a) {
    return c.axisView(a).scale;
}

AxisId formatAxis(RFormat f) {
    return f == RFormat::DiscZ || f == RFormat::FeedZ || f == RFormat::HundredthsZ ? AxisId::Z
                                                                                     : AxisId::X;
}

constexpr int kMenuRows = 3;

} // namespace

// ---------------------------------------------------------------------------
// Formats

int rFormatDecimals(RFormat f, const engine::Positioner& c) {
    switch (f) {
    case RFormat::Integer:
        return 0;
    case RFormat::DiscX:
    case RFormat::DiscZ:
        return scaleOf(c, formatAxis(f)).decimals();
    case RFormat::FeedX:
    case RFormat::FeedZ:
    case RFormat::HundredthsZ:
        return 2;
    case RFormat::Seconds:
        return 3;
    }
    return 0;
}

std::string formatR(std::int64_t value, RFormat f, const engine::Positioner& c) {
    switch (f) {
    case RFormat::Integer:
        return std::to_string(value);
    case RFormat::DiscX:
    case RFormat::DiscZ:
        return formatCoordinate(value, scaleOf(c, formatAxis(f)));
    case RFormat::FeedX:
    case RFormat::FeedZ:
    case RFormat::HundredthsZ: // discretes as mm with 2 decimals, as a feed's mm/min
        return formatFeed(value, scaleOf(c, formatAxis(f)));
    case RFormat::Seconds:
        return formatSeconds(value);
    }
    return {};
}

std::optional<std::int64_t> parseR(std::string_view typed, RFormat f, const engine::Positioner& c) {
    const auto v = evaluateEntry(typed, rFormatDecimals(f, c));
    if (!v)
        return std::nullopt;
    if (f == RFormat::FeedX || f == RFormat::FeedZ || f == RFormat::HundredthsZ) {
        // Hundredths of mm (/min) -> discretes (per minute): 100, 1000 or 10000 per mm, exact.
        const std::int64_t perMm = scaleOf(c, formatAxis(f)).discretesPerMm();
        return *v * (perMm / 100);
    }
    return v;
}

// ---------------------------------------------------------------------------
// Screens

void PresetScreens::enter(Context&) {
    entry_.stop();
    group_ = 0; // «При входе в режим предустановок появляется меню выбора группы»
    menuTop_ = windowTop(menuTop_, menuMarker_, kMenuRows, kGroups);
}

void PresetScreens::leave(Context&) {
    entry_.stop();
}

void PresetScreens::mode(Context&) {
    entry_.stop();
    group_ = 0;
}

void PresetScreens::openGroup(int g) {
    entry_.stop();
    group_ = g;
    page_ = 0;
    marker_ = 0;
    top_ = 0;
    menuMarker_ = g - 1;
    menuTop_ = windowTop(menuTop_, menuMarker_, kMenuRows, kGroups);
}

void PresetScreens::renderMenu(Canvas& c) const {
    c.put(0, 1, "УСТ ПРЕДУСТАНОВКИ");
    for (int row = 0; row < kMenuRows; ++row) {
        const int i = menuTop_ + row;
        c.put(1 + row, 1,
              std::string(i == menuMarker_ ? ">" : " ") + std::to_string(i + 1) + "-" +
                  std::string(groups()[static_cast<std::size_t>(i)].menuName));
    }
}

void PresetScreens::renderGroup(Canvas& c, const Context& ctx) const {
    const engine::Positioner& e = ctx.engine();
    const Group& g = groupDef(group_);
    const Page& p = g.pages[static_cast<std::size_t>(page_)];
    const int count = static_cast<int>(p.items.size());
    const Item& marked = p.items[static_cast<std::size_t>(marker_)];
    c.put(0, 1, "УСТ" + std::to_string(group_) + " " + std::string(p.title));
    if (p.letter != 0)
        c.put(0, 19, std::string(1, p.letter));
    else if (marked.letter != 0)
        c.put(0, 19, std::string(1, marked.letter));
    const int first = g.hint ? 2 : 1;
    const int rows = 4 - first;
    if (g.hint)
        c.put(1, 1, hintOf(marked, e));
    for (int row = 0; row < rows; ++row) {
        const int i = top_ + row;
        if (i >= count)
            break;
        const Item& it = p.items[static_cast<std::size_t>(i)];
        const bool isMarked = i == marker_;
        std::string name = it.r == kCurrent ? std::string(p.axis == AxisId::X ? "X" : "Z")
                                            : "R" + std::to_string(it.r);
        std::string value;
        if (isMarked && entry_.active())
            value = entry_.text();
        else if (it.r == kCurrent)
            value = formatCoordinate(e.axisView(p.axis).currentDisc, e.axisView(p.axis).scale);
        else
            value = formatR(e.r(it.r), it.format, e);
        const std::string line = std::string(isMarked ? ">" : " ") + padLeft(name, 4) + "=" + value;
        c.put(first + row, 1, line);
        if (isMarked && entry_.active())
            c.blink(first + row, 1 + textWidth(line), 1);
    }
}

void PresetScreens::render(Canvas& c, const Context& ctx) const {
    if (group_ == 0)
        renderMenu(c);
    else
        renderGroup(c, ctx);
}

void PresetScreens::store(Context& ctx) {
    engine::Positioner& e = ctx.engine();
    const Page& p = groupDef(group_).pages[static_cast<std::size_t>(page_)];
    const Item& it = p.items[static_cast<std::size_t>(marker_)];
    const RFormat f =
        it.r == kCurrent ? (p.axis == AxisId::X ? RFormat::DiscX : RFormat::DiscZ) : it.format;
    const auto v = parseR(entry_.text(), f, e);
    entry_.stop();
    bool ok = v.has_value();
    if (ok)
        ok = it.r == kCurrent ? e.setCurrentValue(p.axis, *v).ok() : e.setR(it.r, *v).ok();
    if (!ok)
        ctx.inputError();
}

void PresetScreens::key(KeyPress k, Context& ctx) {
    if (group_ == 0) {
        const int d = digitOf(k.key);
        if (d >= 1 && d <= kGroups) {
            openGroup(d);
        } else if (k.key == Key::Up || k.key == Key::Down) {
            menuMarker_ =
                moveMarker(menuMarker_, (k.key == Key::Up ? -1 : 1) * (k.shift ? 3 : 1), kGroups);
            menuTop_ = windowTop(menuTop_, menuMarker_, kMenuRows, kGroups);
        } else if (k.key == Key::Enter) {
            openGroup(menuMarker_ + 1);
        }
        return;
    }
    const Group& g = groupDef(group_);
    const int count = static_cast<int>(g.pages[static_cast<std::size_t>(page_)].items.size());
    const int rows = g.hint ? 2 : 3;
    switch (k.key) {
    case Key::Up:
    case Key::Down:
        entry_.stop();
        marker_ = moveMarker(marker_, (k.key == Key::Up ? -1 : 1) * (k.shift ? 3 : 1), count);
        top_ = windowTop(top_, marker_, rows, count);
        return;
    case Key::Left:
    case Key::Right:
        if (g.pages.size() > 1) {
            entry_.stop();
            page_ = 1 - page_;
        }
        return;
    case Key::Enter:
        if (entry_.active())
            store(ctx);
        return;
    case Key::Equals:
        if (entry_.active() && !entry_.assignResult())
            ctx.inputError();
        return;
    case Key::Del:
        entry_.backspace();
        return;
    default:
        break;
    }
    const Page& p = g.pages[static_cast<std::size_t>(page_)];
    const Item& it = p.items[static_cast<std::size_t>(marker_)];
    const RFormat f =
        it.r == kCurrent ? (p.axis == AxisId::X ? RFormat::DiscX : RFormat::DiscZ) : it.format;
    entry_.begin(k.key, Entry::Kind::Calculator, 13, rFormatDecimals(f, ctx.engine()));
}

} // namespace k528::panel
