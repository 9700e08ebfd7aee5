#include "editor/database_programs.h"
#include "db/notes.h"
#include "session/diagnostic_texts.h"

#include "db/database.h"
#include "db/error.h"
#include "language.h"
#include "profile/text_format.h"
#include "program/diagnostic.h"
#include "program/parser.h"
#include "session/shop_database.h"

#include <QCoreApplication>
#include <algorithm>

namespace k528::studio {

namespace {

// lupdate files a free tr() of namespace k528::studio under this context:
// the run time must ask for the same (it asked for its own and got English).
constexpr const char* kTrContext = "k528::studio";
QString tr(const char* s) { return QCoreApplication::translate(kTrContext, s); }
QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Lines [from, to) of `text` (0-based), each with its "\n".
std::string lines(const std::vector<std::string_view>& all, int from, int to) {
    std::string out;
    for (int i = std::max(0, from); i < to && i < static_cast<int>(all.size()); ++i) {
        out += all[static_cast<std::size_t>(i)];
        out += '\n';
    }
    // Blank lines at the end separate it from the next program: not its text.
    while (out.size() >= 2 && out[out.size() - 1] == '\n' && out[out.size() - 2] == '\n')
        out.pop_back();
    return out;
}

} // namespace

QStringList databaseMachines(QString* error) {
    QStringList out;
    try {
        for (const db::MachineInfo& m : ShopDatabase::at()->use([](db::Database& d) { return d.machines(); }))
            out << fromStd(m.name);
    } catch (const std::exception& e) {
        if (error)
            *error = databaseErrorText(e);
    }
    return out;
}

DatabasePrograms loadDatabasePrograms(const QString& machine) {
    DatabasePrograms r;
    r.machine = machine;
    try {
        const std::string name = machine.toStdString();
        ShopDatabase::at()->use([&](db::Database& d) {
            const std::optional<db::MachineInfo> info = d.machine(name);
            if (!info) {
                r.error = tr("The database has no machine %1").arg(machine);
                return;
            }
            const profile::MachineProfile p = d.loadMachine(name);
            r.revision = info->revision;
            r.text = fromStd(profile::programsFileText(p));
            r.ok = true;
        });
    } catch (const std::exception& e) {
        r.error = databaseErrorText(e);
    }
    return r;
}

DatabaseSave saveDatabasePrograms(const QString& machine, const QString& text, int expectedRevision) {
    DatabaseSave s;
    const QByteArray utf8 = text.toUtf8();
    const std::string_view t(utf8.constData(), static_cast<std::size_t>(utf8.size()));
    const program::ParseResult parsed = program::parse(t);
    if (parsed.hasErrors()) {
        for (const program::Diagnostic& d : parsed.diagnostics)
            if (d.isError()) {
                s.error = tr("Not saved: fix the syntax errors first: %1")
                              .arg(diagnosticLine(d));
                break;
            }
        return s;
    }
    if (parsed.store.headerless) {
        s.error = tr("Not saved: every program needs its %L header in the machine's memory");
        return s;
    }
    // Cut the text at the programs' headers (the comment lines right above a
    // header go with it; what stands before the first program, with the first).
    std::vector<std::string_view> all;
    for (std::size_t pos = 0; pos < t.size();) {
        const std::size_t end = t.find('\n', pos);
        std::string_view l = t.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        if (!l.empty() && l.back() == '\r')
            l.remove_suffix(1);
        all.push_back(l);
        pos = end == std::string_view::npos ? t.size() : end + 1;
    }
    struct Cut {
        int number; // 0: the %MESSAGES section
        int begin;  // 0-based first line
    };
    std::vector<Cut> cuts;
    for (const program::Program* p : parsed.store.inWrittenOrder())
        cuts.push_back({p->number, p->headerLine - 1 - static_cast<int>(p->leading.size())});
    if (parsed.store.messages.present)
        cuts.push_back({0, parsed.store.messages.headerLine - 1 -
                               static_cast<int>(parsed.store.messages.leading.size())});
    std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.begin < b.begin; });
    if (!cuts.empty())
        cuts.front().begin = 0;
    try {
        const auto shop = ShopDatabase::at();
        const std::string name = machine.toStdString();
        profile::MachineProfile p = shop->use([&](db::Database& d) { return d.loadMachine(name); });
        std::map<int, std::string> programs;
        for (std::size_t i = 0; i < cuts.size(); ++i) {
            if (cuts[i].number == 0)
                continue;
            const int end = i + 1 < cuts.size() ? cuts[i + 1].begin : static_cast<int>(all.size());
            std::string slice = lines(all, cuts[i].begin, end);
            // Unchanged but for blank lines at the end: the stored text stays.
            const auto old = p.programs.find(cuts[i].number);
            if (old != p.programs.end()) {
                std::string trimmed = old->second;
                while (trimmed.size() >= 2 && trimmed.back() == '\n' && trimmed[trimmed.size() - 2] == '\n')
                    trimmed.pop_back();
                if (trimmed == slice)
                    slice = old->second;
            }
            programs[cuts[i].number] = std::move(slice);
        }
        p.programs = std::move(programs);
        p.messages.clear();
        for (const program::Message& m : parsed.store.messages.entries)
            p.messages[m.number] = m.text;
        db::WriteOptions o;
        o.summary = db::noteText({"studio.editor", {}});
        o.expectedRevision = expectedRevision;
        o.allowErrors = true; // the constants are not what this writes
        const db::SaveResult r = shop->use([&](db::Database& d) { return d.saveMachine(name, p, o); });
        if (r.changed)
            shop->noteOwn(name, r.revision);
        s.revision = r.revision;
        s.changed = r.changed;
    } catch (const db::Error& e) {
        s.error = e.kind() == db::ErrorKind::Conflict
                      ? tr("Not saved: %1 was changed in the database since revision %2 was opened (%3)")
                            .arg(machine)
                            .arg(expectedRevision)
                            .arg(databaseErrorDetail(e))
                      : databaseErrorText(e);
    } catch (const std::exception& e) {
        s.error = databaseErrorText(e);
    }
    return s;
}

} // namespace k528::studio
