#include "panel/screens/program_editor.h"

#include <algorithm>

namespace k528::panel {

namespace {
constexpr int kRows = 3; // lines 2..4
// The confirmation line (our text: the manual asks for a confirmation
// without printing its screen).
constexpr std::string_view kConfirmLine = "ENTER-ДА  ESC-НЕТ";
} // namespace

bool ProgramEditScreens::corrupt(const Context& ctx) const {
    // Message 31 «Разрушена управляющая программа» stands while the area is bad.
    return ctx.engine().alarmRegistry().active(31);
}

int ProgramEditScreens::shownNumber(const Context& ctx) const {
    if (lastOpened_)
        return *lastOpened_;
    const auto numbers = ctx.engine().programs().numbers();
    return numbers.empty() ? 0 : numbers.front();
}

void ProgramEditScreens::enter(Context&) {
    page_ = Page::Menu;
    entry_.stop();
}

void ProgramEditScreens::leave(Context& ctx) {
    if (page_ == Page::Editor)
        editor_.leave(ctx);
    entry_.stop();
    page_ = Page::Menu;
}

bool ProgramEditScreens::editing() const {
    return page_ == Page::Editor ? editor_.editing() : page_ == Page::Menu && entry_.active();
}

void ProgramEditScreens::cancelEdit() {
    if (page_ == Page::Editor)
        editor_.cancelEdit();
    entry_.stop();
}

void ProgramEditScreens::escape(Context&) {
    switch (page_) {
    case Page::Editor:
        editor_.escape();
        break;
    case Page::Corrupt:
    case Page::Catalog:
        page_ = Page::Menu;
        break;
    case Page::Confirm:
        page_ = confirmBack_;
        break;
    case Page::Menu:
        break;
    }
}

void ProgramEditScreens::mode(Context& ctx) {
    if (page_ == Page::Editor) {
        editor_.leave(ctx);
        page_ = Page::Catalog;
        const auto numbers = ctx.engine().programs().numbers();
        const auto it = std::find(numbers.begin(), numbers.end(), editor_.program());
        if (it != numbers.end())
            catalogMarker_ = static_cast<int>(it - numbers.begin());
        catalogTop_ =
            windowTop(catalogTop_, catalogMarker_, kRows, static_cast<int>(numbers.size()));
    } else if (page_ == Page::Catalog || page_ == Page::Corrupt) {
        page_ = Page::Menu;
    }
}

void ProgramEditScreens::open(int number, Context& ctx) {
    if (number < 1 || number > program::kMaxPrograms) {
        ctx.inputError();
        return;
    }
    if (corrupt(ctx)) {
        page_ = Page::Corrupt;
        return;
    }
    if (!ctx.engine().programs().contains(number)) {
        // «Для открытия УП по номеру (и новой)»: a new, empty program.
        program::ProgramStore* store = ctx.engine().editablePrograms();
        if (!store) {
            ctx.inputError();
            return;
        }
        program::Program p;
        p.number = number;
        store->insert(std::move(p));
        ctx.engine().programsEdited();
    }
    lastOpened_ = number;
    editor_.open(number, ctx);
    page_ = Page::Editor;
}

void ProgramEditScreens::ask(Confirm what, int number, Page back) {
    confirm_ = what;
    confirmNumber_ = number;
    confirmBack_ = back;
    page_ = Page::Confirm;
}

void ProgramEditScreens::render(Canvas& c, const Context& ctx) const {
    if (page_ == Page::Editor) {
        editor_.render(c, ctx);
        return;
    }
    c.put(0, 1, "РЕДАКТИРОВАНИЕ УП");
    switch (page_) {
    case Page::Menu: {
        const std::string number =
            entry_.active() ? entry_.text() : std::to_string(shownNumber(ctx));
        c.put(1, 1, std::string(menuMarker_ == 0 ? ">" : " ") + "ПРОГРАММА " + number);
        c.put(2, 1, std::string(menuMarker_ == 1 ? ">" : " ") + "КАТАЛОГ");
        c.put(3, 1, std::string(menuMarker_ == 2 ? ">" : " ") + "ОЧИСТИТЬ УП");
        if (entry_.active())
            c.blink(1, 12 + textWidth(number), 1);
        break;
    }
    case Page::Corrupt:
        c.put(1, 5, "УП ЗАПОРЧЕНА");
        break;
    case Page::Catalog: {
        const auto numbers = ctx.engine().programs().numbers();
        for (int row = 0; row < kRows; ++row) {
            const int i = catalogTop_ + row;
            if (i >= static_cast<int>(numbers.size()))
                break;
            c.put(1 + row, 1,
                  std::string(i == catalogMarker_ ? ">" : " ") + "L" +
                      std::to_string(numbers[static_cast<std::size_t>(i)]));
        }
        break;
    }
    case Page::Confirm:
        c.put(1, 1,
              confirm_ == Confirm::ClearAll ? std::string("ОЧИСТИТЬ УП?")
                                            : "УДАЛИТЬ L" + std::to_string(confirmNumber_) + "?");
        c.put(3, 1, kConfirmLine);
        break;
    case Page::Editor:
        break;
    }
}

void ProgramEditScreens::key(KeyPress k, Context& ctx) {
    engine::Positioner& e = ctx.engine();
    switch (page_) {
    case Page::Editor:
        editor_.key(k, ctx);
        return;
    case Page::Corrupt:
        if (k.key == Key::Enter)
            page_ = Page::Menu;
        return;
    case Page::Confirm:
        if (k.key == Key::Enter) {
            program::ProgramStore* store = e.editablePrograms();
            if (!store) {
                ctx.inputError();
            } else {
                if (confirm_ == Confirm::ClearAll) {
                    *store = program::ProgramStore{};
                    lastOpened_.reset();
                } else {
                    store->remove(confirmNumber_);
                }
                e.programsEdited();
            }
            page_ = confirmBack_;
            const int count = static_cast<int>(e.programs().size());
            catalogMarker_ = std::clamp(catalogMarker_, 0, std::max(count - 1, 0));
            catalogTop_ = windowTop(catalogTop_, catalogMarker_, kRows, count);
        }
        return;
    case Page::Catalog: {
        const auto numbers = e.programs().numbers();
        const int count = static_cast<int>(numbers.size());
        if (k.key == Key::Up || k.key == Key::Down || k.key == Key::Left || k.key == Key::Right) {
            const int dir = k.key == Key::Up || k.key == Key::Left ? -1 : 1;
            catalogMarker_ = moveMarker(catalogMarker_, dir * (k.shift ? 3 : 1), count);
            catalogTop_ = windowTop(catalogTop_, catalogMarker_, kRows, count);
        } else if (count > 0 && (k.key == Key::Enter || k.key == Key::Del)) {
            const int n =
                numbers[static_cast<std::size_t>(std::clamp(catalogMarker_, 0, count - 1))];
            if (k.key == Key::Enter)
                open(n, ctx);
            else
                ask(Confirm::Delete, n, Page::Catalog);
        }
        return;
    }
    case Page::Menu:
        break;
    }
    // The menu.
    if (k.key == Key::Up || k.key == Key::Down) {
        entry_.stop();
        menuMarker_ = moveMarker(menuMarker_, k.key == Key::Up ? -1 : 1, 3);
        return;
    }
    if (menuMarker_ == 0) {
        if (k.key == Key::Enter) {
            const int n = entry_.active() && !entry_.text().empty() ? std::stoi(entry_.text())
                                                                    : shownNumber(ctx);
            entry_.stop();
            open(n, ctx);
        } else if (k.key == Key::Del) {
            // «с заданным номером»: the number typed, else the one shown.
            const int n = entry_.active() && !entry_.text().empty() ? std::stoi(entry_.text())
                                                                    : shownNumber(ctx);
            entry_.stop();
            if (e.programs().contains(n))
                ask(Confirm::Delete, n, Page::Menu);
            else
                ctx.inputError();
        } else {
            entry_.begin(k.key, Entry::Kind::Digits, 2);
        }
        return;
    }
    if (k.key != Key::Enter)
        return;
    if (menuMarker_ == 1) {
        if (corrupt(ctx)) {
            page_ = Page::Corrupt;
            return;
        }
        // The marker is on the program chosen last.
        const auto numbers = e.programs().numbers();
        const auto it = std::find(numbers.begin(), numbers.end(), shownNumber(ctx));
        catalogMarker_ = it != numbers.end() ? static_cast<int>(it - numbers.begin()) : 0;
        catalogTop_ =
            windowTop(catalogTop_, catalogMarker_, kRows, static_cast<int>(numbers.size()));
        page_ = Page::Catalog;
    } else {
        ask(Confirm::ClearAll, 0, Page::Menu);
    }
}

} // namespace k528::panel
