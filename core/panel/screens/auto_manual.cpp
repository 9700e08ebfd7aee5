#include "panel/screens/auto_manual.h"

#include "engine/rparams.h"

#include <algorithm>

namespace k528::panel {

namespace {
constexpr int kRRows = 3; // screen 3: lines 2..4
constexpr int kRCount = engine::kRCount;

// "R99=" and the value (or the text being typed).
std::string rLine(int n, const std::string& value) {
    return "R" + std::to_string(n) + "=" + value;
}
} // namespace

std::string axisLine(const engine::AxisView& v, bool feed) {
    if (!v.present)
        return {};
    std::string s;
    s += v.moving ? "*" : " ";
    s += v.axis == engine::AxisId::X ? "X" : "Z";
    // The coordinate takes columns 3–11 (±9999.999); a longer value (0.0001 mm
    // discrete above 999 mm) pushes the second field to the right.
    s += padLeft(formatCoordinate(v.currentDisc, v.scale), 9);
    const int rest = 20 - textWidth(s);
    if (feed) {
        s += " F=" + padLeft(formatFeed(v.feedDiscPerMin, v.scale, rest - 3), rest - 3);
    } else {
        // The remaining path ends in column 20 and may take column 12
        // (-1065.124); a value wider than that is no path (a jog without a
        // limit runs towards a far point): the field stays empty.
        const std::string rem = formatCoordinate(v.remainingDisc, v.scale);
        s += padLeft(textWidth(rem) <= rest ? rem : std::string(), rest);
    }
    return s;
}

AutoManualScreens::AutoManualScreens(engine::Mode mode) : mode_(mode) {}

void AutoManualScreens::enter(Context&) {
    page_ = 0;
    cancelEdit();
}

void AutoManualScreens::leave(Context&) {
    cancelEdit();
}

void AutoManualScreens::cancelEdit() {
    typing_ = Typing::None;
    entry_.stop();
}

void AutoManualScreens::mode(Context&) {
    cancelEdit();
    page_ = (page_ + 1) % pages();
}

void AutoManualScreens::renderStatus(Canvas& c, const Context& ctx) const {
    c.put(0, 1, engine::modeTagRu(mode_));
    const engine::ProgramView p = ctx.engine().programView();
    if (typing_ == Typing::Program) {
        c.put(0, 8, entry_.text());
        c.blink(0, 8 + textWidth(entry_.text()), 1);
    } else {
        // The program under way (R250), else the one selected for АВТОМАТ (R252).
        const int number =
            engine::programActive(p.state) && p.mainProgram > 0 ? p.mainProgram : p.selectedProgram;
        if (number > 0)
            c.putRight(0, 9, std::to_string(number));
    }
    renderOverride(c, ctx);
}

void AutoManualScreens::renderAxes(Canvas& c, const Context& ctx) const {
    const engine::ProgramView p = ctx.engine().programView();
    c.put(1, 1, p.messageText);
    c.put(2, 1, axisLine(ctx.engine().axisView(engine::AxisId::X), page_ == 1));
    c.put(3, 1, axisLine(ctx.engine().axisView(engine::AxisId::Z), page_ == 1));
}

void AutoManualScreens::renderRList(Canvas& c, const Context& ctx) const {
    if (typing_ == Typing::RNumber) {
        c.put(1, 1, "НОМЕР R-ПАРАМЕТРА?");
        c.put(2, 1, ">" + entry_.text());
        c.blink(2, 2 + textWidth(entry_.text()), 1);
        return;
    }
    for (int row = 0; row < kRRows; ++row) {
        const int n = rTop_ + row;
        if (n >= kRCount)
            break;
        const bool marked = n == rMarker_;
        const bool typed = marked && typing_ == Typing::RValue;
        const std::string value = typed ? entry_.text() : std::to_string(ctx.engine().r(n));
        c.put(1 + row, 1, std::string(marked ? ">" : " ") + rLine(n, value));
        if (typed)
            c.blink(1 + row, 2 + textWidth(rLine(n, value)), 1);
    }
}

void AutoManualScreens::render(Canvas& c, const Context& ctx) const {
    renderStatus(c, ctx);
    if (page_ == 2)
        renderRList(c, ctx);
    else
        renderAxes(c, ctx);
}

void AutoManualScreens::moveR(int step) {
    rMarker_ = moveMarker(rMarker_, step, kRCount);
    rTop_ = windowTop(rTop_, rMarker_, kRRows, kRCount);
}

void AutoManualScreens::key(KeyPress k, Context& ctx) {
    engine::Positioner& e = ctx.engine();
    // ACK: the number of the program of АВТОМАТ (table 3).
    if (k.key == Key::Ack) {
        cancelEdit();
        typing_ = Typing::Program;
        entry_.start(Entry::Kind::Digits, 2);
        return;
    }
    if (typing_ == Typing::Program) {
        if (k.key == Key::Enter) {
            const std::string t = entry_.text();
            cancelEdit();
            if (t.empty() || !e.selectProgram(std::stoi(t)).ok())
                ctx.inputError();
        } else if (k.key == Key::Del) {
            entry_.backspace();
        } else {
            entry_.type(k.key);
        }
        return;
    }
    if (page_ != 2)
        return;

    // Screen 3: the R-parameters.
    if (typing_ == Typing::RNumber) {
        std::string t;
        const Entry::Answer a = entry_.answer(k.key, t);
        if (a != Entry::Answer::Typing)
            cancelEdit();
        if (a == Entry::Answer::Given) {
            const int n = t.empty() ? -1 : std::stoi(t);
            if (n < 0 || n >= kRCount)
                ctx.inputError();
            else
                moveR(n - rMarker_);
        }
        return;
    }
    switch (k.key) {
    case Key::Up:
    case Key::Down:
        cancelEdit();
        moveR((k.key == Key::Up ? -1 : 1) * (k.shift ? 3 : 1));
        return;
    case Key::Par:
        cancelEdit();
        typing_ = Typing::RNumber;
        entry_.start(Entry::Kind::Digits, 3);
        return;
    case Key::Del:
        if (typing_ == Typing::RValue)
            entry_.backspace();
        return;
    case Key::Equals:
        if (typing_ == Typing::RValue) {
            if (!entry_.assignResult())
                ctx.inputError();
        }
        return;
    case Key::Enter:
        if (typing_ == Typing::RValue) {
            const auto v = evaluateEntry(entry_.text(), 0);
            cancelEdit();
            if (!v || !e.setR(rMarker_, *v).ok())
                ctx.inputError();
        }
        return;
    default:
        break;
    }
    if (entry_.begin(k.key, Entry::Kind::Calculator, 12))
        typing_ = Typing::RValue;
}

} // namespace k528::panel
