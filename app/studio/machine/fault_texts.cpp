#include "machine/fault_texts.h"

#include "machine/simulation.h"
#include "session/translated_texts.h"
#include "window_language.h"

#include <QCoreApplication>

#include <optional>
#include <string>
#include <vector>

namespace k528::studio {

namespace {

// core/machine/fault_texts.cpp's catalog, each text marked for the translators.
const TranslatedText kFaults[] = {
    {"encoder_channel_break", QT_TRANSLATE_NOOP("FaultTexts", "Encoder %1: channel %2 broken")},
    {"drive_not_ready", QT_TRANSLATE_NOOP("FaultTexts", "Feed drive %1 not ready")},
    {"limit_switch", QT_TRANSLATE_NOOP("FaultTexts", "Limit switch %1%2 hit")},
    {"emergency_stop", QT_TRANSLATE_NOOP("FaultTexts", "Emergency stop circuit open")},
    {"dac_limit", QT_TRANSLATE_NOOP("FaultTexts", "Interference on encoder %1 (DAC limit)")},
    {"plc_module_failure", QT_TRANSLATE_NOOP("FaultTexts", "PLC I/O module failure, place %1")},
    {"lost_link", QT_TRANSLATE_NOOP("FaultTexts", "PLC - positioner link lost")},
    {"spindle_drive", QT_TRANSLATE_NOOP("FaultTexts", "Drive not ready: %1")},
    {"spindle_overheat", QT_TRANSLATE_NOOP("FaultTexts", "Motor overheat: %1")},
    {"pump_overload", QT_TRANSLATE_NOOP("FaultTexts", "Motor overload: %1")},
    {"chuck_pressure", QT_TRANSLATE_NOOP("FaultTexts", "Chuck loses its clamping pressure")},
    {"turret_jam", QT_TRANSLATE_NOOP("FaultTexts", "Turret jammed")},
    {"gauge_fault", QT_TRANSLATE_NOOP("FaultTexts", "In-process gauge fault")},
    {"positioner_module.pulse_module_1", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: encoder module CP34.23, place 0, failed")},
    {"positioner_module.pulse_module_2", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: encoder module CP34.23, place 1, failed")},
    {"positioner_module.dac_module", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: DAC module CM32.03 failed")},
    {"positioner_module.comm_module", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: communication module CP52.05 failed")},
    {"positioner_module.panel_link", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: link to the K923 unstable")},
    {"positioner_module.memory", QT_TRANSLATE_NOOP("FaultTexts", "Positioner: RAM/ROM test fails")},
    {"k923.plc_link", QT_TRANSLATE_NOOP("FaultTexts", "K923: no link to the PLC")},
    {"k923.positioner_link", QT_TRANSLATE_NOOP("FaultTexts", "K923: no link to the positioner")},
    {"k923.ram", QT_TRANSLATE_NOOP("FaultTexts", "K923: RAM fault")},
    {"k923.resident", QT_TRANSLATE_NOOP("FaultTexts", "K923: resident software corrupt")},
    {"plc_stopped", QT_TRANSLATE_NOOP("FaultTexts", "PLC in debug stop")},
    {"equipment.spindle", QT_TRANSLATE_NOOP("FaultTexts", "spindle")},
    {"equipment.wheel", QT_TRANSLATE_NOOP("FaultTexts", "wheel spindle")},
    {"equipment.work", QT_TRANSLATE_NOOP("FaultTexts", "work spindle")},
    {"equipment.coolant", QT_TRANSLATE_NOOP("FaultTexts", "coolant pump")},
    {"equipment.lube", QT_TRANSLATE_NOOP("FaultTexts", "lubrication pump")},
    {"equipment.hydraulics", QT_TRANSLATE_NOOP("FaultTexts", "hydraulic pump")},
};

const TranslatedTexts kFaultTexts("FaultTexts", kFaults);

} // namespace

bool hasFaultText(std::string_view id) { return kFaultTexts.has(id); }

QString faultTitle(const machine::FaultText& t) {
    std::vector<std::string> args = t.args;
    // A description's own equipment (not in the table): its name.
    if (t.namesEquipment && !args.empty())
        if (const std::string id = machine::equipmentTextId(args[0]); kFaultTexts.has(id))
            args[0] = kFaultTexts.pattern(id).toStdString();
    if (const std::optional<QString> text = kFaultTexts.text(t.id, args))
        return *text;
    return coreText(machine::faultTextIn(t, true), machine::faultTextIn(t, false)); // an id without a translation
}

QString faultTitle(const machine::FaultSpec& f) { return faultTitle(machine::faultText(f)); }

} // namespace k528::studio
