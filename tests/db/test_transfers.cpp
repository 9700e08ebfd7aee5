// Every transfer on record, with real parts: a socat pty pair for the RS485
// line, `k528 serve` (the simulated K528-05 in F7) on one end, `k528 link
// push/pull` on the other, the log in a database of its own — an SQLite
// file, or (db.transfers.postgresql) a PostgreSQL database of a throwaway
// cluster. A push for a database machine takes released programs only and
// sends nothing otherwise; each push and pull is on record with its parts'
// CRC-32 and SHA-256; the log a command names must be usable, or nothing is
// sent.
#include "cli_runner.h"
#include "db/database.h"
#include "db/sha256.h"
#include "db_test_util.h"
#include "pty_line.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;
using namespace k528::testing;

class TestTransfers : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ptytest::PtyPair line_;
    ptytest::Serve serve_;
    QString db_;

    CliResult link(QStringList args) {
        args = QStringList{"link", "--lang", "en", "--port", line_.b()} + args;
        return runK528(args);
    }
    CliResult db(QStringList args) {
        args = QStringList{"db"} + args + QStringList{"--db", db_};
        return runK528(args);
    }
    QJsonArray log() {
        const CliResult r = db({"log", "--json"});
        return QJsonDocument::fromJson(r.out.toUtf8()).object()["transfers"].toArray();
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QVERIFY(line_.start(dir_.path(), "t"));
        QVERIFY2(serve_.start(line_.a(), {"--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"}), serve_.said().constData());
        db_ = QString::fromStdString(testLocation(dir_, "shop.db").text());
        QCOMPARE(db({"init"}).exitCode, 0);
    }
    void cleanupTestCase() {
        serve_.stop();
        line_.stop();
    }

    // Drafts are not pushed: named, nothing sent, nothing on record.
    void unreleasedProgramsAreNotSent() {
        const QString file = dir_.filePath("lathe.k528m");
        QCOMPARE(db({"export", "training-lathe", "--out", file}).exitCode, 0);
        const CliResult r = link({"push", file, "--machine", "training-lathe", "--db", db_});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("released programs only") && r.err.contains("L1: draft") &&
                     r.err.contains("L90: draft") && r.err.contains("k528 db release training-lathe") &&
                     r.err.contains("nothing was sent"),
                 qPrintable(r.err));
        QVERIFY2(!r.err.contains("push:"), qPrintable(r.err)); // the line was not used
        QCOMPARE(log().size(), 0);
        // In Russian (the default): the same refusal, no English sentence.
        const CliResult ru = runK528({"link", "--port", line_.b(), "push", file, "--machine", "training-lathe", "--db", db_});
        QCOMPARE(ru.exitCode, 1);
        QVERIFY2(ru.err.contains(QStringLiteral("станок training-lathe: передаются только выпущенные программы; не "
                                                "выпущены в этом виде:\n  L1: черновик, ничего из неё не выпущено")) &&
                     ru.err.contains(QStringLiteral("выпустите их (k528 db release training-lathe L<n>)")) &&
                     ru.err.contains(QStringLiteral("ничего не отправлено")) && !hasEnglishSentence(ru.err),
                 qPrintable(ru.err));
        QCOMPARE(log().size(), 0);
        // A machine the database does not have: refused before the line.
        const CliResult none = link({"push", file, "--machine", "no-such", "--db", db_});
        QCOMPARE(none.exitCode, 2);
        QVERIFY2(none.err.contains("no machine \"no-such\""), qPrintable(none.err));
        // A log the command names that cannot be used: nothing is sent.
        const CliResult lost = link({"push", file, "--db", dir_.filePath("missing.db")});
        QCOMPARE(lost.exitCode, 2);
        QVERIFY2(lost.err.contains("no database at") && lost.err.contains("nothing was sent"), qPrintable(lost.err));
    }

    // Released programs go, and the push is on record with what moved.
    void releasedPushIsOnRecord() {
        for (const char* l : {"L1", "L90", "L91"})
            QCOMPARE(db({"release", "training-lathe", l, "--note", "в работу"}).exitCode, 0);
        const QString file = dir_.filePath("lathe.k528m");
        CliResult r = link({"push", file, "--machine", "training-lathe", "--db", db_});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.err.contains("on record: transfer"), qPrintable(r.err));
        QJsonArray entries = log();
        QCOMPARE(entries.size(), 1);
        const QJsonObject e = entries[0].toObject();
        QCOMPARE(e["direction"].toString(), QString("push"));
        QCOMPARE(e["result"].toString(), QString("ok"));
        QCOMPARE(e["machine"].toString(), QString("training-lathe"));
        QCOMPARE(e["revision"].toInt(), 1);
        QVERIFY2(e["controller"].toString().startsWith("serial:" + line_.b() + "?baud=115200&address=1"),
                 qPrintable(e["controller"].toString()));
        QVERIFY(!e["user"].toString().isEmpty());
        QVERIFY(!e["host"].toString().isEmpty());
        // Each program with its SHA-256 as the database keeps it and a CRC-32.
        db::Database d = db::Database::open(testLocation(dir_, "shop.db"), testOptions());
        int programs = 0;
        QStringList kinds;
        for (const QJsonValue& v : e["items"].toArray()) {
            const QJsonObject i = v.toObject();
            kinds << i["kind"].toString();
            QCOMPARE(i["state"].toString(), QString("new"));
            QCOMPARE(i["crc32"].toString().size(), 8);
            if (i["kind"].toString() == "program") {
                ++programs;
                const auto text = d.programText("training-lathe", i["number"].toInt(), 1);
                QVERIFY(text);
                QCOMPARE(i["sha256"].toString().toStdString(), db::sha256Hex(*text));
            }
        }
        QCOMPARE(programs, 3);
        QVERIFY2(kinds.contains("c") && kinds.contains("r"), qPrintable(kinds.join(",")));

        // A program changed since its release is a draft again: refused.
        QCOMPARE(db({"set", "training-lathe", "#3=ПРОВЕРКА"}).exitCode, 0);
        profile::MachineProfile p = d.loadMachine("training-lathe");
        p.programs[90] += "N99 M02\n";
        d.saveMachine("training-lathe", p, by("Петров"));
        QCOMPARE(db({"export", "training-lathe", "--out", dir_.filePath("draft.k528m")}).exitCode, 0);
        r = link({"push", dir_.filePath("draft.k528m"), "--machine", "training-lathe", "--db", db_});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("L90: not the released version (revision 1)"), qPrintable(r.err));
        QCOMPARE(log().size(), 1);

        // push --machine without a file: the machine as released (L90 of revision 1).
        r = link({"push", "--machine", "training-lathe", "--db", db_});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        entries = log();
        QCOMPARE(entries.size(), 2);
        QCOMPARE(entries[0].toObject()["revision"].toInt(), 3);
        const auto released90 = d.programText("training-lathe", 90, 1);
        bool found90 = false;
        for (const QJsonValue& v : entries[0].toObject()["items"].toArray())
            if (v.toObject()["kind"].toString() == "program" && v.toObject()["number"].toInt() == 90) {
                found90 = true;
                QCOMPARE(v.toObject()["sha256"].toString().toStdString(), db::sha256Hex(*released90));
            }
        QVERIFY(found90);
        // The machine allows drafts: a technologist (SQLite: everyone) pushes them.
        QCOMPARE(db({"set", "training-lathe", "push.unreleased=true"}).exitCode, 0);
        r = link({"push", dir_.filePath("draft.k528m"), "--machine", "training-lathe", "--db", db_});
        QVERIFY2(r.exitCode == 0 && r.err.contains("not released"), qPrintable(r.out + r.err));
        QCOMPARE(log().size(), 3);
    }

    // A pull is on record with what was read.
    void pullIsOnRecord() {
        const CliResult r = link({"pull", "--out", dir_.filePath("pulled.k528m"), "--machine", "training-lathe",
                                  "--db", db_});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject e = log()[0].toObject();
        QCOMPARE(e["direction"].toString(), QString("pull"));
        QCOMPARE(e["result"].toString(), QString("ok"));
        int programs = 0;
        for (const QJsonValue& v : e["items"].toArray()) {
            QCOMPARE(v.toObject()["state"].toString(), QString("read"));
            programs += v.toObject()["kind"].toString() == "program";
        }
        QCOMPARE(programs, 3);
        // The text log names it.
        const CliResult text = db({"log", "training-lathe", "--lang", "en"});
        QVERIFY2(text.out.contains("pull  ok") && text.out.contains("push  ok"), qPrintable(text.out));
        const CliResult ru = db({"log", "training-lathe"});
        QVERIFY2(ru.out.contains(QStringLiteral("из станка  успешно")) && ru.out.contains(QStringLiteral("в станок   успешно")),
                 qPrintable(ru.out));
    }

    // A line that does not answer: the failed push is on record too.
    void failedPushIsOnRecord() {
        serve_.stop();
        const CliResult r = link({"--timeout-ms", "50", "push", "--machine", "training-lathe", "--db", db_});
        QCOMPARE(r.exitCode, 2);
        const QJsonObject e = log()[0].toObject();
        QCOMPARE(e["direction"].toString(), QString("push"));
        QCOMPARE(e["result"].toString(), QString("failed"));
        QVERIFY(!e["detail"].toString().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestTransfers)
#include "test_transfers.moc"
