// The command line speaks one language at a time: Russian by default, English
// with --lang en. Its own words come from one catalog (app/cli/cli_texts.h)
// with both languages of every id; what `k528 db` reports, what `k528 shop`
// prints and the option errors are said in Russian without an English
// sentence left over, and in English as before.
#include "cli_runner.h"
#include "cli_texts.h"
#include "db/db_test_util.h"
#include "profile/problem.h"
#ifdef K528_CLI_LANG_SHOP
#include "rig/tcp_serve.h"
#endif
#include "util/system_texts.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <cerrno>
#include <cstring>
#include <set>

using k528::testing::hasEnglishSentence;

namespace {

QString fromView(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

std::set<QString> placeholders(const QString& text) {
    std::set<QString> out;
    static const QRegularExpression re(QStringLiteral("%[1-9]"));
    for (auto it = re.globalMatch(text); it.hasNext();)
        out.insert(it.next().captured(0));
    return out;
}

bool hasCyrillic(const QString& text) {
    for (const QChar c : text)
        if (c.script() == QChar::Script_Cyrillic)
            return true;
    return false;
}

// The command line's sources (app/cli), each file's text.
QStringList cliSources() {
    QStringList texts;
    const QDir dir(QStringLiteral(K528_SOURCE_DIR "/app/cli"));
    for (const QString& name : dir.entryList({QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files)) {
        QFile f(dir.filePath(name));
        if (f.open(QIODevice::ReadOnly))
            texts << QString::fromUtf8(f.readAll());
    }
    return texts;
}

} // namespace

class TestCliLang : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QString db_;

    CliResult db(QStringList args) {
        args.prepend(QStringLiteral("db"));
        args << QStringLiteral("--db") << db_;
        return runK528(args);
    }
    CliResult en(QStringList args) { return db(args << QStringLiteral("--lang") << QStringLiteral("en")); }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        db_ = dir_.filePath(QStringLiteral("lang.db"));
        qputenv("K528_DB", QFile::encodeName(db_));
    }

    // Every text has both languages with the same arguments: Russian with
    // Russian words, English without a Russian one (the panel's own names,
    // quoted in «», aside).
    void catalogHasBothLanguages() {
        std::set<std::string_view> ids;
        QVERIFY(k528::cli::cliTexts().texts().size() > 80);
        for (const k528::util::CatalogText& t : k528::cli::cliTexts().texts()) {
            const QString id = fromView(t.id), ru = fromView(t.ru), en = fromView(t.en);
            QVERIFY2(ids.insert(t.id).second, qPrintable(id + ": twice"));
            QVERIFY2(!ru.isEmpty() && !en.isEmpty() && ru != en, qPrintable(id));
            QVERIFY2(hasCyrillic(ru), qPrintable(id + ": " + ru));
            QString enOwn = en;
            enOwn.remove(QRegularExpression(QStringLiteral("«[^«»]*»")));
            QVERIFY2(!hasCyrillic(enOwn), qPrintable(id + ": " + en));
            QVERIFY2(placeholders(ru) == placeholders(en), qPrintable(id + ": " + ru + " | " + en));
        }
    }

