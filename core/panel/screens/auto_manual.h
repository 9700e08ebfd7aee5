// АВТОМАТ (2.6.2) and РУЧНОЙ (2.6.3): screens 1 and 2 of both modes, and
// screen 3 of РУЧНОЙ, the R-parameter editor. MODE pages through them.
//
//   screen 1              screen 2              РУЧ screen 3
//   АВТ     1      100%*  АВТ     1      100%*  РУЧ     1      100%*
//   <message of # >       <message of # >        R98=-12345
//   *X  234.567 -110.000  *X  234.567 F= 10.00  >R99=5034
//    Z-1065.124    0.000   Z-1065.124 F=1000.0   R100=0
//
// ACK types the program number of АВТОМАТ (R252) in columns 8–9, ENTER
// selects it. On screen 3 ▲▼ (SHIFT: 3 at a time) move the marker, digits
// and + - * / . = type a value, ENTER writes it (engine setR), PAR asks for
// a parameter number. Layouts and decisions: docs/panel.md.
#pragma once

#include "panel/screen.h"

namespace k528::panel {

class AutoManualScreens : public Screen {
public:
    explicit AutoManualScreens(engine::Mode mode);

    void enter(Context& ctx) override;
    void leave(Context& ctx) override;
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    bool editing() const override { return typing_ != Typing::None; }
    void cancelEdit() override;
    void mode(Context& ctx) override;

    int page() const { return page_; }
    int rMarker() const { return rMarker_; }

private:
    enum class Typing { None, Program, RValue, RNumber };
    int pages() const { return mode_ == engine::Mode::Manual ? 3 : 2; }
    void renderStatus(Canvas& c, const Context& ctx) const;
    void renderAxes(Canvas& c, const Context& ctx) const;
    void renderRList(Canvas& c, const Context& ctx) const;
    void moveR(int step);

    engine::Mode mode_;
    int page_ = 0;
    Typing typing_ = Typing::None;
    Entry entry_;
    int rMarker_ = 0, rTop_ = 0;
};

// One axis line of АВТ/РУЧ: motion mark, letter, the current coordinate
// right-aligned in columns 3–11, then the remaining path (screen 1,
// right-aligned ending in column 20, at most 9 characters, else empty) or
// «F=» and the feed in mm/min (screen 2, columns 13–14 and 15–20).
std::string axisLine(const engine::AxisView& v, bool feed);

} // namespace k528::panel
