#include "program/gfunctions.h"

namespace k528::program {

std::string gName(int g) {
    std::string s = "G";
    if (g >= 0 && g < 10)
        s += '0';
    s += std::to_string(g);
    return s;
}

std::string_view gMeaningRu(GFunction f) {
    switch (f) {
    case GFunction::Unknown:
        return "неизвестная функция";
    case GFunction::Rapid:
        return "ускоренное перемещение";
    case GFunction::Feed:
        return "перемещение с заданной подачей";
    case GFunction::Dwell:
        return "выдержка времени";
    case GFunction::Handwheel:
        return "перемещение маховиком по оси";
    case GFunction::StopOnSignal:
        return "прерывание перемещения по сигналу";
    case GFunction::OmitHandwheelOffset:
        return "отключение коррекции СМА";
    case GFunction::OmitCorrection:
        return "отключение коррекции";
    case GFunction::OmitDressing:
        return "отключение суммарной величины правки";
    case GFunction::OmitZeroOffset:
        return "отключение смещения нуля";
    case GFunction::AllComponents:
        return "все коррекции действительны";
    case GFunction::OverrideAllAxes:
        return "корректор подачи действует по всем осям";
    case GFunction::NoOverride:
        return "отмена коррекции подачи по оси";
    case GFunction::Absolute:
        return "программирование в абсолютных значениях";
    case GFunction::Incremental:
        return "программирование в приращениях";
    case GFunction::SetPosition:
        return "установка фактического положения по оси";
    case GFunction::OscillationStop:
        return "останов осцилляции оси";
    case GFunction::OscillationStart:
        return "пуск осцилляции оси";
    }
    return "";
}

std::string_view gMeaningEn(GFunction f) {
    switch (f) {
    case GFunction::Unknown:
        return "unknown function";
    case GFunction::Rapid:
        return "rapid motion";
    case GFunction::Feed:
        return "motion at the programmed feed";
    case GFunction::Dwell:
        return "dwell";
    case GFunction::Handwheel:
        return "handwheel motion on the axis";
    case GFunction::StopOnSignal:
        return "motion interrupted by a signal";
    case GFunction::OmitHandwheelOffset:
        return "handwheel offset (DRF) left out";
    case GFunction::OmitCorrection:
        return "correction left out";
    case GFunction::OmitDressing:
        return "dressing sum left out";
    case GFunction::OmitZeroOffset:
        return "zero offset left out";
    case GFunction::AllComponents:
        return "all components active";
    case GFunction::OverrideAllAxes:
        return "feed override on all axes";
    case GFunction::NoOverride:
        return "no feed override on the axis";
    case GFunction::Absolute:
        return "absolute dimensions";
    case GFunction::Incremental:
        return "incremental dimensions";
    case GFunction::SetPosition:
        return "set the actual position of the axis";
    case GFunction::OscillationStop:
        return "stop oscillation of the axis";
    case GFunction::OscillationStart:
        return "start oscillation of the axis";
    }
    return "";
}

} // namespace k528::program
