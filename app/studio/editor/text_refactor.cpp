#include "editor/text_refactor.h"

#include "editor/refactor_texts.h"
#include "session/diagnostic_texts.h"
#include "program/diagnostic.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "program/refactor.h"

#include <QCoreApplication>

namespace k528::studio {

namespace {

// lupdate files a free tr() of namespace k528::studio under this context:
// the run time must ask for the same (it asked for its own and got English).
constexpr const char* kTrContext = "k528::studio";
QString tr(const char* s) { return QCoreApplication::translate(kTrContext, s); }

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// The store of `text`, or the reason it cannot be refactored.
bool readStore(const QString& text, program::ProgramStore& store, QString& error) {
    const QByteArray utf8 = text.toUtf8();
    program::ParseResult parsed = program::parse(std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
    if (parsed.hasErrors()) {
        for (const program::Diagnostic& d : parsed.diagnostics)
            if (d.isError()) {
                error = tr("Fix the syntax errors first: %1").arg(diagnosticLine(d));
                break;
            }
        return false;
    }
    store = std::move(parsed.store);
    return true;
}

TextRefactor done(const program::ProgramStore& store) {
    TextRefactor r;
    r.ok = true;
    r.text = fromStd(program::format(store));
    return r;
}

TextRefactor failed(QString error) {
    TextRefactor r;
    r.error = std::move(error);
    return r;
}

} // namespace

TextRefactor renumberText(const QString& text, int program, int start, int step) {
    program::ProgramStore store;
    QString error;
    if (!readStore(text, store, error))
        return failed(error);
    if (program != 0 && !store.contains(program))
        return failed(tr("The file has no program L%1").arg(program));
    for (program::Program& p : store.programs()) {
        if (program != 0 && p.number != program)
            continue;
        const program::RefactorResult r = program::renumber(p, start, step);
        if (!r.ok)
            return failed(QStringLiteral("L%1: ").arg(p.number) + refactorText(r));
    }
    return done(store);
}

TextRefactor moveProgramText(const QString& text, int from, int to, bool copy) {
    program::ProgramStore store;
    QString error;
    if (!readStore(text, store, error))
        return failed(error);
    const program::RefactorResult r = copy ? program::copyProgram(store, from, to) : program::moveProgram(store, from, to);
    if (!r.ok)
        return failed(refactorText(r));
    store.headerless = false; // two programs, or one that is no longer the default number
    return done(store);
}

TextRefactor formatText(const QString& text) {
    program::ProgramStore store;
    QString error;
    if (!readStore(text, store, error))
        return failed(error);
    return done(store);
}

} // namespace k528::studio
