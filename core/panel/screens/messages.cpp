#include "panel/screens/messages.h"

#include "catalog/messages.h"

namespace k528::panel {

namespace {

using engine::AlarmCategory;

// Positioner messages of the categories, in the order they came.
void positioner(const engine::Positioner& c, bool faults, std::vector<std::string>& out) {
    for (const engine::AlarmView& a : c.alarms()) {
        const bool isFault =
            a.category == AlarmCategory::Fault || a.category == AlarmCategory::Program;
        if (isFault != faults)
            continue;
        out.push_back(engine::alarmText(a, true));
    }
}

// PLC messages whose bit is set in `bits` (bit k-1 = message k).
void plc(const engine::Positioner& c, catalog::PlcGroup g, std::uint32_t bits,
         std::vector<std::string>& out) {
    const auto& texts = c.profile().plcTexts(g);
    for (int k = 1; k <= catalog::plcMessageCount(g); ++k) {
        if (!((bits >> (k - 1)) & 1u))
            continue;
        const auto it = texts.find(k);
        out.push_back(it != texts.end() && !it->second.empty() ? it->second
                                                               : catalog::plcMessageAddress(g, k));
    }
}

} // namespace

std::string_view serviceListTitle(ServiceList l) {
    switch (l) {
    case ServiceList::Messages:
        return "СООБЩЕНИЯ";
    case ServiceList::Faults:
        return "НЕИСПРАВНОСТИ";
    case ServiceList::System:
        return "СИСТЕМА";
    }
    return "";
}

std::vector<std::string> serviceEntries(const engine::Positioner& c, ServiceList l) {
    std::vector<std::string> out;
    const engine::PlcMessagesView p = c.plcMessages();
    switch (l) {
    case ServiceList::Messages:
        plc(c, catalog::PlcGroup::Work, p.work, out);
        break;
    case ServiceList::Faults:
        positioner(c, true, out);
        plc(c, catalog::PlcGroup::Alarm, p.alarms, out);
        break;
    case ServiceList::System:
        positioner(c, false, out);
        plc(c, catalog::PlcGroup::System, p.system, out);
        break;
    }
    return out;
}

char32_t serviceMark(const engine::Positioner& c) {
    const engine::AlarmRegistry& a = c.alarmRegistry();
    const engine::PlcMessagesView p = c.plcMessages();
    if (a.anyLatched(AlarmCategory::Fault) || a.anyLatched(AlarmCategory::Program) || p.alarms != 0)
        return U'!';
    if (a.anyLatched(AlarmCategory::System) || p.system != 0)
        return U'?';
    if (p.work != 0)
        return U'*';
    return 0;
}

} // namespace k528::panel
