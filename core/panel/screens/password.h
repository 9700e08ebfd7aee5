// The password of 2.6 before РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5),
// РЕДАКТИРОВАНИЕ УП (F6) and УПРАВЛЕНИЕ ДАННЫМИ (F7):
//
//   ПАРОЛЬ?           *      after a wrong password for F6 / F7:
//   >****                    ПАРОЛЬ?           *
//                            >
//                            ДОСТУП ЗАКРЫТ
//
// Four digits (shown as «*»), ENTER. The Panel checks it («1111»): right —
// the mode opens; wrong — F5 opens for viewing only, F6/F7 stay closed
// («ДОСТУП ЗАКРЫТ», the digits can be typed again). DEL takes back a digit.
#pragma once

#include "panel/screen.h"

namespace k528::panel {

class PasswordScreen : public Screen {
public:
    // Digits the line takes: the password's four («ввести четырехзначный
    // пароль»); a fifth digit is not taken (DEL takes one back).
    static constexpr int kMaxTyped = 4;
    // Asks for the password of mode `target`; `imposed`: the PLC has already
    // put the engine in that mode (ESC cannot go back).
    void start(engine::Mode target, bool imposed);
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress k, Context& ctx) override;
    bool editing() const override { return !entry_.text().empty(); }
    void cancelEdit() override { entry_.start(Entry::Kind::Digits, kMaxTyped); }

    engine::Mode target() const { return target_; }
    bool imposed() const { return imposed_; }
    const std::string& typed() const { return entry_.text(); }
    // A wrong password for F6 / F7.
    void setClosed();
    bool closed() const { return closed_; }

private:
    engine::Mode target_ = engine::Mode::MachineData;
    bool imposed_ = false;
    bool closed_ = false;
    Entry entry_;
};

} // namespace k528::panel
