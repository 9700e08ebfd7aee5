#include "session/machine_source.h"
#include "db/notes.h"

#include "db/database.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "profile/english.h"
#include "profile/validate.h"
#include "session/shop_database.h"
#include "window_language.h"

#include <QCoreApplication>
#include <QHash>
#include <QSettings>
#include <exception>

namespace k528::studio {

namespace {

constexpr const char* kMachineKey = "machine/name";

QString fromStd(const std::string& s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString databaseProblem(const std::exception& e) {
    return QCoreApplication::translate("k528::studio::MachineSource",
                                       "The machine database is not used: %1")
        .arg(databaseErrorText(e));
}

// The machine's description (its PLC, equipment and prove-out sections, a
// hand-made file named by its `machine` setting) must build a simulation:
// throws plc::DescriptionError before a window is built on it.
void checkDescription(const profile::MachineProfile& p) {
    const machine::Simulation simulation(p);
}

} // namespace

QString MachineSource::text() const {
    switch (kind) {
    case Kind::Unknown: return {};
    case Kind::Database: return QCoreApplication::translate("k528::studio::MachineSource", "database %1").arg(path);
    case Kind::Builtin: return QCoreApplication::translate("k528::studio::MachineSource", "built-in");
    case Kind::File: return path;
    case Kind::NotInDatabase:
        return QCoreApplication::translate("k528::studio::MachineSource", "not in the database %1").arg(path);
    }
    return {};
}

MachineChoice loadMachine(const QString& nameOrPath) {
    const std::string name = nameOrPath.toStdString();
    MachineChoice c;
    bool found = false;
    try {
        // The database, created with the built-in machines (and its folder)
        // when it does not exist: the first start on a new machine.
        found = ShopDatabase::at()->use([&](db::Database& d) {
            if (!profile::checkName(name).empty() || !d.hasMachine(name))
                return false;
            c.profile = d.loadMachine(name);
            c.source = {MachineSource::Kind::Database, fromStd(d.path().string())};
            return true;
        });
    } catch (const std::exception& e) {
        c.warning = databaseProblem(e);
    }
    if (found) {
        checkDescription(c.profile);
        return c;
    }
    c.profile = profile::load(name); // throws profile::FileError
    c.source = profile::isBuiltin(name) ? MachineSource{MachineSource::Kind::Builtin, QString()}
                                        : MachineSource{MachineSource::Kind::File, nameOrPath};
    checkDescription(c.profile);
    return c;
}

QStringList machineNames(QString* warning) {
    QStringList names;
    try {
        for (const db::MachineInfo& m : ShopDatabase::at()->use([](db::Database& d) { return d.machines(); }))
            names << fromStd(m.name);
        return names;
    } catch (const std::exception& e) {
        if (warning)
            *warning = databaseProblem(e);
    }
    for (const std::string& n : profile::builtinNames())
        names << fromStd(n);
    return names;
}

QString machineTitle(const profile::MachineProfile& p) {
    const std::string title = profile::titleText(p, inWindowLanguage(false, true));
    return fromStd(title.empty() ? p.name : title);
}

namespace {

// Two machines of one title (two lathes made from one machine file) are
// told apart by their names.
std::vector<TitledMachine> distinct(std::vector<TitledMachine> machines) {
    QHash<QString, int> count;
    for (const TitledMachine& m : machines)
        ++count[m.title];
    for (TitledMachine& m : machines)
        if (count.value(m.title) > 1 && m.title != m.name)
            m.title = QCoreApplication::translate("k528::studio::MachineSource", "%1 — %2").arg(m.title, m.name);
    return machines;
}

} // namespace

std::vector<TitledMachine> titledMachines(QString* warning) {
    const bool english = inWindowLanguage(false, true);
    try {
        return distinct(ShopDatabase::at()->use([&](db::Database& d) {
            std::vector<TitledMachine> out;
            for (const db::MachineInfo& m : d.machines()) {
                // The list has the Russian title; the English one is a setting
                // of the machine's (text.en.title), read with its profile.
                std::string title = english ? profile::titleText(d.loadMachine(m.name), true) : m.title;
                out.push_back({fromStd(m.name), fromStd(title.empty() ? m.name : title)});
            }
            return out;
        }));
    } catch (const std::exception& e) {
        if (warning)
            *warning = databaseProblem(e);
    }
    std::vector<TitledMachine> out;
    for (const std::string& n : profile::builtinNames())
        out.push_back({fromStd(n), machineTitle(profile::builtin(n))});
    return out;
}

MachineSave saveMachine(const profile::MachineProfile& p) {
    MachineSave s;
    try {
        db::WriteOptions o;
        o.summary = db::noteText({"studio.kept", {}});
        // Constants a trainer made faulty on purpose stay as they are.
        o.allowErrors = true;
        const auto shop = ShopDatabase::at();
        const db::SaveResult r = shop->use([&](db::Database& d) {
            return d.hasMachine(p.name) ? d.saveMachine(p.name, p, o) : d.createMachine(p, o);
        });
        if (r.changed || r.revision == 1)
            shop->noteOwn(p.name, r.revision);
        s.revision = r.revision;
        s.changes = static_cast<int>(r.changes.size());
    } catch (const std::exception& e) {
        s.error = databaseErrorText(e);
    }
    return s;
}

QString startMachineName() {
    return QSettings().value(kMachineKey, fromStd(std::string(profile::kDefaultProfile))).toString();
}

void rememberMachine(const QString& name) {
    QSettings().setValue(kMachineKey, name);
}

} // namespace k528::studio
