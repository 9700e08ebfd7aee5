#include "session/program_loader.h"
#include "session/core_texts.h"

#include "engine/load_programs.h"
#include "session/diagnostic_texts.h"
#include "engine/program_check.h"
#include "language.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <algorithm>

namespace k528::studio {

namespace {

// lupdate files a free tr() of namespace k528::studio under this context:
// the run time must ask for the same (it asked for its own and got English).
constexpr const char* kTrContext = "k528::studio";
QString tr(const char* text) {
    return QCoreApplication::translate(kTrContext, text);
}

} // namespace

ProgramLoad loadProgramFile(SimulationSession& session, const QString& path) {
    ProgramLoad r;
    if (ShopDatabase::isOpenDatabaseFile(path.toStdString())) {
        r.problem = tr("%1 is the database this window uses: it is not read as a program").arg(path);
        return r;
    }
    std::string text;
    if (!readTextFile(path, text, r.problem)) // why in the window's language
        return r;
    return loadProgramText(session, text, QFileInfo(path).fileName());
}

ProgramLoad loadProgramText(SimulationSession& session, const std::string& text, const QString& name) {
    ProgramLoad r;
    engine::Positioner& ctl = session.controller();
    const engine::FileCheck c = engine::checkFileForMachine(text, {}, session.simulation().profile(), ctl.programs());
    for (const program::Diagnostic& d : c.diagnostics)
        r.findings << diagnosticLine(d); // "LINE:COL: error: …" as `k528 check` prints it
    // The file's order, as `k528 run` picks the first.
    std::vector<const program::Program*> order;
    for (const program::Program& p : c.parsed.store.programs())
        order.push_back(&p);
    std::stable_sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
        return a->headerLine < b->headerLine;
    });
    for (const program::Program* p : order)
        r.programs << p->number;
    if (c.hasErrors()) {
        r.problem = tr("%1 has errors: nothing was loaded.").arg(name);
        return r;
    }
    if (r.programs.isEmpty()) {
        r.problem = tr("%1 holds no program.").arg(name);
        return r;
    }
    if (!engine::loadPrograms(ctl, c.parsed.store).ok()) {
        r.problem = tr("A program is running: stop it (RESET) before loading programs.");
        return r;
    }
    ctl.selectProgram(r.programs.front()); // R252: АВТОМАТ starts it
    r.loaded = true;
    session.advance(0); // the views show the new programs
    return r;
}

} // namespace k528::studio
