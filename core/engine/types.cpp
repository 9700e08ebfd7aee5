#include "engine/types.h"

namespace k528::engine {

std::string_view modeTagRu(Mode m) {
    switch (m) {
    case Mode::Auto:
        return "АВТ";
    case Mode::Manual:
        return "РУЧ";
    case Mode::Reference:
        return "ПБТ";
    case Mode::SetActual:
        return "УСТ";
    case Mode::MachineData:
        return "ПАР";
    case Mode::ProgramEdit:
        return "РЕД";
    case Mode::DataControl:
        return "УПР";
    }
    return "";
}

std::string_view modeNameRu(Mode m) {
    switch (m) {
    case Mode::Auto:
        return "АВТОМАТ";
    case Mode::Manual:
        return "РУЧНОЙ";
    case Mode::Reference:
        return "ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ";
    case Mode::SetActual:
        return "ПРЕДУСТАНОВКИ";
    case Mode::MachineData:
        return "РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ";
    case Mode::ProgramEdit:
        return "РЕДАКТИРОВАНИЕ УП";
    case Mode::DataControl:
        return "УПРАВЛЕНИЕ ДАННЫМИ";
    }
    return "";
}

std::string_view modeNameEn(Mode m) {
    switch (m) {
    case Mode::Auto:
        return "automatic";
    case Mode::Manual:
        return "manual";
    case Mode::Reference:
        return "reference point";
    case Mode::SetActual:
        return "presets";
    case Mode::MachineData:
        return "machine constants";
    case Mode::ProgramEdit:
        return "program editing";
    case Mode::DataControl:
        return "data control";
    }
    return "";
}

std::string_view programStateName(ProgramState s) {
    switch (s) {
    case ProgramState::Idle:
        return "idle";
    case ProgramState::Running:
        return "running";
    case ProgramState::Dwell:
        return "dwell";
    case ProgramState::WaitingM:
        return "waiting_m";
    case ProgramState::M0:
        return "m0";
    case ProgramState::Interrupted:
        return "interrupted";
    case ProgramState::Ended:
        return "ended";
    case ProgramState::Alarm:
        return "alarm";
    }
    return "";
}

} // namespace k528::engine
