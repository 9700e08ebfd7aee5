// Where the workstation's machines come from: the shop's database
// (db::defaultDatabasePath(), $K528_DB; created with the built-in machines on
// the first start), so that the simulated machine runs the constants,
// programs and messages a technologist keeps there (`k528 db`). When the
// database cannot be used the built-in profiles still run, and the reason is
// told (a damaged file is never changed or replaced).
#pragma once

#include "profile/profile.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace k528::studio {

// Where a machine came from, said in the window's language when asked (the
// machine's label says it again after a change of the language).
struct MachineSource {
    enum class Kind { Unknown, Database, Builtin, File, NotInDatabase };
    Kind kind = Kind::Unknown;
    QString path; // the database's or the machine file's
    QString text() const; // "database PATH", "built-in", the file's path; "" when unknown
};

struct MachineChoice {
    profile::MachineProfile profile;
    MachineSource source;
    QString warning; // why the database was not used; empty when it was
};

// The machine `nameOrPath`: a machine of the database, else a built-in
// profile, else a machine file. Throws profile::FileError when nothing fits,
// plc::DescriptionError when its machine description cannot be simulated.
MachineChoice loadMachine(const QString& nameOrPath);

// The machines to choose from: the database's, else the built-in ones.
QStringList machineNames(QString* warning = nullptr);

// How the window names a machine: its title in the window's language (the
// machine file's `title`, or its `title.en` in English), its name where it
// has no title. The name is the shop's identifier, not words for a reader.
QString machineTitle(const profile::MachineProfile& p);

// The machines to choose from (as machineNames()) with their titles.
struct TitledMachine {
    QString name;
    QString title; // machineTitle() of its profile
};
std::vector<TitledMachine> titledMachines(QString* warning = nullptr);

// Keeps `p` as the current state of machine p.name in the database (a new
// revision, with its history; a new machine if the database has none of that
// name). Returns the revision, or 0 and `error` why not (the database cannot
// be used, a value the definitions refuse).
struct MachineSave {
    int revision = 0;
    int changes = 0; // items changed by this revision (0: nothing was different)
    QString error;
};
MachineSave saveMachine(const profile::MachineProfile& p);

// The machine the workstation starts with: the last one chosen (settings),
// else the default profile.
QString startMachineName();
void rememberMachine(const QString& name);

} // namespace k528::studio
