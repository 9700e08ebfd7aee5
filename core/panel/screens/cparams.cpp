#include "panel/screens/cparams.h"

#include "catalog/cparams.h"

#include <algorithm>
#include <cstdio>

namespace k528::panel {

namespace {
constexpr int kBlock = catalog::kAxisBlock;  // 52
constexpr int kFirstCommon = 2 * kBlock + 1; // 105
constexpr int kLast = catalog::kCParamCount; // 152

std::string number3(int n) {
    char b[8];
    std::snprintf(b, sizeof b, "%03d", n);
    return b;
}
} // namespace

void CParamScreen::enter(Context&) {
    cancelEdit();
}

void CParamScreen::cancelEdit() {
    entry_.stop();
    prompt_ = false;
}

void CParamScreen::render(Canvas& c, const Context& ctx) const {
    c.put(0, 1, "ПАРАМЕТРЫ СТАНКА");
    if (prompt_) {
        c.put(1, 1, "НОМЕР ПАРАМЕТРА?");
        c.put(2, 1, ">" + entry_.text());
        c.blink(2, 2 + textWidth(entry_.text()), 1);
        return;
    }
    const auto values = ctx.engine().c();
    const auto value = [&](int n) {
        return n == current_ && entry_.active()
                   ? entry_.text()
                   : std::to_string(values[static_cast<std::size_t>(n)]);
    };
    c.put(1, 1, catalog::cParam(current_).name);
    if (common()) {
        // «№kkk cccc.ccc»
        const std::string line = "№" + number3(current_) + " " + value(current_);
        c.put(2, 1, line);
        if (entry_.active())
            c.blink(2, 1 + textWidth(line), 1);
        return;
    }
    const int x = current_ > kBlock ? current_ - kBlock : current_;
    for (int i = 0; i < 2; ++i) {
        const int n = x + i * kBlock;
        const std::string line =
            "N" + number3(n) + (n == current_ ? ">" : " ") + (i == 0 ? "X=" : "Z=") + value(n);
        c.put(2 + i, 1, line);
        if (n == current_ && entry_.active())
            c.blink(2 + i, 1 + textWidth(line), 1);
    }
}

void CParamScreen::step(int dir) {
    // Order: the pairs 1..52 (on the axis of the marker), then 105..152.
    if (common()) {
        if (dir < 0 && current_ == kFirstCommon)
            current_ = kBlock; // back to the last pair, on X
        else
            current_ = std::clamp(current_ + dir, kFirstCommon, kLast);
        return;
    }
    const bool z = current_ > kBlock;
    const int x = z ? current_ - kBlock : current_;
    if (dir > 0 && x == kBlock) {
        current_ = kFirstCommon;
        return;
    }
    const int nx = std::clamp(x + dir, 1, kBlock);
    current_ = z ? nx + kBlock : nx;
}

void CParamScreen::key(KeyPress k, Context& ctx) {
    if (prompt_) {
        std::string t;
        const Entry::Answer a = entry_.answer(k.key, t);
        if (a != Entry::Answer::Typing)
            cancelEdit();
        if (a == Entry::Answer::Given) {
            const int n = t.empty() ? 0 : std::stoi(t);
            if (n >= 1 && n <= kLast)
                current_ = n;
            else
                ctx.inputError();
        }
        return;
    }
    switch (k.key) {
    case Key::Up:
    case Key::Down:
        cancelEdit();
        for (int i = 0; i < (k.shift ? 3 : 1); ++i)
            step(k.key == Key::Up ? -1 : 1);
        return;
    case Key::Left:
        cancelEdit();
        if (common())
            current_ = lastAxis_;
        else
            current_ = current_ > kBlock ? current_ - kBlock : current_ + kBlock;
        return;
    case Key::Right:
        cancelEdit();
        if (!common()) {
            lastAxis_ = current_;
            current_ = kFirstCommon;
        }
        return;
    case Key::Par:
        cancelEdit();
        prompt_ = true;
        entry_.start(Entry::Kind::Digits, 3);
        return;
    case Key::Enter:
        if (entry_.active()) {
            const auto v = evaluateEntry(entry_.text(), 0);
            entry_.stop();
            if (!v || !ctx.engine().setC(current_, *v).ok())
                ctx.inputError();
        }
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
    if (ctx.access() != Access::Full)
        return; // view only
    entry_.begin(k.key, Entry::Kind::Calculator, 12, 0);
}

} // namespace k528::panel
