// The shop's machines for a test: a test database (`k528 db init`) whose
// machines are the built-in lathe imported under the names given, each with
// its line (`k528 db set NAME line=tcp://127.0.0.1:PORT/1`) to its own
// simulated K528-05 served over Modbus TCP (`k528 serve --tcp` on a free
// localhost port). The tests of `k528 shop`, of its MQTT publisher and of the
// desktop's Shop workspace share it.
#pragma once

#include "cli_runner.h"
#include "rig/tcp_serve.h"

#include <QDir>
#include <QStringList>
#include <functional>
#include <memory>
#include <vector>

namespace k528::testrig {

// The keys that put a served controller in F7 «РАБОТА С ПЭВМ» (after power-on it is in F2).
inline const QString kWorkWithPcKeys = QStringLiteral("F7 1 1 1 1 ENTER DOWN DOWN ENTER");

// A shop's row of machines: m01, m02, …
inline QString shopMachineName(int i) { return QStringLiteral("m%1").arg(i + 1, 2, 10, QLatin1Char('0')); }
inline QStringList shopMachineNames(int n) {
    QStringList names;
    for (int i = 0; i < n; ++i)
        names << shopMachineName(i);
    return names;
}

class ShopMachines {
public:
    QString cli;                                // k528
    QString db;                                 // the test database's file
    QString machineFile;                        // the built-in lathe as exported (dir/lathe.k528m)
    std::vector<quint16> ports;                 // one per machine, then the spare ones
    std::vector<std::unique_ptr<Serve>> serves; // one per machine

    // `k528 ARGS --db db`.
    CliResult k528(QStringList args, int timeoutMs = 60000) const {
        args << "--db" << db;
        return runProgram(cli, args, timeoutMs);
    }

    // Makes the database in `dir` with the machines `names` and starts their
    // servers together (machine i with `keysOf(i)` after `serve --tcp`),
    // then waits for each; `spare` more free ports for the test. "" when
    // every machine serves, else what went wrong.
    QString start(const QString& k528Path, const QDir& dir, const QStringList& names,
                  const std::function<QStringList(int)>& keysOf, int spare = 0) {
        cli = k528Path;
        db = dir.filePath("shop.db");
        const int n = static_cast<int>(names.size());
        ports = freePorts(n + spare);
        if (static_cast<int>(ports.size()) != n + spare)
            return QStringLiteral("not enough free ports");
        CliResult r = k528({"db", "init"});
        if (r.exitCode != 0)
            return "db init: " + r.err;
        machineFile = dir.filePath("lathe.k528m");
        r = k528({"db", "export", "training-lathe", "--out", machineFile});
        if (r.exitCode != 0)
            return "db export: " + r.err;
        for (int i = 0; i < n; ++i) {
            r = k528({"db", "import", machineFile, "--as", names[i]});
            if (r.exitCode != 0)
                return "db import: " + r.err;
            r = k528({"db", "set", names[i], "line=tcp://127.0.0.1:" + QString::number(ports[i]) + "/1"});
            if (r.exitCode != 0)
                return "db set: " + r.out + r.err;
        }
        for (int i = 0; i < n; ++i) {
            serves.push_back(std::make_unique<Serve>(cli, ports[i]));
            serves.back()->begin(keysOf(i));
        }
        for (auto& s : serves) {
            QByteArray said;
            if (!s->serving(&said, 30000))
                return QStringLiteral("%1: exit %2: %3")
                    .arg(s->address())
                    .arg(s->process().exitCode())
                    .arg(QString::fromUtf8(said));
        }
        return {};
    }
    void stop() { serves.clear(); }
};

} // namespace k528::testrig