    // Core's texts the command line passes on — a file that cannot be read or
    // written and the system's reason, an MQTT address (util/system_texts.h),
    // a line= value (profile's line.* problems) — have both languages with
    // the same arguments, and a reason of the system the C library would say
    // in English only is said from the catalog: every errno of it in Russian.
    void coreTextsHaveBothLanguages() {
        std::vector<k528::util::CatalogText> texts(k528::util::systemTexts().texts().begin(),
                                                   k528::util::systemTexts().texts().end());
        QVERIFY(texts.size() > 40);
        int lines = 0;
        for (const k528::util::CatalogText& t : k528::profile::problemTexts().texts())
            if (t.id.starts_with("line.")) {
                texts.push_back(t);
                ++lines;
            }
        QVERIFY(lines >= 10);
        std::set<std::string_view> ids;
        for (const k528::util::CatalogText& t : texts) {
            const QString id = fromView(t.id), ru = fromView(t.ru), en = fromView(t.en);
            QVERIFY2(ids.insert(t.id).second, qPrintable(id + ": twice"));
            QVERIFY2(!ru.isEmpty() && !en.isEmpty() && ru != en, qPrintable(id));
            QVERIFY2(hasCyrillic(ru) && !hasEnglishSentence(ru), qPrintable(id + ": " + ru));
            QVERIFY2(!hasCyrillic(en), qPrintable(id + ": " + en));
            QVERIFY2(placeholders(ru) == placeholders(en), qPrintable(id + ": " + ru + " | " + en));
        }
        // The English of a system's reason is the C library's own (the
        // command line said strerror() before, and says it with --lang en).
        for (const int e : {ENOENT, EACCES, ENOSPC, EROFS, EISDIR, ENOTDIR, EDQUOT, EIO, ELOOP}) {
            const k528::util::Message m = k528::util::systemError(e);
            QVERIFY2(m.id.starts_with("errno.E"), m.id.c_str());
            QCOMPARE(QString::fromStdString(k528::util::systemText(m, false)), QString::fromUtf8(std::strerror(e)));
            QVERIFY(hasCyrillic(QString::fromStdString(k528::util::systemText(m, true))));
        }
        // One the catalog does not name: its number and the C library's words, quoted.
        const k528::util::Message other = k528::util::systemError(ENOEXEC);
        QCOMPARE(QString::fromStdString(k528::util::systemText(other, true)),
                 QStringLiteral("системная ошибка %1 («%2»)").arg(ENOEXEC).arg(QString::fromUtf8(std::strerror(ENOEXEC))));
    }

    // Each id the commands say is in the catalog (else the id itself would be
    // printed), and each id of the catalog is said somewhere. word() and say()
    // are the short forms of cliText in cmd_grade, cmd_exercise and cmd_link
    // (link::say is core's link catalog, not this one).
    void sourcesSayTheCatalogsIds() {
        const QString sources = cliSources().join('\n');
        static const QRegularExpression call(QStringLiteral("(?<![:\\w])(?:cliText|word|say)\\(\\s*\"([^\"]+)\""));
        int calls = 0;
        for (auto it = call.globalMatch(sources); it.hasNext(); ++calls) {
            const QString id = it.next().captured(1);
            QVERIFY2(k528::cli::cliTexts().find(id.toStdString()), qPrintable(id + ": not in the catalog"));
        }
        QVERIFY2(calls > 80, qPrintable(QString::number(calls)));
        for (const k528::util::CatalogText& t : k528::cli::cliTexts().texts())
            QVERIFY2(sources.contains('"' + fromView(t.id) + '"'), qPrintable(fromView(t.id) + ": never said"));
    }

