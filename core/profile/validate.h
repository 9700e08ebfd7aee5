// Checking a machine profile.
//
// validate() checks every value against its definition and runs the
// cross-checks of the machine constants that the K528-05 reports with its
// messages (appendix М): one discrete per axis (15), L/N (13 X / 29 Z), N ДОС
// (37), N ЦАП (38), N маховика (39), ПРЕДЕЛ ЦАП against МАКС.ЦАП (6 X / 22 Z),
// manual-cycle programs that do not exist (45), plus checks the manual leaves
// to the technologist (soft limits, speeds, accelerations). The rules and the
// messages chosen are in docs/machine-constants.md.
//
// The item checks (check...) are what the machine-file reader applies to every
// line; they return "" when the item is fine, otherwise what is wrong (English).
#pragma once

#include "catalog/messages.h"
#include "profile/problem.h"
#include "profile/profile.h"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::profile {

enum class Severity { Error, Warning };

struct Finding {
    Severity severity = Severity::Error;
    std::vector<int> cParams;   // C-parameters involved (ascending), may be empty
    std::optional<int> message; // appendix М number the controller reports, if any
    std::string
        subject; // "C022", "C017,C069", "R204", "L11", "#3", "A01", "simulation x.kv", "name"
    // What is wrong, as an id of core's problems and its arguments (the
    // desktop says it by the id in its window's language) ...
    Problem problem;
    // ... and as the catalog says it in Russian and English (the command
    // line, --json, the database's rejection).
    std::string textRu;
    std::string textEn;
};

// All findings, in a fixed order: C values by number, axis cross-checks (X,
// then Z), common cross-checks, then R, programs, messages, PLC texts,
// simulation settings, name and title.
std::vector<Finding> validate(const MachineProfile& p);
// Only the machine constants (ranges and cross-checks); `c` is indexed by
// number (c[0] unused). `programs` is used for the manual-cycle check (45)
// when given.
std::vector<Finding> checkCParams(std::span<const std::int64_t> c,
                                  const std::map<int, std::string>* programs = nullptr);

bool hasErrors(const std::vector<Finding>& findings);
// "error [M37] C017,C069: ..." — one line per finding, its text in Russian
// or English (the label "error"/"warning" stays English in both, as the
// command line's findings do: docs/database.md).
std::string formatFinding(const Finding& f, bool russian = false);

// Item checks: "" if fine, otherwise what is wrong.
std::string checkName(std::string_view name);
std::string checkTitle(std::string_view title);
std::string checkCValue(int number, std::int64_t value);
std::string checkRPreset(int number, std::int64_t value);
std::string checkProgram(int number, std::string_view text);
std::string checkMessage(int number, std::string_view text);
std::string checkPlcText(catalog::PlcGroup group, int k, std::string_view text);
std::string checkSetting(std::string_view key, std::string_view value);

// The program number of a program-language header line «%L<n> ...», or
// nullopt when `line` is not a header. Lexical only (the program parser
// owns the language): optional blanks, '%', 'L' or 'l', digits.
std::optional<int> programHeaderNumber(std::string_view line);

} // namespace k528::profile
