// Program diagnostics (program/diagnostic_texts.h: an id and its arguments)
// and the rules behind them in the window's language, through its
// translators. The command line says the same ids from core's catalog.
#pragma once

#include <QString>

#include <cstdint>
#include <string_view>

namespace k528::program {
struct Diagnostic;
struct DiagnosticPart;
enum class Rule : std::uint16_t;
} // namespace k528::program
namespace k528::proveout {
enum class Rule : std::uint8_t;
} // namespace k528::proveout

namespace k528::studio {

// E.g. «Ошибка перехода: кадра N40 нет в программе L1».
QString diagnosticText(const program::Diagnostic& d);
QString diagnosticText(const program::DiagnosticPart& p);
// "[M53] " before the text when the controller has a message for it.
QString diagnosticWithManual(const program::Diagnostic& d);
// «12:5: ошибка: [M53] Ошибка перехода: …», as `k528 check` prints it.
QString diagnosticLine(const program::Diagnostic& d);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasDiagnosticText(std::string_view id);

// A short name of a rule for the Problems list («цель перехода»,
// «G00 в материал»); its id (ruleId) goes in the tooltip.
QString ruleName(program::Rule r);
QString ruleName(proveout::Rule r);

} // namespace k528::studio