    // What `k528 db` reports on standard output.
    void databaseReports() {
        const QString version = QString::number(k528::db::latestSchemaVersion());
        auto r = db({"init"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QStringLiteral("база данных %1\nсхема       версия %2 (создана)\n"
                                       "загружены   grinder-205, training-lathe (встроенные станки)\n"
                                       "станков     2\n")
                            .arg(db_, version));
        r = en({"init"});
        QCOMPARE(r.out, QStringLiteral("database  %1\nschema    version %2 (up to date)\nmachines  2\n").arg(db_, version));

        r = db({"machines"});
        QVERIFY2(r.out.startsWith(QStringLiteral("СТАНОК          РЕВ  ИЗМЕНЁН               КЕМ         НАЗВАНИЕ\n")),
                 qPrintable(r.out));
        QVERIFY2(en({"machines"}).out.startsWith("MACHINE         REV  CHANGED               BY          TITLE\n"),
                 qPrintable(r.out));

        r = db({"set", "grinder-205", "C022=2133", "--author", "Иванов"});
        QVERIFY2(r.out.startsWith(QStringLiteral("grinder-205: ревизия 2 (1 изменение)\n")), qPrintable(r.out + r.err));
        r = en({"set", "grinder-205", "C022=2100", "R12=5"});
        QVERIFY2(r.out.startsWith("grinder-205: revision 3 (2 changes)\n"), qPrintable(r.out + r.err));
        r = db({"set", "grinder-205", "C022=2100"});
        QCOMPARE(r.out, QStringLiteral("grinder-205: изменений нет (ревизия 3)\n"));
        r = db({"set", "grinder-205", "R12="});
        QVERIFY2(r.out.contains(QStringLiteral(": 5 -> (нет)")) && !r.out.contains("(none)"), qPrintable(r.out));

        r = db({"show", "grinder-205", "--history", "2"});
        QVERIFY2(r.out.contains(QStringLiteral("станок      grinder-205")) &&
                     r.out.contains(QStringLiteral("ревизия     4, изменил ")) &&
                     r.out.contains(QStringLiteral("(изменений: 2)")),
                 qPrintable(r.out));
        r = en({"show", "grinder-205", "--history", "2"});
        QVERIFY2(r.out.contains("machine   grinder-205") && r.out.contains("revision  4, changed ") &&
                     r.out.contains("(2 changes)"),
                 qPrintable(r.out));
        r = db({"show", "grinder-205", "--program", "77"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("у станка grinder-205 нет программы L77")), qPrintable(r.err));

        r = db({"release", "grinder-205", "L11", "--author", "Петров"});
        QVERIFY2(r.out.startsWith(QStringLiteral("выпущена    grinder-205 L11 в ревизии 1 (SHA-256 ")) &&
                     r.out.contains(QStringLiteral("…): Петров, ")),
                 qPrintable(r.out + r.err));
        r = en({"withdraw", "grinder-205", "L11", "--author", "Petrov"});
        QVERIFY2(r.out.startsWith("withdrawn grinder-205 L11 as of revision 1 (SHA-256 ") && r.out.contains(" by Petrov at "),
                 qPrintable(r.out + r.err));

        r = db({"diff", "grinder-205", "grinder-205"});
        QVERIFY2(r.out.endsWith(QStringLiteral("различий нет\n")), qPrintable(r.out));
        QVERIFY(en({"diff", "grinder-205", "grinder-205"}).out.endsWith("no differences\n"));
        r = db({"diff", "grinder-205", "training-lathe"});
        QVERIFY2(r.exitCode == 0 && !r.out.contains("no differences"), qPrintable(r.err));
        r = db({"diff", "grinder-205", "nosuch"});
        QVERIFY2(r.err.contains(QStringLiteral("«nosuch» — не станок ")), qPrintable(r.err));

        QCOMPARE(db({"log"}).out, QStringLiteral("передач в журнале нет\n"));
        QCOMPARE(en({"log", "grinder-205"}).out, QStringLiteral("no transfers on record for grinder-205\n"));

        r = db({"roles"});
        QVERIFY2(r.out.contains(QStringLiteral("роли        нет: у базы данных SQLite один пользователь")), qPrintable(r.out));
        QVERIFY(en({"roles"}).out.contains("roles     none: an SQLite database has one user"));

        r = db({"copy", "--to", dir_.filePath(QStringLiteral("copy.db"))});
        QVERIFY2(r.out.startsWith(QStringLiteral("скопирована  ")) && r.out.contains(QStringLiteral("журналы     сообщений 0")),
                 qPrintable(r.out + r.err));
        r = en({"copy", "--to", dir_.filePath(QStringLiteral("copy-en.db"))});
        QVERIFY2(r.out.startsWith("copied    ") && r.out.contains("logs      0 messages"), qPrintable(r.out + r.err));

        // Not one English sentence in the Russian reports (paths, names and
        // options are not sentences).
        for (const QStringList& args :
             {QStringList{"init"}, QStringList{"machines"}, QStringList{"show", "grinder-205", "--history", "3"},
              QStringList{"show", "training-lathe", "--programs"}, QStringList{"log"}, QStringList{"roles"}}) {
            r = db(args);
            QVERIFY2(r.exitCode == 0 && !hasEnglishSentence(r.out) && !hasEnglishSentence(r.err),
                     qPrintable(args.join(' ') + ": " + r.out + r.err));
        }
    }

    // `db calc`'s report is read by a technologist: its head line, the steps
    // and the remarks in the language; --json the same in both.
    void calcReport() {
        const QStringList axis = {"db", "calc", "--screw-lead", "5", "--encoder-lines", "2500", "--drive-speed", "10000",
                                  "--feed", "5000", "--rapid", "8000", "--accel", "runup:5000:2000"};
        CliResult r = runK528(axis);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("Ось X, дискрета 0.001 мм\n")) &&
                     r.out.contains(QStringLiteral("C022  УСКОРЕНИЕ 1          1066")) &&
                     r.out.contains(QStringLiteral("\nКак получено:\n")) &&
                     r.out.contains(QStringLiteral("  УСКОРЕНИЕ 1: разгон 0 -> 5000 мм/мин за 2000 мс: A = ")) &&
                     r.out.contains(QStringLiteral("  К(СКОР) = 262 x Kd ")) &&
                     r.out.contains(QStringLiteral("УСКОРЕНИЕ 1 по формуле 1: напечатанная формула 0.8533·Vmax/T даёт 2133")) &&
                     !hasEnglishSentence(r.out),
                 qPrintable(r.out));
        r = runK528(axis + QStringList{"--lang", "en"});
        QVERIFY2(r.out.startsWith("Axis X, discrete 0.001 mm\n") && r.out.contains("\nHow:\n") &&
                     r.out.contains("  ACCELERATION 1: run-up 0 -> 5000 mm/min in 2000 ms: A = ") &&
                     r.out.contains("the printed formula 0.8533·Vmax/T gives 2133"),
                 qPrintable(r.out));
        QCOMPARE(runK528(axis + QStringList{"--json"}).out, runK528(axis + QStringList{"--json", "--lang", "en"}).out);
        r = runK528(axis + QStringList{"--gear", "two"});
        QVERIFY2(r.err.contains(QStringLiteral("--gear: «two» — не число")), qPrintable(r.err));
        r = runK528(axis + QStringList{"--feed", "-5"});
        QVERIFY2(r.err.contains(QStringLiteral("--feed -5 вне диапазона: допустимо 0..200000 мм/мин")), qPrintable(r.err));
    }

    // The usage errors of the commands' own options: Russian, and English with
    // --lang en (never the other language's words).
    void optionErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("ru");
        QTest::addColumn<QString>("en");
        const auto row = [](const char* name, QStringList args, const char* ru, const char* en) {
            QTest::newRow(name) << args << QString::fromUtf8(ru) << QString::fromUtf8(en);
        };
        row("db log", {"db", "log", "a", "b"}, "db log принимает не больше одного станка",
            "db log takes at most one machine");
        row("db log --since", {"db", "log", "--since", "yesterday"}, "после --since нужно время вида 2024-05-17",
            "--since takes a time as 2024-05-17");
        row("db show --c", {"db", "show", "grinder-205", "--c", "999"}, "--c: «999» — не номер C-параметра 1..152",
            "--c: '999' is not a C-parameter number 1..152");
        row("db release", {"db", "release", "grinder-205", "L100"}, "«L100»: программа — L1..L99",
            "'L100': a program is L1..L99");
        row("db export --format", {"db", "export", "grinder-205", "--format", "xml"}, "--format — k528m или csv, а не «xml»",
            "--format is k528m or csv, not 'xml'");
        row("db show @", {"db", "show", "grinder-205@0"}, "«grinder-205@0»: после @ нужен номер ревизии больше 0",
            "'grinder-205@0': the revision after @ must be a positive number");
        row("shop", {"shop", "look"}, "shop нужна подкоманда status или publish", "shop needs status or publish");
        row("shop publish", {"shop", "publish"}, "shop publish нужен --mqtt mqtt://ХОСТ[:ПОРТ]",
            "shop publish needs --mqtt mqtt://HOST[:PORT]");
        row("shop status nosuch", {"shop", "status", "nosuch"}, "нет станка «nosuch» в базе данных",
            "no machine 'nosuch' in the database");
        const QString shaft = QStringLiteral(K528_SOURCE_DIR "/resources/samples/lathe-shaft.k528");
        row("run --override", {"run", "--override", "3", shaft}, "--override — одно из 0 1 2 5 10 20 35 50 75 90 100, а не «3»",
            "--override is one of 0 1 2 5 10 20 35 50 75 90 100, not '3'");
        row("run --r", {"run", "--r", "250=1", shaft}, "--r 250=1: R232..R262 только для чтения",
            "--r 250=1: R232..R262 are read only");
        row("run --program", {"run", "--program", "0", shaft}, "после --program нужен номер программы 1..99, а не «0»",
            "--program needs a program number 1..99, not '0'");
        row("run --pass", {"run", "--pass", "2", shaft}, "--pass задаётся вместе с --from", "--pass goes with --from");
        row("run no file", {"run"}, "run нужен ровно один ФАЙЛ", "run needs exactly one FILE");
        row("check no file", {"check"}, "check нужен хотя бы один ФАЙЛ", "check needs at least one FILE");
        row("check --number", {"check", "--number", "100", shaft}, "после --number нужен номер программы 1..99, а не «100»",
            "--number needs a program number 1..99, not '100'");
        row("format two files", {"format", shaft, shaft}, "format нужен ровно один ФАЙЛ", "format needs exactly one FILE");
        row("path --max-frames", {"path", "--max-frames", "0", shaft}, "после --max-frames нужно целое число 1..100000000, а не «0»",
            "--max-frames needs a whole number 1..100000000, not '0'");
        row("plot --out", {"plot", shaft}, "plot нужен --out ФАЙЛ.png", "plot needs --out FILE.png");
        row("panel button", {"panel", "--keys", "PUSH:START"}, "«PUSH:START» нажимает кнопку станка: задайте --machine",
            "'PUSH:START' presses a button of the machine: give --machine");
        row("panel --lang", {"panel", "--lang", "de"}, "--lang — ru или en, а не «de»", "");
        row("grade", {"grade", "--json", "--csv", "x", shaft}, "--json или --csv, но не оба", "--json or --csv, not both");
        row("exercise", {"exercise"}, "exercise нужна подкоманда list или show ID", "exercise needs list or show ID");
        row("db calc", {"db", "calc", "extra"}, "db calc принимает только параметры", "db calc takes options only");
        row("db trial", {"db", "trial"}, "db trial нужен СТАНОК", "db trial needs MACHINE");
        row("link", {"link", "--port", "/dev/null"}, "link нужна команда: ping, status, pull, push, clear, diag, watch или scan",
            "link needs a command: ping, status, pull, push, clear, diag, watch or scan");
        row("shop status no line", {"shop", "status", "training-lathe"}, "у станка «training-lathe» нет линии: k528 db set",
            "machine 'training-lathe' has no line: k528 db set");
    }
    void optionErrors() {
        QFETCH(QStringList, args);
        QFETCH(QString, ru);
        QFETCH(QString, en);
        QCOMPARE(runK528({"db", "init"}).exitCode, 0);
        CliResult r = runK528(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(ru) && !hasEnglishSentence(r.err) && r.err.contains(QStringLiteral("Справка: k528 --help.")),
                 qPrintable(r.err));
        if (en.isEmpty()) // --lang other than en: Russian, as the default
            return;
        r = runK528(args + QStringList{"--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(en) && !hasCyrillic(r.err), qPrintable(r.err));
    }

    // `k528 shop status`: a machine's line, in the command's language (the
    // line's failure in core's link texts), --json the same in both.
    void shopStatus() {
#ifndef K528_CLI_LANG_SHOP
        QSKIP("built without the link plugins (K528_LINK_PLUGINS)");
#endif
        QCOMPARE(runK528({"db", "init"}).exitCode, 0);
        auto r = runK528({"shop", "status"});
        QVERIFY2(r.exitCode == 0 && r.err.contains(QStringLiteral("k528 shop: ни у одного станка базы данных нет линии")) &&
                     !hasEnglishSentence(r.err),
                 qPrintable(r.err));
        r = runK528({"shop", "status", "--lang", "en"});
        QVERIFY2(r.err.contains("k528 shop: no machine of the database has a line"), qPrintable(r.err));
        // Port 1 of this host: nobody listens, the line is refused at once.
        QCOMPARE(runK528({"db", "set", "grinder-205", "line=tcp://127.0.0.1:1/1"}).exitCode, 0);
        r = runK528({"shop", "status", "grinder-205"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith(QStringLiteral("grinder-205      нет связи нет связи  ")) &&
                     r.out.contains(QStringLiteral("; с ")) && r.out.contains(" tcp://127.0.0.1:1/1") &&
                     !hasEnglishSentence(r.out, false),
                 qPrintable(r.out));
        r = runK528({"shop", "status", "grinder-205", "--lang", "en"});
        QVERIFY2(r.out.startsWith("grinder-205      offline offline  ") && r.out.contains("; since ") && !hasCyrillic(r.out),
                 qPrintable(r.out));
        r = runK528({"shop", "status", "grinder-205", "--json", "--lang", "en"});
        QVERIFY2(r.out.contains("\"online\":false") && r.out.contains("\"state\":\"offline\""), qPrintable(r.out));
        r = runK528({"shop", "status", "grinder-205", "--json"});
        QVERIFY2(r.out.contains("\"online\":false") && r.out.contains("\"state\":\"offline\""), qPrintable(r.out));
    }

    // `k528 link watch` and `scan` print as they go and stop at the first
    // line standard output loses: said as every other command says it, in
    // the command's language, with the system's reason.
    void linkLostOutput() {
#ifndef K528_CLI_LANG_SHOP
        QSKIP("built without the link plugins (K528_LINK_PLUGINS)");
#else
        const std::vector<quint16> ports = k528::testrig::freePorts(1);
        QCOMPARE(ports.size(), std::size_t{1});
        k528::testrig::Serve serve(QStringLiteral(K528_CLI), ports[0]);
        QByteArray said;
        QVERIFY2(serve.start({}, &said), said.constData());
        const QStringList line{"link", "--tcp", serve.address()};
        for (const QStringList& c : {QStringList{"watch", "--seconds", "5"}, QStringList{"scan", "--addresses", "1"}}) {
            CliResult r = runK528ToFile(line + c, "/dev/full");
            QVERIFY2(r.exitCode == 2 &&
                         r.err.contains(
                             QStringLiteral("k528: не удаётся записать стандартный вывод: на устройстве не осталось места")) &&
                         !hasEnglishSentence(r.err),
                     qPrintable(c.join(' ') + ": " + r.err));
            QCOMPARE(r.err.count(QStringLiteral("стандартный вывод")), 1); // said once, though main() flushes again
            r = runK528ToFile(line + c + QStringList{"--lang", "en"}, "/dev/full");
            QVERIFY2(r.exitCode == 2 && r.err.contains("k528: cannot write standard output: No space left on device") &&
                         !hasCyrillic(r.err),
                     qPrintable(c.join(' ') + ": " + r.err));
        }
#endif
    }

    // What goes wrong with a file, a line= value, a --param, an --as, a
    // --blank or an --mqtt address: said in the command's language, Russian
    // without an English sentence, English without a Russian word.
    void failures_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("stdoutFile"); // standard output to this file, else a pipe
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("ru");
        QTest::addColumn<QString>("en");
        const auto row = [](const char* name, QStringList args, const char* out, int code, const char* ru, const char* en) {
            QTest::newRow(name) << args << QString::fromUtf8(out) << code << QString::fromUtf8(ru) << QString::fromUtf8(en);
        };
        const QString shaft = QStringLiteral(K528_SOURCE_DIR "/resources/samples/lathe-shaft.k528");
        row("check /nonexistent", {"check", "/nonexistent"}, "", 2,
            "k528: не удаётся открыть /nonexistent: нет такого файла или папки",
            "k528: cannot open /nonexistent: No such file or directory");
        row("check /dev/zero", {"check", "/dev/zero"}, "", 2,
            "k528: не удаётся прочитать /dev/zero: это символьное устройство, а не обычный файл "
            "(k528 читает только файлы программ и станков)",
            "k528: cannot read /dev/zero: it is a character device, not a regular file "
            "(k528 reads program and machine files only)");
        row("run --trace /dev/full", {"run", "--trace", "/dev/full", shaft}, "/dev/null", 2,
            "k528: файл трассы: не удаётся записать /dev/full: на устройстве не осталось места",
            "k528: the trace: cannot write /dev/full: No space left on device");
        row("path > /dev/full", {"path", shaft}, "/dev/full", 2,
            "k528: не удаётся записать стандартный вывод: на устройстве не осталось места",
            "k528: cannot write standard output: No space left on device");
        row("run --profile /dev/zero", {"run", "--profile", "/dev/zero", shaft}, "", 2,
            "k528: /dev/zero: файл нельзя прочитать: это символьное устройство, а не обычный файл",
            "k528: /dev/zero: cannot read the file: it is a character device, not a regular file");
        row("db export --out /dev/full", {"db", "export", "grinder-205", "--out", "/dev/full"}, "", 2,
            "k528: не удаётся записать /dev/full: на устройстве не осталось места",
            "k528: cannot write /dev/full: No space left on device");
        row("db set line=", {"db", "set", "grinder-205", "line=tcp://10.0.0.5:0/1"}, "", 1,
            "линия «tcp://10.0.0.5:0/1»: порт после хоста — 1..65535",
            "line 'tcp://10.0.0.5:0/1': the port after the host is 1..65535");
        row("db set line= serial", {"db", "set", "grinder-205", "line=serial:/dev/ttyS0?speed=9600"}, "", 1,
            "линия «serial:/dev/ttyS0?speed=9600»: «speed» — не настройка последовательной линии",
            "line 'serial:/dev/ttyS0?speed=9600': 'speed' is not a setting of a serial line");
        row("run --param", {"run", "--param", "1=5", shaft}, "", 2,
            "k528: --param 1=5: C001 = 5 вне диапазона 0...1 константы «НАЛИЧ.ОСИ»",
            "k528: --param 1=5: C001 = 5 is outside the range 0...1 of");
        row("db import --as", {"db", "import", "--as", "1 x", shaft}, "", 2,
            "k528: --as 1 x: в имени «1 x» есть символ, кроме a-z",
            "k528: --as 1 x: ");
        row("check --blank", {"check", "--profile", "training-lathe", "--blank", "UCG,x", shaft}, "", 2,
            "k528: --blank UCG,x: UCG: после «UCG,» ожидался тип N",
            "k528: --blank UCG,x: UCG: expected the type N after UCG,");
        // A file of comments only: read, but no program to run.
        const QString empty = dir_.filePath("comments-only.k528");
        {
            QFile f(empty);
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write("; RU: пусто\n; EN: nothing here\n") > 0);
        }
        row("run: no program", {"run", empty}, "", 1, "comments-only.k528 нет ни одной программы",
            "comments-only.k528 holds no program");
        row("path: no program", {"path", empty}, "", 1, "comments-only.k528 нет ни одной программы",
            "comments-only.k528 holds no program");
        row("unknown option", {"check", "--nosuch", shaft}, "", 2, "неизвестный параметр --nosuch",
            "unknown option --nosuch");
        row("option that takes no value", {"check", "--json=yes", shaft}, "", 2,
            "параметр --json не принимает значения", "option --json takes no value");
        row("db: unknown subcommand", {"db", "nosuch"}, "", 2, "неизвестная подкоманда db «nosuch» (init, machines",
            "unknown db subcommand 'nosuch' (init, machines");
        row("db check: an argument", {"db", "check", "extra"}, "", 2, "db check не принимает аргументов",
            "db check takes no arguments");
#ifdef K528_CLI_LANG_SHOP
        row("shop publish --mqtt", {"shop", "publish", "--mqtt", "http://127.0.0.1:1883"}, "", 2,
            "k528: --mqtt: «http://127.0.0.1:1883» — не mqtt://ХОСТ[:ПОРТ] (MQTT без шифрования; TLS не поддерживается)",
            "k528: --mqtt: 'http://127.0.0.1:1883' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)");
        row("shop publish --mqtt port", {"shop", "publish", "--mqtt", "mqtt://127.0.0.1:0"}, "", 2,
            "k528: --mqtt: «mqtt://127.0.0.1:0»: порт — 1..65535", "k528: --mqtt: 'mqtt://127.0.0.1:0': the port is 1..65535");
        row("shop publish --mqtt host", {"shop", "publish", "--mqtt", "mqtt://:1883"}, "", 2,
            "k528: --mqtt: «mqtt://:1883»: после mqtt:// нет имени или адреса хоста",
            "k528: --mqtt: 'mqtt://:1883': no host name or address after mqtt://");
        // A machine offline (line= to a closed port): its status line is printed, and lost.
        row("shop status > /dev/full", {"shop", "status", "grinder-205"}, "/dev/full", 2,
            "k528: не удаётся записать стандартный вывод: на устройстве не осталось места",
            "k528: cannot write standard output: No space left on device");
#endif
    }
    // (After shopStatus: a machine has a line, so `shop publish` checks --mqtt.)
    void failures() {
        QFETCH(QStringList, args);
        QFETCH(QString, stdoutFile);
        QFETCH(int, exitCode);
        QFETCH(QString, ru);
        QFETCH(QString, en);
        QCOMPARE(runK528({"db", "init"}).exitCode, 0);
        const auto call = [&](const QStringList& a) {
            return stdoutFile.isEmpty() ? runK528(a) : runK528ToFile(a, stdoutFile);
        };
        CliResult r = call(args);
        QCOMPARE(r.exitCode, exitCode);
        // A finding's label stays English (`  error simulation line: …`, as check's).
        QString said = r.err;
        said.remove(QRegularExpression(QStringLiteral("(?m)^\\s+error [\\w. ]+:")));
        QVERIFY2(r.err.contains(ru) && !hasEnglishSentence(said), qPrintable(r.err));
        r = call(args + QStringList{"--lang", "en"});
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains(en) && !hasCyrillic(r.err.remove(QRegularExpression(QStringLiteral("«[^«»]*»")))),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliLang)
#include "test_cli_lang.moc"
