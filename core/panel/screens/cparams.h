// РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (2.6.6).
//
//   axis parameters           common parameters        PAR
//   ПАРАМЕТРЫ СТАНКА    *     ПАРАМЕТРЫ СТАНКА    *    ПАРАМЕТРЫ СТАНКА    *
//   F ОБЫЧНАЯ                 ESC=сброс в исх.сост     НОМЕР ПАРАМЕТРА?
//   N040>X=150000             №123 1                   >12
//   N092 Z=200000
//
// ▼ ▲ the next / previous parameter (axis parameters 1..52 as X/Z pairs,
// then the common ones 105..152; no wrap), ◀ the other axis of the pair,
// ▶ to the common parameters (◀ back to the axis parameter left), PAR a parameter by
// number, digits and + - * / = type a value, ENTER writes it (engine setC;
// a refusal is «ОШИБКА ВВОДА»). Values are integers in the units of table Е,
// as appendix Ж enters them. View only after a wrong password: values
// cannot be typed. The next entry shows the parameter shown last.
#pragma once

#include "catalog/cparams.h"
#include "panel/screen.h"

namespace k528::panel {

class CParamScreen : public Screen {
public:
    void enter(Context& ctx) override;
    void leave(Context&) override { cancelEdit(); }
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    bool editing() const override { return entry_.active(); }
    void cancelEdit() override;

    // The parameter under the marker (1..152).
    int current() const { return current_; }

private:
    bool common() const { return current_ > 2 * catalog::kAxisBlock; }
    void step(int dir);

    int current_ = 1;
    int lastAxis_ = 1;    // ◀ from the common parameters goes back here
    bool prompt_ = false; // PAR: the number is typed
    Entry entry_;
};

} // namespace k528::panel
