// `k528 db`: every subcommand once, with its errors and exit codes
// (0 ok, 1 rejected input, 2 usage / unknown machine / unusable database).
#include "cli_runner.h"
#include "db_test_util.h"
#include "profile/builtin.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>

using namespace k528::testing;

namespace {

QString builtinText(const char* name) {
    const auto t = k528::profile::builtinText(name);
    return QString::fromUtf8(t.data(), static_cast<qsizetype>(t.size()));
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeFile(const QString& path, const QByteArray& data) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    return f.write(data) == data.size();
}

// The line number (1-based) of the first line starting with `prefix`.
int lineOf(const QString& text, const QString& prefix) {
    const QStringList lines = text.split('\n');
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].startsWith(prefix))
            return i + 1;
    return 0;
}

} // namespace

class TestCliDb : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QString db_;
    k528::db::Location where_;

    CliResult db(QStringList args, const QByteArray& in = {}) {
        args.prepend("db");
        args << "--db" << db_;
        return runK528(args, in);
    }

private slots:
    void initTestCase() {
        // Never the user's own database.
        qputenv("K528_DB", (dir_.path() + "/must-not-be-used.db").toUtf8());
    }
    void init() {
        static int n = 0;
        // On PostgreSQL (db.cli.postgresql) a new database for each test.
        where_ = testLocation(dir_, QString("t%1.db").arg(++n).toStdString());
        db_ = QString::fromStdString(where_.text());
        QFile::remove(db_);
    }

    void initCreatesThenReports() {
        auto r = db({"init"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("схема       версия %1 (создана)").arg(k528::db::latestSchemaVersion())),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("загружены   grinder-205, training-lathe (встроенные станки)")));
        QVERIFY(r.out.contains(QStringLiteral("станков     2")));
        r = db({"init", "--lang", "en"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QString("schema    version %1 (up to date)").arg(k528::db::latestSchemaVersion())),
                 qPrintable(r.out));
        QVERIFY(r.out.contains("machines  2"));
        QVERIFY(!r.out.contains("loaded"));
        QCOMPARE(runK528({"db", "init", "extra", "--db", db_}).exitCode, 2);
    }

    void explicitMissingDatabaseIsNotCreated() {
        K528_SQLITE_ONLY();
        auto r = db({"machines", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no database at " + db_), qPrintable(r.err));
        QVERIFY(r.err.contains("k528 db init --db"));
        r = db({"machines"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("нет базы данных " + db_ + " (создать её: k528 db init --db"), qPrintable(r.err));
        QVERIFY(!QFile::exists(db_));
    }

    void defaultLocationIsCreatedOnFirstUse() {
        K528_SQLITE_ONLY();
        QTemporaryDir home;
        const QByteArray old = qgetenv("K528_DB");
        qunsetenv("K528_DB");
        qputenv("XDG_DATA_HOME", home.path().toUtf8());
        const auto r = runK528({"db", "machines"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("grinder-205"));
        QVERIFY(QFile::exists(home.path() + "/k528studio/k528.db"));
        // $K528_DB wins.
        qputenv("K528_DB", (home.path() + "/other.db").toUtf8());
        QCOMPARE(runK528({"db", "init"}).exitCode, 0);
        QVERIFY(QFile::exists(home.path() + "/other.db"));
        qunsetenv("XDG_DATA_HOME");
        qputenv("K528_DB", old);
    }

    void machinesPlainAndJson() {
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"machines"});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QVERIFY(lines[0].startsWith(QStringLiteral("СТАНОК ")));
        QVERIFY(db({"machines", "--lang", "en"}).out.startsWith("MACHINE "));
        QVERIFY(lines[1].startsWith("grinder-205 "));
        QVERIFY(lines[1].contains("приложение Ж"));
        r = db({"machines", "--json"});
        QCOMPARE(r.exitCode, 0);
        const auto ms = QJsonDocument::fromJson(r.out.toUtf8()).object()["machines"].toArray();
        QCOMPARE(ms.size(), 2);
        QCOMPARE(ms[1].toObject()["name"].toString(), QString("training-lathe"));
        QCOMPARE(ms[1].toObject()["revision"].toInt(), 1);
        QVERIFY(ms[0].toObject()["changed_at"].toString().endsWith("Z"));
        QCOMPARE(db({"machines", "--bogus"}).exitCode, 2);
    }

    void showExplainsConstants() {
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"show", "grinder-205"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("станок      grinder-205 — Внутришлифовальный")));
        const QStringList lines = r.out.split('\n');
        const auto line = [&](const QString& start) {
            for (const auto& l : lines)
                if (l.startsWith(start))
                    return l;
            return QString();
        };
        QVERIFY(line("C022  УСКОРЕНИЕ 1").contains(" 2000  "));
        QVERIFY(line("C022  УСКОРЕНИЕ 1").contains("= 0.0781 м/с²"));
        QVERIFY(line("C040  F ОБЫЧНАЯ").contains("= 5000 мм/мин"));
        QVERIFY(line("C069  N ДОС").contains("2-й модуль СР34.23, канал 1"));
        QVERIFY(line("C143  N ручного цикла 1").contains("L11 (ВЫХОД В ИСХОДНОЕ)"));
        QVERIFY(line("R204").contains("= 20.000 мм"));
        QVERIFY(line("R204").contains("ДИАМЕТР НОВ.КРУГА"));
        QVERIFY(r.out.contains("программы: 3 (L1, L11, L14)"));
        r = db({"show", "grinder-205", "--lang", "en"});
        QVERIFY(r.out.contains("ACCELERATION 1"));
        QVERIFY(r.out.contains("= 5000 mm/min"));

        r = db({"show", "grinder-205", "--c", "22"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("C022 УСКОРЕНИЕ 1 (ось X) = 2000"));
        QVERIFY(r.out.contains("диапазон:  0...32767"));
        QVERIFY(r.out.contains("Z4106"));
        QVERIFY(r.out.contains("0,8533 * Vmax / Тразг")); // the manual's text
        QVERIFY(r.out.contains(QStringLiteral("история C022")));
        QCOMPARE(db({"show", "grinder-205", "--c", "C074"}).out.contains("(ось Z) = 4445"), true);

        r = db({"show", "grinder-205", "--r", "204"});
        QVERIFY(r.out.contains("R204 = 20000 = 20.000 мм"));
        QVERIFY(r.out.contains("УСТАНОВОЧНЫЕ ДАННЫЕ"));
        r = db({"show", "grinder-205", "--programs"});
        QVERIFY(r.out.contains("ПРАВКА КРУГА"));
        QVERIFY(r.out.contains("sha256 "));
        r = db({"show", "grinder-205", "--program", "14"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith("%L14 (ПРАВКА КРУГА)\n"));
        QVERIFY(builtinText("grinder-205").contains(r.out));
        r = db({"show", "grinder-205", "--messages"});
        QVERIFY(r.out.contains("#1  ПОДВОД"));
        QVERIFY(r.out.contains("A01  Z1900.0"));
        QVERIFY(r.out.contains("Z1900.0   Нет давления в гидросистеме\n"));

        r = db({"show", "grinder-205", "--json", "--c", "22"});
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o["name"].toString(), QString("grinder-205"));
        const QJsonObject c = o["c"].toArray()[0].toObject();
        QCOMPARE(c["value"].toInt(), 2000);
        QCOMPARE(c["address"].toString(), QString("Z4106"));
        QCOMPARE(c["explanation_en"].toString(),
                 QString("= 0.0781 m/s²; run-up to F AUTO RAPID in 1067 ms"));
        QCOMPARE(o["findings"].toArray().size(), 0);

        // Errors.
        r = db({"show", "lathe-9", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("no machine \"lathe-9\""));
        QVERIFY(r.err.contains("grinder-205, training-lathe"));
        QCOMPARE(db({"show", "grinder-205", "--c", "153"}).exitCode, 2);
        QCOMPARE(db({"show", "grinder-205", "--r", "300"}).exitCode, 2);
        QCOMPARE(db({"show", "grinder-205", "--c", "1", "--programs"}).exitCode, 2);
        QCOMPARE(db({"show"}).exitCode, 2);
        r = db({"show", "grinder-205@2", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("has revisions 1..1; there is no revision 2"));
        QCOMPARE(db({"show", "grinder-205@x"}).exitCode, 2);
    }

    void setValidatesAndRecordsHistory() {
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r =
            db({"set", "grinder-205", "C022=2133", "R12=5", "#9=ПРОВЕРКА", "--author", "Иванов"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("grinder-205: ревизия 2 (изменений: 3)")), qPrintable(r.out));
        QVERIFY(r.out.contains("C022 УСКОРЕНИЕ 1: 2000 -> 2133"));
        QVERIFY(r.out.contains("R12"));
        // A cross-check error: rejected whole with the manual's message.
        r = db({"set", "grinder-205", "C022=1000", "C069=1", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("machine grinder-205: rejected, nothing was written"), qPrintable(r.err));
        QVERIFY(r.err.contains("error [M37] C017,C069:"));
        // In Russian (the default): the same findings in core's Russian.
        r = db({"set", "grinder-205", "C022=1000", "C069=1"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("k528: станок grinder-205: отклонено, ничего не записано (ошибок: 1):")),
                 qPrintable(r.err));
        QVERIFY(r.err.contains("error [M37] C017,C069:"));
        QVERIFY2(!r.err.contains("rejected"), qPrintable(r.err));
        r = db({"set", "grinder-205", "C020=0"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("[M13] C020"));
        r = db({"set", "grinder-205", "C028=100", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("[M6]"));
        // Nothing of the rejected writes landed.
        r = db({"show", "grinder-205", "--c", "22"});
        QVERIFY(r.out.contains("= 2133"));
        QVERIFY(r.out.contains(QStringLiteral("ревизия 2")));
        QVERIFY(r.out.contains("Иванов: 2000 -> 2133"));
        // Allowed on purpose.
        r = db({"set", "grinder-205", "C069=1", "--allow-errors"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("error [M37]"));
        // Removing items; texts; simulation settings.
        r = db(
            {"set", "grinder-205", "R12=", "A10=Нет воздуха", "x.kv=1.5", "title=Шлифовальный 2"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("R12 Параметр пользователя: 5 -> (нет)")));
        r = db({"show", "grinder-205", "--history", "1"});
        QVERIFY(r.out.contains(QStringLiteral("ревизия 4")));
        QVERIFY(!r.out.contains(QStringLiteral("ревизия 3")));
        QVERIFY(r.out.contains("x.kv: 1 -> 1.5"));
        // Usage errors.
        QCOMPARE(db({"set", "grinder-205"}).exitCode, 2);
        QCOMPARE(db({"set", "grinder-205", "C153=1"}).exitCode, 2);
        QCOMPARE(db({"set", "grinder-205", "C022=fast"}).exitCode, 2);
        QCOMPARE(db({"set", "grinder-205", "Q1=1"}).exitCode, 2);
        QCOMPARE(db({"set", "no-such", "C022=1"}).exitCode, 2);
        r = db({"set", "grinder-205", "R240=1"});
        QCOMPARE(r.exitCode, 1); // read only
        QVERIFY(r.err.contains("R240"));
    }

    void exportIsTheMachineFile() {
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"export", "grinder-205"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, builtinText("grinder-205"));
        QCOMPARE(db({"set", "grinder-205", "C022=2133"}).exitCode, 0);
        QCOMPARE(db({"export", "grinder-205@1"}).out, builtinText("grinder-205"));
        const QString out = dir_.filePath("g.k528m");
        QCOMPARE(db({"export", "grinder-205", "--out", out}).exitCode, 0);
        const QString text = QString::fromUtf8(readAll(out));
        QVERIFY(text.contains("C022=2133 ; УСКОРЕНИЕ 1\n"));
        r = db({"export", "training-lathe", "--format", "csv"});
        QVERIFY(r.out.startsWith("number;axis;name;value;unit\n1;X;НАЛИЧ.ОСИ;1;flag\n"));
        QCOMPARE(r.out.count('\n'), 153);
        QCOMPARE(db({"export", "grinder-205", "--format", "xml"}).exitCode, 2);
        QCOMPARE(db({"export", "nope"}).exitCode, 2);
        QCOMPARE(db({"export", "grinder-205", "--out", dir_.filePath("no/dir/x")}).exitCode, 2);
    }

    // --out follows a symbolic link (the link stays), writes into
    // a FIFO directly (it stays a FIFO), refuses a directory with the reason
    // and reports a full device — never replacing what is there.
    void exportOutFollowsLinksAndNeverReplacesSpecialFiles() {
        QCOMPARE(db({"init"}).exitCode, 0);
        const QString target = dir_.filePath("real.k528m");
        QVERIFY(writeFile(target, "old\n"));
        QVERIFY(QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup));
        const QString link = dir_.filePath("link.k528m");
        QFile::remove(link);
        QVERIFY(QFile::link(target, link));
        auto r = db({"export", "grinder-205", "--out", link});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(QString::fromUtf8(readAll(target)), builtinText("grinder-205"));
        QVERIFY(QFile::permissions(target).testFlag(QFile::ReadGroup));
        QVERIFY(!QFile::permissions(target).testFlag(QFile::ReadOther));

        const QString fifo = dir_.filePath("backup.fifo");
        QFile::remove(fifo);
        QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        QProcess p;
        p.start(QStringLiteral(K528_CLI), {"db", "export", "grinder-205", "--out", fifo, "--db", db_});
        QVERIFY(p.waitForStarted());
        QFile reader(fifo);
        QVERIFY(reader.open(QIODevice::ReadOnly)); // waits for the writer
        const QByteArray got = reader.readAll();
        reader.close();
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(QString::fromUtf8(got), builtinText("grinder-205"));
        struct stat st {};
        QCOMPARE(::lstat(fifo.toLocal8Bit().constData(), &st), 0);
        QVERIFY(S_ISFIFO(st.st_mode));

        r = db({"export", "grinder-205", "--out", dir_.path()});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать ") + dir_.path() + QStringLiteral(": это папка")), qPrintable(r.err));
        QVERIFY(!r.err.contains("Success"));
        r = db({"export", "grinder-205", "--out", "/dev/full"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать /dev/full: на устройстве не осталось места")), qPrintable(r.err));
        QVERIFY(QFileInfo("/dev/full").exists() && !QFileInfo("/dev/full").isFile());
    }

    // A backup to a full disk is not a success.
    void lostStandardOutputIsAnError() {
        QCOMPARE(db({"init"}).exitCode, 0);
        for (const QStringList& args : {QStringList{"db", "export", "grinder-205"},
                                        QStringList{"db", "machines"},
                                        QStringList{"db", "machines", "--json"},
                                        QStringList{"db", "show", "grinder-205"}}) {
            const auto r = runK528ToFile(args + QStringList{"--db", db_}, "/dev/full");
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ')));
            QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать стандартный вывод: на устройстве не осталось места")),
                     qPrintable(r.err));
        }
    }

    // `db set` with one item twice names it instead of keeping the last.
    void setRefusesARepeatedItem() {
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"set", "grinder-205", "C022=2133", "C022=2000", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("C022 is given twice ('C022=2133' and 'C022=2000')"), qPrintable(r.err));
        r = db({"set", "grinder-205", "c22=2133", "C022=2000"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("C022 задан дважды («c22=2133» и «C022=2000»)"), qPrintable(r.err));
        QCOMPARE(db({"set", "grinder-205", "R12=5", "R012="}).exitCode, 2);
        QCOMPARE(db({"set", "grinder-205", "C022=2133", "C023=2000"}).exitCode, 0);
        QVERIFY(db({"export", "grinder-205"}).out.contains("C022=2133 "));
    }

    // A mistyped simulation key is refused before a revision is made, naming
    // the known keys close to it; --allow-unknown stores it; removing it is allowed.
    void setRefusesAnUnknownSimulationKey() {
        QCOMPARE(db({"init"}).exitCode, 0);
        const QString before = db({"machines"}).out;
        auto r = db({"set", "grinder-205", "tilte=oops", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("'tilte' is not a known simulation key; nothing was saved"), qPrintable(r.err));
        QVERIFY2(r.err.contains("did you mean title"), qPrintable(r.err));
        QVERIFY2(r.err.contains("--allow-unknown"), qPrintable(r.err));
        r = db({"set", "grinder-205", "tilte=oops"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("«tilte» — неизвестный параметр моделирования; ничего не сохранено (может быть, title?)"),
                 qPrintable(r.err));
        r = db({"set", "grinder-205", "x.kvv=1.5", "C022=2133"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("«x.kvv»") && r.err.contains("x.kv"), qPrintable(r.err));
        QCOMPARE(db({"machines"}).out, before); // no revision was made
        QVERIFY(!db({"export", "grinder-205"}).out.contains("tilte"));
        r = db({"set", "grinder-205", "tilte=oops", "--allow-unknown"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(db({"export", "grinder-205"}).out.contains("tilte=oops"));
        r = db({"set", "grinder-205", "tilte="});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(!db({"export", "grinder-205"}).out.contains("tilte"));
        QCOMPARE(db({"set", "grinder-205", "x.kv=1.5"}).exitCode, 0);
    }

    // The database's errors in the command's language (--lang, Russian by
    // default): the same ids and arguments, never an English sentence in a
    // Russian run.
    void errorsInTheCommandsLanguage() {
        QCOMPARE(db({"init"}).exitCode, 0);
        struct Case {
            QStringList args;
            int exitCode;
            QString ru, en;
        };
        const QList<Case> cases = {
            {{"show", "nosuch"}, 2, "нет станка «nosuch» в " + db_ + " (станки: grinder-205, training-lathe)",
             "no machine \"nosuch\" in " + db_ + " (machines: grinder-205, training-lathe)"},
            {{"show", "grinder-205@7"}, 2, "у станка grinder-205 ревизии 1..1; ревизии 7 нет",
             "machine grinder-205 has revisions 1..1; there is no revision 7"},
            {{"set", "training-lathe", "C999=1"}, 2, "C999: такого C-параметра нет (1..152)",
             "C999: no such C-parameter (1..152)"},
            {{"set", "training-lathe", "R12=x"}, 2, "R12: «x» — не целое число", "R12: 'x' is not a whole number"},
            {{"set", "training-lathe", "A99=x"}, 2, "A99: такого сообщения ПЛК нет (A01..A", "A99: no such PLC message (A01..A"},
            {{"set", "training-lathe", "Q1"}, 2, "«Q1» — не ПУНКТ=ЗНАЧЕНИЕ", "'Q1' is not ITEM=VALUE"},
            {{"set", "training-lathe", "x.kv=999999"}, 1, "значение 999999 вне 0.01..100",
             "value 999999 is outside 0.01..100"},
            {{"set", "nosuch", "C022=2000"}, 2, "нет станка «nosuch»", "no machine \"nosuch\""},
            {{"release", "training-lathe", "L77"}, 2, "у станка training-lathe нет программы L77 (на ревизии 1); ничего не выпущено",
             "machine training-lathe has no program L77 (at revision 1); nothing was released"},
            {{"withdraw", "training-lathe", "L1"}, 1, "ни разу не выпускалась; ничего не записано",
             "was never released; nothing was written"},
        };
        const auto check = [&](const QStringList& args, int exitCode, const QString& ru, const QString& en) {
            auto r = db(args);
            QCOMPARE(r.exitCode, exitCode);
            QVERIFY2(r.err.contains(ru), qPrintable(args.join(' ') + ": " + r.err));
            QVERIFY2(!hasEnglishSentence(r.err), qPrintable(args.join(' ') + ": " + r.err));
            r = db(args + QStringList{"--lang", "en"});
            QCOMPARE(r.exitCode, exitCode);
            QVERIFY2(r.err.contains(en), qPrintable(args.join(' ') + " --lang en: " + r.err));
        };
        for (const Case& c : cases) {
            check(c.args, c.exitCode, c.ru, c.en);
            if (QTest::currentTestFailed())
                return;
        }
        // The trainer's lock of the constants refuses a change in either language.
        QCOMPARE(db({"set", "training-lathe", "constants.lock=A1"}).exitCode, 0);
        check({"set", "training-lathe", "C022=2000"}, 1,
              "станок training-lathe: константы станка заблокированы преподавателем для группы «A1» (параметр "
              "constants.lock): C022 не изменены; ничего не записано",
              "machine training-lathe: the machine constants are locked by the trainer for the class «A1» (setting "
              "constants.lock): C022 not changed; nothing was written");
    }

    // A device as the database is "not a regular file", not
    // "Operation not supported".
    void deviceAsDatabaseIsNamed() {
        K528_SQLITE_ONLY();
        const auto r = runK528({"db", "init", "--db", "/dev/null", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/dev/null: is not a regular file (a character device)"), qPrintable(r.err));
        QVERIFY(!r.err.contains("Operation not supported"));
    }

    // What is wrong with a location, a file, the connection or the command
    // line itself, in the command's language: never an English sentence in
    // a Russian run (SQLite's, libpq's or the system's own words are quoted
    // in «»), the same ids in English with --lang en.
    void locationFileAndUsageErrorsInTheCommandsLanguage() {
        K528_SQLITE_ONLY();
        QTemporaryDir tmp;
        // A database whose pages were overwritten (the integrity check finds
        // it), and one cut short (SQLite cannot read it).
        const QString damaged = tmp.filePath("damaged.db"), cut = tmp.filePath("cut.db");
        for (const QString& f : {damaged, cut})
            QCOMPARE(runK528({"db", "init", "--db", f}).exitCode, 0);
        QByteArray bytes = readAll(damaged);
        QVERIFY(bytes.size() > 4096 * 5 + 3100);
        bytes.replace(4096 * 5 + 100, 3000, QByteArray(3000, '\xff'));
        QVERIFY(writeFile(damaged, bytes));
        QVERIFY(QFile::resize(cut, 4096 * 20));
        struct Case {
            QStringList args;
            int exitCode;
            QStringList ru, en; // what each says (en empty: no English run)
        };
        const QList<Case> cases = {
            {{"db", "machines", "--db", "postgresql://u:pw@h/x"}, 2,
             {"место базы данных «postgresql://u:pw@h/x»: пароль в место базы данных не пишется"},
             {"database location \"postgresql://u:pw@h/x\": a password does not go into a database location"}},
            {{"db", "machines", "--db", "mysql://x/y"}, 2, {"неизвестный вид базы данных «mysql»"},
             {"unknown kind of database \"mysql\""}},
            {{"db", "machines", "--db", "sqlite:"}, 2, {"после sqlite: нужен путь к файлу"}, {"sqlite: needs a file path"}},
            {{"db", "machines", "--db", ""}, 2, {"после --db нужен путь к файлу или URI postgresql://", "Справка: k528 --help."},
             {"--db needs a file path or a postgresql:// URI", "Try 'k528 --help'."}},
            {{"db", "machines", "--db", "postgresql://bad host/x"}, 2, {"нет подключения к базе данных postgresql://bad host/x: «"},
             {"cannot connect to the database postgresql://bad host/x: "}},
            {{"db", "show", "grinder-205", "--db", "/dev/null"}, 2, {"/dev/null: это не обычный файл (символьное устройство)"},
             {"/dev/null: is not a regular file (a character device)"}},
            {{"db", "machines", "--db", damaged}, 2,
             {damaged + ": база данных повреждена (проверка целостности, SQLite: «", "; файл не изменён"},
             {damaged + ": the database is damaged (integrity check: ", "; the file was left untouched"}},
            {{"db", "set", "grinder-205", "C022=2133", "--db", cut}, 2,
             {cut + ": файл не читается как база данных (SQLite: «", "; файл не изменён"},
             {cut + ": cannot be read as a database (", "; the file was left untouched"}},
            {{"db", "machines", "--bogus"}, 2, {"k528: неизвестный параметр --bogus\nСправка: k528 --help."},
             {"k528: unknown option --bogus\nTry 'k528 --help'."}},
            {{"db", "machines", "--db"}, 2, {"параметру --db нужно значение"}, {"option --db needs a value"}},
            {{"db", "bogus"}, 2, {"неизвестная подкоманда db «bogus»"}, {"unknown db subcommand 'bogus'"}},
            {{"db", "machines", "extra"}, 2, {"db machines не принимает аргументов"}, {"db machines takes no arguments"}},
            {{"db", "set", "grinder-205"}, 2, {"db set нужны СТАНОК и хотя бы один ПУНКТ=ЗНАЧЕНИЕ"},
             {"db set needs MACHINE and at least one ITEM=VALUE"}},
            {{"db", "show"}, 2, {"db show нужен один СТАНОК (или СТАНОК@РЕВ)"}, {"db show needs one MACHINE (or MACHINE@REV)"}},
            {{"db", "machines", "--lang", "xx"}, 2, {"--lang — ru или en, а не «xx»"}, {}},
        };
        for (const Case& c : cases) {
            auto r = runK528(c.args);
            QVERIFY2(r.exitCode == c.exitCode, qPrintable(c.args.join(' ') + ": " + r.err));
            for (const QString& s : c.ru)
                QVERIFY2(r.err.contains(s), qPrintable(c.args.join(' ') + ": " + r.err));
            QVERIFY2(!hasEnglishSentence(r.err, false) && !r.err.contains("Try"), qPrintable(c.args.join(' ') + ": " + r.err));
            if (c.en.isEmpty())
                continue;
            // "--db" last takes its value: --lang en goes first.
            QStringList en = c.args;
            en.insert(2, "--lang");
            en.insert(3, "en");
            r = runK528(en);
            QVERIFY2(r.exitCode == c.exitCode, qPrintable(en.join(' ') + ": " + r.err));
            for (const QString& s : c.en)
                QVERIFY2(r.err.contains(s), qPrintable(en.join(' ') + ": " + r.err));
        }
        QVERIFY(readAll(damaged) == bytes); // refused files are left as they were
    }

    // A byte-order mark inside a machine file is shown visibly.
    void byteOrderMarkInsideAMachineFileIsNamed() {
        QCOMPARE(db({"init"}).exitCode, 0);
        const QString f = dir_.filePath("joined.k528m");
        QByteArray text = builtinText("grinder-205").toUtf8();
        const int at = text.indexOf("\n[c]");
        QVERIFY(at > 0);
        text.insert(at + 1, "\xEF\xBB\xBF");
        QVERIFY(writeFile(f, text));
        const auto r = db({"import", f, "--as", "joined", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("U+FEFF (byte-order mark)"), qPrintable(r.err));
        QVERIFY(!r.err.contains(QChar(0xFEFF)));
    }

    void importRejectsBadFilesWhole() {
        QCOMPARE(db({"init"}).exitCode, 0);
        const QString good = builtinText("training-lathe");
        const QString f = dir_.filePath("lathe.k528m");
        QVERIFY(writeFile(f, good.toUtf8()));
        // Exists already.
        auto r = db({"import", f});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("станок training-lathe уже есть в ")), qPrintable(r.err));
        QVERIFY(r.err.contains("--replace"));
        // Under another name: exact.
        r = db({"import", f, "--as", "lathe-2", "--author", "Петров"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("lathe-2: ревизия 1")));
        QCOMPARE(db({"export", "lathe-2"}).out,
                 QString(good).replace("name=training-lathe", "name=lathe-2"));
        // A value outside its range: the file's line, nothing imported.
        QString bad = good;
        bad.replace("\nC040=", "\nC040=9999999 ; x\nC040_=");
        const int badLine = lineOf(bad, "C040=");
        bad.replace("\nC040_=", "\n;");
        QVERIFY(writeFile(f, bad.toUtf8()));
        r = db({"import", f, "--as", "lathe-3", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(f + ":" + QString::number(badLine) + ": "), qPrintable(r.err));
        QVERIFY(r.err.contains("nothing was imported"));
        // In Russian (the default): the same place, core's problem in Russian.
        r = db({"import", f, "--as", "lathe-3"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(f + ":" + QString::number(badLine) + ": C040 = 9999999 вне диапазона") &&
                     r.err.contains(QStringLiteral("ничего не импортировано")),
                 qPrintable(r.err));
        QVERIFY(!db({"machines"}).out.contains("lathe-3"));
        // A cross-check error: the line of the first constant involved.
        QString cross = good;
        const QString dac = "C070=";
        const int dacLine = lineOf(cross, dac);
        QVERIFY(dacLine > 0);
        const QString c18 = cross.split('\n')[lineOf(cross, "C018=") - 1]; // "C018=v ; N ЦАП"
        const QString v18 = c18.mid(5, c18.indexOf(' ') - 5);
        QStringList lines = cross.split('\n');
        lines[dacLine - 1] = "C070=" + v18 + " ; N ЦАП";
        cross = lines.join('\n');
        QVERIFY(writeFile(f, cross.toUtf8()));
        r = db({"import", f, "--as", "lathe-4"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(
            r.err.contains(f + ":" + QString::number(lineOf(cross, "C018=")) + ": error [M38]"),
            qPrintable(r.err));
        QVERIFY(!db({"machines"}).out.contains("lathe-4"));
        QCOMPARE(db({"import", f, "--as", "lathe-4", "--allow-errors"}).exitCode, 0);
        // --replace: the next revision of the machine.
        QString changed = good;
        changed.replace("name=training-lathe", "name=lathe-2");
        changed.replace("\nC021=1000 ", "\nC021=1200 ");
        QVERIFY(writeFile(f, changed.toUtf8()));
        r = db({"import", f, "--replace"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("lathe-2: ревизия 2 (1 изменение)")), qPrintable(r.out));
        QVERIFY(r.out.contains("C021 T контроля ДОС: 1000 -> 1200"));
        QVERIFY(db({"import", f, "--replace"}).out.contains(QStringLiteral("изменений нет")));
        QVERIFY(db({"import", f, "--replace", "--lang", "en"}).out.contains("no changes"));
        // From standard input.
        r = db({"import", "-", "--as", "lathe-5"}, good.toUtf8());
        QCOMPARE(r.exitCode, 0);
        // CSV: the constants of an existing machine.
        const QString csv = dir_.filePath("c.csv");
        QString csvText = db({"export", "grinder-205", "--format", "csv"}).out;
        csvText.replace("\n22;X;УСКОРЕНИЕ 1;2000;", "\n22;X;УСКОРЕНИЕ 1;2133;");
        QVERIFY(writeFile(csv, csvText.toUtf8()));
        r = db({"import", csv, "--as", "grinder-205"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("C022 УСКОРЕНИЕ 1: 2000 -> 2133"));
        QCOMPARE(db({"import", csv}).exitCode, 2); // which machine?
        csvText.replace("\n22;X;УСКОРЕНИЕ 1;2133;", "\n22;Z;УСКОРЕНИЕ 1;2133;");
        QVERIFY(writeFile(csv, csvText.toUtf8()));
        r = db({"import", csv, "--as", "grinder-205"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(csv + ":" + QString::number(lineOf(csvText, "22;")) + ":"),
                 qPrintable(r.err));
        // Usage.
        QCOMPARE(db({"import"}).exitCode, 2);
        QCOMPARE(db({"import", dir_.filePath("missing.k528m")}).exitCode, 2);
        QCOMPARE(db({"import", f, "--as", "Bad Name"}).exitCode, 2);
    }

    void diffOfMachinesRevisionsAndFiles() {
        QCOMPARE(db({"init"}).exitCode, 0);
        QCOMPARE(db({"set", "grinder-205", "C022=2133", "C023=4266"}).exitCode, 0);
        auto r = db({"diff", "grinder-205@1", "grinder-205"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out,
                 QString("--- grinder-205@1\n+++ grinder-205@2\n"
                         "C022 УСКОРЕНИЕ 1: 2000 -> 2133\nC023 УСКОРЕНИЕ 2: 4000 -> 4266\n"));
        r = db({"diff", "grinder-205", "grinder-205"});
        QVERIFY(r.out.endsWith(QStringLiteral("различий нет\n")));
        const QString f = dir_.filePath("g.k528m");
        QVERIFY(writeFile(f, builtinText("grinder-205").toUtf8()));
        r = db({"diff", f, "grinder-205", "--json"});
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o["a"].toString(), f);
        QCOMPARE(o["changes"].toArray().size(), 2);
        QCOMPARE(o["changes"].toArray()[0].toObject()["key"].toString(), QString("C022"));
        QCOMPARE(o["changes"].toArray()[0].toObject()["before"].toString(), QString("2000"));
        r = db({"diff", "grinder-205", "training-lathe"});
        QVERIFY(r.out.contains("name: grinder-205 -> training-lathe"));
        QVERIFY(r.out.contains("L1: changed") || r.out.contains("L1:"));
        r = db({"diff", "grinder-205", "nothing-here"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("«nothing-here» — не станок ")), qPrintable(r.err));
        QVERIFY(db({"diff", "grinder-205", "nothing-here", "--lang", "en"}).err.contains("'nothing-here' is neither"));
        QCOMPARE(db({"diff", "grinder-205@9", "grinder-205"}).exitCode, 2);
        QCOMPARE(db({"diff", "grinder-205"}).exitCode, 2);
    }

    void calcFromPhysicalData() {
        // Appendix Ж, axis X: 5 mm screw, 2500 lines, 10 V = 10 m/min, run-up
        // to 5000 mm/min in 2 s.
        const QStringList axis = {"--screw-lead",  "5",    "--encoder-lines", "2500",
                                  "--drive-volts", "10",   "--drive-speed",   "10000",
                                  "--feed",        "5000", "--rapid",         "8000",
                                  "--auto-rapid",  "5000", "--home-start",    "50",
                                  "--home-creep",  "5",    "--accel",         "runup:5000:2000",
                                  "--diameter", "--lang", "en"};
        auto r = runK528(QStringList{"db", "calc"} + axis);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("C022  УСКОРЕНИЕ 1          1066"), qPrintable(r.out));
        QVERIFY(r.out.contains("C026  К(СКОР)              262"));
        QVERIFY(r.out.contains("C027  К(ОШИБ)              26"));
        QVERIFY(r.out.contains("C028  ПРЕДЕЛ ЦАП           2395"));
        QVERIFY(r.out.contains("C019  L ИМП.ДОС            1"));
        QVERIFY(r.out.contains("C020  N ИМП.ДОС            2"));
        QVERIFY(r.out.contains("C040  F ОБЫЧНАЯ            500000"));
        QVERIFY(r.out.contains("the printed formula 0.8533·Vmax/T gives 2133"));
        QVERIFY(r.out.contains("Formula 1 as printed gives twice the acceleration"));
        r = runK528(QStringList{"db", "calc", "--as-printed"} + axis);
        QVERIFY(r.out.contains("C022  УСКОРЕНИЕ 1          2133"));
        r = runK528(QStringList{"db", "calc", "--json", "--axis", "Z"} + axis);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o["axis"].toString(), QString("Z"));
        QCOMPARE(o["accel1"].toObject()["printed_value"].toInt(), 2133);
        QCOMPARE(o["accel1"].toObject()["formula"].toInt(), 1);
        bool found = false;
        for (const auto& c : o["constants"].toArray())
            if (c.toObject()["number"].toInt() == 74)
                found = c.toObject()["value"].toInt() == 1066;
        QVERIFY(found);
        // From a machine of the database.
        QCOMPARE(db({"init"}).exitCode, 0);
        r = db({"calc", "--machine", "grinder-205", "--axis", "Z", "--lang", "en"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("C078  К(СКОР)              131       (as now)"),
                 qPrintable(r.out));
        QVERIFY(r.out.contains("data of machine grinder-205"));
        // Errors.
        r = runK528({"db", "calc", "--screw-lead", "5", "--lang", "ru"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("db calc нужен --encoder-lines")), qPrintable(r.err));
        QVERIFY(runK528({"db", "calc", "--screw-lead", "5", "--lang", "en"}).err.contains("needs --encoder-lines"));
        QCOMPARE(runK528(QStringList{"db", "calc", "--accel", "fast"} + axis.mid(0, 8)).exitCode,
                 2);
        r = runK528(QStringList{"db", "calc"} + axis + QStringList{"--drive-speed", "100"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("above what the drive reaches"));
        QCOMPARE(runK528(QStringList{"db", "calc", "--discrete", "0.5"} + axis).exitCode, 2);
        // A number out of an option's range says so and gives the range, not «not a number».
        r = runK528(QStringList{"db", "calc"} + axis + QStringList{"--screw-lead", "1e-300"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--screw-lead 1e-300 is out of range: give 0.01..1000 mm"), qPrintable(r.err));
        QVERIFY(!r.err.contains("not a number"));
        r = runK528(QStringList{"db", "calc"} + axis + QStringList{"--encoder-lines", "1e400"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--encoder-lines 1e400 is out of range: give 1..1000000 lines"), qPrintable(r.err));
        r = runK528(QStringList{"db", "calc"} + axis + QStringList{"--feed", "-5"});
        QVERIFY2(r.err.contains("--feed -5 is out of range: give 0..200000 mm/min"), qPrintable(r.err));
        r = runK528(QStringList{"db", "calc"} + axis + QStringList{"--gear", "two"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--gear: 'two' is not a number"), qPrintable(r.err));
        QCOMPARE(runK528(QStringList{"db", "calc"} + axis + QStringList{"--screw-lead", "5e0"}).exitCode, 0);
    }

    void auditLog() {
        QCOMPARE(db({"init"}).exitCode, 0);
        QCOMPARE(db({"set", "grinder-205", "C022=2133", "--author", "Сидоров"}).exitCode, 0);
        auto r = db({"audit", "--limit", "1"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.count('\n'), 1);
        QVERIFY(r.out.contains("Сидоров"));
        QVERIFY(r.out.contains("set"));
        QVERIFY(r.out.contains("grinder-205@2"));
        r = db({"audit", "--json", "--machine", "training-lathe"});
        const auto a = QJsonDocument::fromJson(r.out.toUtf8()).object()["audit"].toArray();
        QCOMPARE(a.size(), 1);
        QCOMPARE(a[0].toObject()["action"].toString(), QString("seed"));
        QCOMPARE(db({"audit", "--limit", "x"}).exitCode, 2);
    }

    // `db check`: a database as written has no problem; SQL that changed
    // one change's author and not its revision's is named, in the
    // command's language, exit 1; the check itself writes nothing.
    void checkNamesWhatIsWrong() {
        QCOMPARE(db({"init"}).exitCode, 0);
        QCOMPARE(db({"set", "grinder-205", "C022=2133", "--author", "Петров"}).exitCode, 0);
        auto r = db({"check"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("проверка    нарушений нет")), qPrintable(r.out));
        r = db({"check", "--lang", "en", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value("ok").toBool(), true);

        QCOMPARE(runSql(where_, "UPDATE changes SET author = 'X' WHERE revision = 2 AND key = 'C022' AND "
                                "machine_id = (SELECT id FROM machines WHERE name = 'grinder-205')"),
                 std::string());
        const QByteArray before = onPostgres() ? QByteArray() : readAll(db_);
        r = db({"check", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("check     problems found: "), qPrintable(r.out));
        QVERIFY2(r.out.contains("machine grinder-205 revision 2: 1 of its changes do not name the revision's "
                                "author and time"),
                 qPrintable(r.out));
        r = db({"check"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("станок grinder-205, ревизия 2: изменений, где автор и время не те, "
                                               "что у ревизии: 1")),
                 qPrintable(r.out));
        QVERIFY2(!hasEnglishSentence(r.out), qPrintable(r.out));
        r = db({"check", "--json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject j = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(j.value("ok").toBool(), false);
        bool named = false;
        for (const auto p : j.value("problems").toArray())
            named = named || (p.toObject().value("kind").toString() == "change-authors" &&
                              p.toObject().value("args").toArray().at(0).toString() == "grinder-205");
        QVERIFY2(named, qPrintable(r.out));
        if (!onPostgres())
            QCOMPARE(readAll(db_), before);
        // Usage: no arguments; a database that is not there is not created.
        QCOMPARE(db({"check", "extra"}).exitCode, 2);
        const QString absent = dir_.filePath("absent.db");
        r = runK528({"db", "check", "--db", absent});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(!QFile::exists(absent));
    }

    void unusableDatabaseIsLeftAlone() {
        K528_SQLITE_ONLY();
        const QByteArray junk = "not a database at all\n" + QByteArray(200, 'x');
        QVERIFY(writeFile(db_, junk));
        for (const QStringList& args :
             {QStringList{"init"}, QStringList{"machines"}, QStringList{"show", "grinder-205"},
              QStringList{"set", "grinder-205", "C022=2133"}, QStringList{"check"}}) {
            auto r = db(args + QStringList{"--lang", "en"});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("not a K528 Studio database"), qPrintable(r.err));
            QVERIFY2(r.err.contains("; the file was left untouched"), qPrintable(r.err));
            r = db(args);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("это не база данных K528 Studio") && r.err.contains("; файл не изменён"),
                     qPrintable(r.err));
            QVERIFY2(!hasEnglishSentence(r.err), qPrintable(r.err));
        }
        QCOMPARE(readAll(db_), junk);
    }

    // A shop file the user may only read (root-owned 0644 in a root-owned
    // folder): listing, showing, exporting, running and checking with its
    // machines work and write nothing; a change is refused naming the file
    // and the permission, in the language asked for. As root (CI) k528 runs
    // as `nobody` (setpriv); as another user the file and folder are chmod'ed.
    void readOnlyDatabase() {
        K528_SQLITE_ONLY();
        const bool root = geteuid() == 0;
        QTemporaryDir top(QDir::temp().filePath("k528-ro-XXXXXX"));
        QVERIFY(top.isValid());
        const QString folder = top.filePath("shop");
        QVERIFY(QDir().mkpath(folder));
        const QString file = folder + "/k528.db";
        QCOMPARE(runK528({"db", "init", "--db", file}).exitCode, 0);
        QCOMPARE(runK528({"db", "set", "grinder-205", "R12=777", "--db", file}).exitCode, 0);
        const QString sample = QStringLiteral(K528_SOURCE_DIR "/resources/samples/grinder-bore-205.k528");
        const auto ranAsOwner = runK528({"run", "--json", "--profile", "grinder-205", "--db", file, sample});
        QCOMPARE(ranAsOwner.exitCode, 0);
        QFile::setPermissions(top.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                              QFileDevice::ExeOwner | QFileDevice::ReadOther |
                                              QFileDevice::ExeOther);
        const auto readable = QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther;
        const auto traversable = readable | QFileDevice::ExeOwner | QFileDevice::ExeGroup | QFileDevice::ExeOther;
        QFile::setPermissions(folder, root ? traversable | QFileDevice::WriteOwner : traversable);
        QFile::setPermissions(file, root ? readable | QFileDevice::WriteOwner : readable);
        const QByteArray before = readAll(file);
        const QStringList filesBefore = QDir(folder).entryList(QDir::Files);
        const auto asReader = [&](QStringList args) {
            if (!root)
                return runK528(args);
            return runProgram("setpriv", QStringList{"--reuid=65534", "--regid=65534", "--clear-groups",
                                                     QStringLiteral(K528_CLI)} + args,
                              60000);
        };
        const auto set = asReader({"db", "set", "grinder-205", "R12=5", "--db", file});
        const auto setEn = asReader({"db", "set", "grinder-205", "R12=5", "--db", file, "--lang", "en"});
        const auto machines = asReader({"db", "machines", "--db", file});
        const auto show = asReader({"db", "show", "grinder-205", "--r", "12", "--db", file});
        const auto exported = asReader({"db", "export", "grinder-205", "--db", file});
        const auto ran = asReader({"run", "--json", "--profile", "grinder-205", "--db", file, sample});
        const auto checked = asReader({"check", "--profile", "grinder-205", "--db", file, sample});
        const auto init = asReader({"db", "init", "--db", file});
        QFile::setPermissions(folder, traversable | QFileDevice::WriteOwner);
        QFile::setPermissions(file, readable | QFileDevice::WriteOwner);

        QCOMPARE(set.exitCode, 2);
        QVERIFY2(set.err.contains("только для чтения: " + file + " (нет права на запись)"), qPrintable(set.err));
        QCOMPARE(setEn.exitCode, 2);
        QVERIFY2(setEn.err.contains("read-only: " + file + " (permission denied); nothing was written"),
                 qPrintable(setEn.err));
        for (const CliResult* r : {&set, &setEn})
            QVERIFY2(!r->err.contains("PRAGMA") && !r->err.contains("attempt to write"), qPrintable(r->err));
        QVERIFY2(machines.exitCode == 0, qPrintable(machines.err));
        QVERIFY(machines.out.contains("grinder-205") && machines.out.contains("training-lathe"));
        QVERIFY2(show.exitCode == 0, qPrintable(show.err));
        QVERIFY2(show.out.contains("777"), qPrintable(show.out));
        QVERIFY2(exported.exitCode == 0 && exported.out.contains("R12=777"), qPrintable(exported.err));
        QVERIFY2(ran.exitCode == 0, qPrintable(ran.err));
        QCOMPARE(ran.out, ranAsOwner.out);
        QVERIFY2(checked.exitCode == 0, qPrintable(checked.err + checked.out));
        QVERIFY2(init.exitCode == 0 && init.out.contains(QStringLiteral("доступ      только чтение (нет права на запись)")), qPrintable(init.err));
        QCOMPARE(readAll(file), before);
        QCOMPARE(QDir(folder).entryList(QDir::Files), filesBefore);
    }

    void helpAndUsage() {
        auto r = runK528({"db", "--help"});
        QCOMPARE(r.exitCode, 0);
        for (const char* sub : {"init", "machines", "show", "set", "export", "import", "diff", "calc",
                                "audit", "copy", "release", "withdraw", "log", "roles"})
            QVERIFY2(r.out.contains(QString("  ") + sub), sub);
        QVERIFY(runK528({"--help"}).out.contains("db "));
        QCOMPARE(runK528({"db"}).exitCode, 2);
        r = runK528({"db", "frobnicate", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("unknown db subcommand 'frobnicate'"));
        // --db before the subcommand.
        QCOMPARE(runK528({"db", "--db", db_, "init"}).exitCode, 0);
        if (onPostgres())
            QCOMPARE(runK528({"db", "--db", db_, "machines"}).exitCode, 0);
        else
            QVERIFY(QFile::exists(db_));
    }
};

QTEST_GUILESS_MAIN(TestCliDb)
#include "test_cli_db.moc"
