// The trainer's names of the simulated machine's faults in the window's
// language: core's fault id and arguments (machine::faultText) said through
// the translators; core's catalog (machine::faultTexts(), what the CLI says)
// holds the same ids (studio.ui_language fails on an id this table lacks or
// says differently).
#pragma once

#include <QString>

#include <string_view>

namespace k528::machine {
struct FaultSpec;
struct FaultText;
} // namespace k528::machine

namespace k528::studio {

// E.g. "Encoder X: channel 1 broken" / «ДОС X: обрыв канала 1».
QString faultTitle(const machine::FaultSpec& f);
QString faultTitle(const machine::FaultText& t);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasFaultText(std::string_view id);

} // namespace k528::studio
