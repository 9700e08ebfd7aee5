#include "engine/alarms.h"

#include "catalog/messages.h"
#include "engine/views.h"

#include <algorithm>

namespace k528::engine {

std::string alarmText(const AlarmView& a, bool russian) {
    if (const catalog::PositionerMessage* m = russian ? catalog::findPositionerMessage(a.number) : nullptr)
        return m->panelText();
    return catalog::numberedMessage(a.number, russian ? a.textRu : a.textEn, russian);
}

std::string_view alarmCategoryName(AlarmCategory c) {
    switch (c) {
    case AlarmCategory::Fault:
        return "fault";
    case AlarmCategory::Program:
        return "program";
    case AlarmCategory::System:
        return "system";
    }
    return "";
}

int alarmAxis(int n) {
    switch (n) {
    case 1:
    case 4:
    case 5:
    case 6:
    case 7:
    case 8:
    case 10:
    case 11:
    case 12:
    case 13:
    case 16:
    case 33:
    case 34:
    case 35:
    case 36:
    case 56:
        return 0;
    case 17:
    case 20:
    case 21:
    case 22:
    case 23:
    case 24:
    case 26:
    case 27:
    case 28:
    case 29:
    case 32:
    case 49:
    case 50:
    case 51:
    case 52:
    case 57:
        return 1;
    default:
        return -1;
    }
}

bool AlarmRegistry::raise(int n, bool activeCondition, int program, int line) {
    if (n < 1 || n > kMessageCount)
        return false;
    AlarmEntry& e = e_[static_cast<std::size_t>(n)];
    const bool fresh = !e.latched;
    if (fresh) {
        e.latched = true;
        e.order = ++order_;
        e.program = program;
        e.line = line;
        latchedMask_ |= bit(n);
    }
    if (activeCondition) {
        e.active = true;
        activeMask_ |= bit(n);
    }
    return fresh;
}

void AlarmRegistry::acknowledge(AlarmCategory category) {
    for (int n = 1; n <= kMessageCount; ++n) {
        AlarmEntry& e = e_[static_cast<std::size_t>(n)];
        if (e.latched && !e.active && alarmCategory(n) == category) {
            e.latched = false;
            latchedMask_ &= ~bit(n);
        }
    }
}

void AlarmRegistry::acknowledgeAll() {
    acknowledge(AlarmCategory::Fault);
    acknowledge(AlarmCategory::Program);
    acknowledge(AlarmCategory::System);
}

std::vector<int> AlarmRegistry::latchedList() const {
    std::vector<int> v;
    for (int n = 1; n <= kMessageCount; ++n)
        if (latched(n))
            v.push_back(n);
    std::sort(v.begin(), v.end(), [&](int a, int b) { return entry(a).order < entry(b).order; });
    return v;
}

void PlcMessages::update(const InterfaceWords& w) {
    alarmNow_ = static_cast<std::uint32_t>(w.word(z::AlarmMessagesFirst)) |
                (static_cast<std::uint32_t>(w.word(z::AlarmMessagesFirst + 1)) << 16);
    alarmLatched_ |= alarmNow_;
    work_ = static_cast<std::uint32_t>(w.word(z::WorkMessagesFirst)) |
            (static_cast<std::uint32_t>(w.word(z::WorkMessagesFirst + 1)) << 16);
    systemNow_ = w.word(z::SystemMessagesWord);
    systemLatched_ = static_cast<std::uint16_t>(systemLatched_ | systemNow_);
}

} // namespace k528::engine
