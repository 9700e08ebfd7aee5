// РЕДАКТИРОВАНИЕ УП (2.6.7): the menu, «УП ЗАПОРЧЕНА», the catalog, the
// confirmation of a deletion, and the frame editor (frame_editor.h).
//
//   menu                    corrupt store           catalog
//   РЕДАКТИРОВАНИЕ УП   *   РЕДАКТИРОВАНИЕ УП   *   РЕДАКТИРОВАНИЕ УП   *
//    ПРОГРАММА 7                УП ЗАПОРЧЕНА         L1
//   >КАТАЛОГ                                        >L21
//    ОЧИСТИТЬ УП                                     L34
//
// Menu: ▲▼ and ENTER; on ПРОГРАММА digits type the number (shown: the
// program opened last, after power-on the first of the catalog, 0 if it is
// empty), ENTER opens it (a new one is created), DEL deletes it. ОЧИСТИТЬ УП
// clears the program area after a confirmation. The catalog: ▲▼◀► (SHIFT: 3
// at a time), ENTER opens, DEL deletes (with confirmation). MODE: editor ->
// catalog -> menu; ESC out of the catalog, «УП ЗАПОРЧЕНА» and the confirmation.
#pragma once

#include "panel/screen.h"
#include "panel/screens/frame_editor.h"

#include <optional>
#include <vector>

namespace k528::panel {

class ProgramEditScreens : public Screen {
public:
    enum class Page { Menu, Corrupt, Catalog, Editor, Confirm };

    void enter(Context& ctx) override;
    void leave(Context& ctx) override;
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    bool editing() const override;
    void cancelEdit() override;
    void escape(Context& ctx) override;
    void mode(Context& ctx) override;
    bool titleLine() const override { return page_ != Page::Editor; }

    Page page() const { return page_; }
    const FrameEditor& editor() const { return editor_; }
    // The number on the ПРОГРАММА line.
    int shownNumber(const Context& ctx) const;

private:
    enum class Confirm { ClearAll, Delete };
    void open(int number, Context& ctx);
    void ask(Confirm what, int number, Page back);
    bool corrupt(const Context& ctx) const;

    Page page_ = Page::Menu;
    int menuMarker_ = 1; // КАТАЛОГ, as printed
    std::optional<int> lastOpened_;
    Entry entry_; // the number typed on ПРОГРАММА
    int catalogMarker_ = 0, catalogTop_ = 0;
    Confirm confirm_ = Confirm::ClearAll;
    int confirmNumber_ = 0;
    Page confirmBack_ = Page::Menu;
    FrameEditor editor_;
};

} // namespace k528::panel
