#include "machine/fault_catalog.h"

namespace k528::machine {

namespace {

constexpr util::CatalogText kFaultTexts[] = {
    {"encoder_channel_break", "ДОС %1: обрыв канала %2", "Encoder %1: channel %2 broken"},
    {"drive_not_ready", "Нет готовности привода подачи %1", "Feed drive %1 not ready"},
    {"limit_switch", "Наезд на конечник %1%2", "Limit switch %1%2 hit"},
    {"emergency_stop", "Обрыв цепи аварийного останова", "Emergency stop circuit open"},
    {"dac_limit", "Помеха в линиях ДОС %1 (предел ЦАП)", "Interference on encoder %1 (DAC limit)"},
    {"plc_module_failure", "Отказ модуля ввода-вывода ПЛК, место %1", "PLC I/O module failure, place %1"},
    {"lost_link", "Нет связи ПЛК и БП", "PLC - positioner link lost"},
    {"spindle_drive", "Нет готовности привода: %1", "Drive not ready: %1"},
    {"spindle_overheat", "Перегрев двигателя: %1", "Motor overheat: %1"},
    {"pump_overload", "Перегрузка двигателя: %1", "Motor overload: %1"},
    {"chuck_pressure", "Патрон теряет давление зажима", "Chuck loses its clamping pressure"},
    {"turret_jam", "Резцедержатель заклинило", "Turret jammed"},
    {"gauge_fault", "Неисправность прибора активного контроля", "In-process gauge fault"},
    {"positioner_module.pulse_module_1", "БП: отказ модуля ДОС CP34.23, место 0", "Positioner: encoder module CP34.23, place 0, failed"},
    {"positioner_module.pulse_module_2", "БП: отказ модуля ДОС CP34.23, место 1", "Positioner: encoder module CP34.23, place 1, failed"},
    {"positioner_module.dac_module", "БП: отказ модуля ЦАП CM32.03", "Positioner: DAC module CM32.03 failed"},
    {"positioner_module.comm_module", "БП: отказ модуля связи CP52.05", "Positioner: communication module CP52.05 failed"},
    {"positioner_module.panel_link", "БП: неустойчивая связь с K923", "Positioner: link to the K923 unstable"},
    {"positioner_module.memory", "БП: ошибка теста ОЗУ/ПЗУ", "Positioner: RAM/ROM test fails"},
    {"k923.plc_link", "K923: нет связи с ПЛК", "K923: no link to the PLC"},
    {"k923.positioner_link", "K923: нет связи с БП", "K923: no link to the positioner"},
    {"k923.ram", "K923: неисправно ОЗУ", "K923: RAM fault"},
    {"k923.resident", "K923: нарушен резидент", "K923: resident software corrupt"},
    {"plc_stopped", "ПЛК в режиме «ОТЛАДКА СТОП»", "PLC in debug stop"},
    // The equipment of the shipped machine descriptions, by its name there.
    {"equipment.spindle", "шпиндель", "spindle"},
    {"equipment.wheel", "шпиндель круга", "wheel spindle"},
    {"equipment.work", "шпиндель изделия", "work spindle"},
    {"equipment.coolant", "насос СОЖ", "coolant pump"},
    {"equipment.lube", "насос смазки", "lubrication pump"},
    {"equipment.hydraulics", "гидронасос", "hydraulic pump"},
};

} // namespace

util::TextCatalog faultTexts() { return util::TextCatalog(kFaultTexts); }

std::string equipmentTextId(const std::string& name) { return "equipment." + name; }

std::string faultTextIn(const FaultText& t, bool russian) {
    const util::TextCatalog catalog = faultTexts();
    std::vector<std::string> args = t.args;
    if (t.namesEquipment && !args.empty())
        if (const util::CatalogText* e = catalog.find(equipmentTextId(args[0])))
            args[0] = std::string(e->in(russian));
    return catalog.render(t.id, args, russian);
}

} // namespace k528::machine
