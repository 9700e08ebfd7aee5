// Loading a program file (shared/spec/program-language.md) into the
// simulated controller, as a technologist proves a program written offline:
// the file is checked for the machine it goes to (engine/program_check.h:
// syntax, every rule, the machine's limits and feeds, over the programs the
// controller already holds); with an error nothing is loaded, otherwise its
// programs and messages replace those of the same numbers and the first of
// its programs is selected for АВТОМАТ.
#pragma once

#include <QString>
#include <QStringList>
#include <string>

namespace k528::studio {

class SimulationSession;

struct ProgramLoad {
    bool loaded = false;
    QList<int> programs;  // the file's program numbers, in the file's order
    QStringList findings; // "LINE:COL: error|warning: [Mnn] text", in the UI language
    QString problem;      // why nothing was loaded ("" when loaded)
};

ProgramLoad loadProgramFile(SimulationSession& session, const QString& path);
// The same for the text of such a file (the editor's text), named `name`.
ProgramLoad loadProgramText(SimulationSession& session, const std::string& text, const QString& name);

} // namespace k528::studio
