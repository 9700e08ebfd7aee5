#include "machine/fault_texts.h"

#include "machine/simulation.h"

#include <QCoreApplication>

namespace k528::studio {

namespace {

struct FaultTexts {
    Q_DECLARE_TR_FUNCTIONS(FaultTexts)
public:
    // The equipment names of the shipped machine descriptions.
    static QString equipment(const QString& name) {
        if (name == "spindle")
            return tr("spindle");
        if (name == "wheel")
            return tr("wheel spindle");
        if (name == "work")
            return tr("work spindle");
        if (name == "coolant")
            return tr("coolant pump");
        if (name == "lube")
            return tr("lubrication pump");
        if (name == "hydraulics")
            return tr("hydraulic pump");
        return name; // a description's own equipment: its name
    }

    // The text of a fault id, %1 %2 … its arguments; empty for an unknown id.
    static QString pattern(const std::string& id) {
        struct Entry {
            const char* id;
            QString text;
        };
        const Entry table[] = {
            {"encoder_channel_break", tr("Encoder %1: channel %2 broken")},
            {"drive_not_ready", tr("Feed drive %1 not ready")},
            {"limit_switch", tr("Limit switch %1%2 hit")},
            {"emergency_stop", tr("Emergency stop circuit open")},
            {"dac_limit", tr("Interference on encoder %1 (DAC limit)")},
            {"plc_module_failure", tr("PLC I/O module failure, place %1")},
            {"lost_link", tr("PLC - positioner link lost")},
            {"spindle_drive", tr("Drive not ready: %1")},
            {"spindle_overheat", tr("Motor overheat: %1")},
            {"pump_overload", tr("Motor overload: %1")},
            {"chuck_pressure", tr("Chuck loses its clamping pressure")},
            {"turret_jam", tr("Turret jammed")},
            {"gauge_fault", tr("In-process gauge fault")},
            {"positioner_module.pulse_module_1", tr("Positioner: encoder module CP34.23, place 0, failed")},
            {"positioner_module.pulse_module_2", tr("Positioner: encoder module CP34.23, place 1, failed")},
            {"positioner_module.dac_module", tr("Positioner: DAC module CM32.03 failed")},
            {"positioner_module.comm_module", tr("Positioner: communication module CP52.05 failed")},
            {"positioner_module.panel_link", tr("Positioner: link to the K923 unstable")},
            {"positioner_module.memory", tr("Positioner: RAM/ROM test fails")},
            {"k923.plc_link", tr("K923: no link to the PLC")},
            {"k923.positioner_link", tr("K923: no link to the positioner")},
            {"k923.ram", tr("K923: RAM fault")},
            {"k923.resident", tr("K923: resident software corrupt")},
            {"plc_stopped", tr("PLC in debug stop")},
        };
        for (const Entry& e : table)
            if (id == e.id)
                return e.text;
        return {};
    }
};

} // namespace

QString faultTitle(const machine::FaultSpec& f) {
    const machine::FaultText t = machine::faultText(f);
    QString text = FaultTexts::pattern(t.id);
    if (text.isEmpty())
        return QString::fromStdString(machine::describeFault(f)); // an id without a translation
    const bool equipment = f.kind == machine::Fault::SpindleDrive ||
                           f.kind == machine::Fault::SpindleOverheat ||
                           f.kind == machine::Fault::PumpOverload;
    for (const std::string& a : t.args) {
        const QString arg = QString::fromStdString(a);
        text = text.arg(equipment ? FaultTexts::equipment(arg) : arg);
    }
    return text;
}

} // namespace k528::studio
