#include "session/catalog_texts.h"

#include "catalog/messages.h"
#include "engine/types.h"
#include "engine/views.h"
#include "profile/tools.h"
#include "session/translated_texts.h"
#include "window_language.h"

#include <QCoreApplication>

#include <string>

namespace k528::studio {

namespace {

// catalog::positionerMessages()' English, by number (table М.1).
// clang-format off
const TranslatedText kMessages[] = {
    {"1", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No regulator enable X")},
    {"2", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No answer from encoder slot 0")},
    {"3", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No answer from DAC")},
    {"4", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder channel 1 broken (X)")},
    {"5", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder channel 2 broken (X)")},
    {"6", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "DAC limit exceeded (X)")},
    {"7", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Max. following error X in motion")},
    {"8", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Position/clamp check X")},
    {"9", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Emergency \"STOP\" from PLC")},
    {"10", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Limit switch X \"-\"")},
    {"11", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Limit switch X \"+\"")},
    {"12", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Software limit switch (X)")},
    {"13", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder ratio error (X)")},
    {"14", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "CP52.05 failure in positioner")},
    {"15", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "C-parameters destroyed")},
    {"16", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Drive X not ready")},
    {"17", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No regulator enable Z")},
    {"18", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No answer from encoder slot 1")},
    {"19", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No link with PLC")},
    {"20", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder channel 1 broken (Z)")},
    {"21", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder channel 2 broken (Z)")},
    {"22", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "DAC limit exceeded (Z)")},
    {"23", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Max. following error Z in motion")},
    {"24", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Position/clamp check Z")},
    {"25", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No link with panel")},
    {"26", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Limit switch Z \"-\"")},
    {"27", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Limit switch Z \"+\"")},
    {"28", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Software limit switch (Z)")},
    {"29", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder ratio error (Z)")},
    {"30", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Positioner RAM/ROM failure")},
    {"31", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Control program destroyed")},
    {"32", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Drive Z not ready")},
    {"33", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "X coordinate setting")},
    {"34", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "X/L")},
    {"35", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "X/M17")},
    {"36", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "X/end of L")},
    {"37", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "N encoder error")},
    {"38", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "N DAC error")},
    {"39", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "N handwheel error")},
    {"40", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Home switch not left")},
    {"41", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "No \"0\" mark")},
    {"42", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Not homed")},
    {"43", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Wheel D > Dmax")},
    {"44", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Wheel D < Dmin")},
    {"45", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "L missing")},
    {"46", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Overflow")},
    {"47", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "G?")},
    {"48", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Nesting depth L")},
    {"49", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Z coordinate setting")},
    {"50", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Z/L")},
    {"51", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Z/M17")},
    {"52", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Z/end of L")},
    {"53", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Jump error")},
    {"54", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Duplicate frame numbers")},
    {"55", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "PLC I/O module failure")},
    {"56", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder check X")},
    {"57", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "Encoder check Z")},
    {"58", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "M30/L")},
    {"59", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "M2/L")},
    {"60", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "M17/L")},
    {"61", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "M30/M17")},
    {"62", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "M2/M17")},
    {"63", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "G04/X/Z")},
    {"64", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "G04/L")},
};
// clang-format on

// engine::modeNameEn, by engine::Mode.
const TranslatedText kModes[] = {
    {"1", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "automatic")},
    {"2", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "manual")},
    {"3", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "reference point")},
    {"4", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "presets")},
    {"5", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "machine constants")},
    {"6", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "program editing")},
    {"7", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "data control")},
};

// proveout::toolKindText's English, by profile::ToolKind.
const TranslatedText kToolKinds[] = {
    {"0", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "turning")},
    {"1", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "facing")},
    {"2", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "grooving")},
    {"3", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "boring")},
    {"4", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "drill")},
    {"5", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "threading")},
};

// catalog::rGroupNameEn, by group 1..9 (the preset screens «УСТАНОВОЧНЫЕ ДАННЫЕ n»).
const TranslatedText kRGroups[] = {
    {"1", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "coordinates and offsets")},
    {"2", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "initial position")},
    {"3", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "adjustment")},
    {"4", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "dressing")},
    {"5", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "grinding wheel")},
    {"6", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "diamond")},
    {"7", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "oscillation")},
    {"8", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "speeds")},
    {"9", QT_TRANSLATE_NOOP("k528::studio::CatalogTexts", "axial orientation")},
};

const TranslatedTexts kMessageTexts("k528::studio::CatalogTexts", kMessages);
const TranslatedTexts kModeTexts("k528::studio::CatalogTexts", kModes);
const TranslatedTexts kToolKindTexts("k528::studio::CatalogTexts", kToolKinds);
const TranslatedTexts kRGroupTexts("k528::studio::CatalogTexts", kRGroups);

} // namespace

QString positionerMessageText(int number) { return kMessageTexts.pattern(std::to_string(number)); }

QString alarmMessage(const engine::AlarmView& a) {
    if (const QString text = positionerMessageText(a.number); !text.isEmpty())
        return text;
    return QString::fromStdString(a.textEn); // outside the catalog: the same in both languages
}

QString positionerMessageLine(int number) {
    return QString::fromStdString(
        catalog::numberedMessage(number, positionerMessageText(number).toStdString(), inWindowLanguage(true, false)));
}

QString alarmLine(const engine::AlarmView& a) {
    return QString::fromStdString(
        catalog::numberedMessage(a.number, alarmMessage(a).toStdString(), inWindowLanguage(true, false)));
}

QString modeName(engine::Mode m) { return kModeTexts.pattern(std::to_string(static_cast<int>(m))); }

QString rGroupName(int group) { return kRGroupTexts.pattern(std::to_string(group)); }

QString toolKindText(profile::ToolKind k) { return kToolKindTexts.pattern(std::to_string(static_cast<int>(k))); }

} // namespace k528::studio
