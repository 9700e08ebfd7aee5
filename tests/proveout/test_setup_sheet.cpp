// The setup sheet (карта наладки, handbook 14.3; docs/proveout.md):
// `k528 setup-sheet` writes a PDF that, read back with pdftotext
// (poppler-utils), names every tool of the machine with its station, each
// program with its cycle time (the figure `k528 path` reports), and every R
// preset — in Russian and in English; its content survives the JSON the
// command hands its renderer.
#include "cli_runner.h"
#include "profile/builtin.h"
#include "profile/english.h"
#include "profile/tools.h"
#include "program/parser.h"
#include "proveout/setup_sheet.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;

namespace {

const QString kShaft = QStringLiteral(K528_SOURCE_DIR "/resources/samples/lathe-shaft.k528");
const QString kGrinder = QStringLiteral(K528_SOURCE_DIR "/resources/samples/grinder-bore-205.k528");

QString pdfText(const QString& pdf) {
    QProcess p;
    p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
    if (!p.waitForFinished(30000) || p.exitCode() != 0)
        return QStringLiteral("pdftotext failed: ") + QString::fromUtf8(p.readAllStandardError());
    QString t = QString::fromUtf8(p.readAllStandardOutput());
    // pdftotext gives the font's ligatures as such («ﬁnishing», «Oﬀset»).
    const std::pair<const char*, const char*> ligatures[] = {
        {"\uFB00", "ff"}, {"\uFB01", "fi"}, {"\uFB02", "fl"}, {"\uFB03", "ffi"}, {"\uFB04", "ffl"}};
    for (const auto& [l, s] : ligatures)
        t.replace(QString::fromUtf8(l), QString::fromUtf8(s));
    return t;
}

// Without white space: a table's cell may wrap a long name over two lines.
QString squeezed(QString s) { return s.remove(QRegularExpression(QStringLiteral("\\s+"))); }

} // namespace

class TestSetupSheet : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString db_;

    // The cycle time of program 1 of `file` as `k528 path --json` gives it.
    double pathCycleTime(const QString& profile, const QString& file) {
        const CliResult r = runK528({"path", "--db", db_, "--profile", profile, "--json", file});
        return QJsonDocument::fromJson(r.out.toUtf8()).object()["cycle_time_s"].toDouble(-1);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        db_ = dir_.filePath("none.db");
    }

    void pdfNamesEveryToolTheCycleTimeAndThePresets_data() {
        QTest::addColumn<QString>("lang");
        QTest::newRow("ru") << "ru";
        QTest::newRow("en") << "en";
    }
    void pdfNamesEveryToolTheCycleTimeAndThePresets() {
        QFETCH(QString, lang);
#ifndef K528_SHEET_RENDERER_BUILT
        QSKIP("the PDF is written by k528-sheet, built with the desktop program; this build (K528_BUILD_GUI=OFF) "
              "has none: withoutTheRendererItSaysSo checks the message instead");
#endif
        const bool ru = lang == "ru";
        const QString pdf = dir_.filePath("shaft-" + lang + ".pdf");
        const CliResult r = runK528({"setup-sheet", "--db", db_, "--profile", "training-lathe", "--lang", lang,
                                     "--out", pdf, kShaft});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString text = pdfText(pdf);
        QVERIFY2(!text.startsWith("pdftotext failed"), qPrintable(text));
        const QString flat = squeezed(text);
        QVERIFY2(text.contains(ru ? QString("Карта наладки") : QString("Setup sheet")), qPrintable(text));
        QVERIFY(text.contains("training-lathe"));
        // The machine's title in the sheet's language.
        QVERIFY2(text.simplified().contains(ru ? QString("Учебный токарный станок") : QString("Training lathe with")),
                 qPrintable(text));
        QVERIFY(text.contains("lathe-shaft.k528"));
        // The blank of the file's UCG comment.
        QVERIFY2(text.contains(ru ? QString("наружный Ø45 мм, длина 80 мм") : QString("outside Ø45 mm, length 80 mm")),
                 qPrintable(text));

        // Every tool: its station, kind, name and offset R-parameters.
        const profile::MachineProfile machine = profile::builtin("training-lathe");
        const std::vector<profile::Tool> tools = profile::tools(machine);
        QCOMPARE(tools.size(), std::size_t(4));
        for (const profile::Tool& t : tools) {
            // Its name in the sheet's language: the machine gives each its English.
            const std::string name = profile::toolName(machine, t, !ru);
            const std::string other = profile::toolName(machine, t, ru);
            QVERIFY(name != other);
            for (const QString& word : QString::fromStdString(name).split(' ')) // a cell may wrap it
                QVERIFY2(text.contains(word), name.c_str());
            QVERIFY2(!text.contains(QString::fromStdString(other).split(' ').front()), qPrintable(text));
            QVERIFY(text.contains(QStringLiteral("T%1").arg(t.station)));
            QVERIFY(flat.contains(squeezed(QString::fromUtf8(std::string(proveout::toolKindText(t.kind, ru)).c_str()))));
            if (t.offsetR >= 0) // on the tool's row: its offset R-parameters
                QVERIFY2(QRegularExpression(QStringLiteral("T%1\\s.*R%2").arg(t.station).arg(t.offsetR)).match(text).hasMatch(),
                         qPrintable(text));
        }
        // The cycle time of the main program: the figure of `k528 path`.
        const double cycle = pathCycleTime("training-lathe", kShaft);
        QVERIFY(cycle > 0);
        const QString seconds = QString::number(cycle, 'f', 1) + (ru ? " с" : " s");
        QVERIFY2(text.contains(QString::number(cycle, 'f', 1)), qPrintable(seconds + "\n" + text));
        QVERIFY(text.contains(ru ? QString("подпрограмма") : QString("subprogram")));
        // Every R preset of the machine, the offsets said to be the tools'.
        for (const auto& [n, v] : machine.r) {
            const QRegularExpression row(QStringLiteral("R%1\\s+%2\\s").arg(n).arg(v));
            QVERIFY2(row.match(text).hasMatch(), qPrintable(QStringLiteral("R%1=%2\n").arg(n).arg(v) + text));
        }
        // The tables' column headers wrap between words only (a narrow column
        // broke «Orientati-on», «Statio-n», «вершин-ы»): each word whole.
        using proveout::SheetText;
        for (const SheetText h : {SheetText::Station, SheetText::Kind, SheetText::Name, SheetText::TipRadius,
                                  SheetText::Orientation, SheetText::OffsetR, SheetText::OffsetX, SheetText::OffsetZ,
                                  SheetText::Program, SheetText::ProgramTitle, SheetText::CycleTime,
                                  SheetText::Parameter, SheetText::Value, SheetText::ValueMm, SheetText::Meaning})
            for (const QString& word : QString::fromUtf8(std::string(proveout::sheetText(h, ru)).c_str()).split(' '))
                QVERIFY2(QRegularExpression(QStringLiteral("(^|\\s)") + QRegularExpression::escape(word) +
                                            QStringLiteral("(\\s|$)"))
                             .match(text)
                             .hasMatch(),
                         qPrintable(word + "\n" + text));
        QVERIFY(text.contains(ru ? QString("коррекция X инструмента 1") : QString("X offset of tool 1")));
        QVERIFY(text.contains("200"));  // R220 in mm
        if (ru) // the Russian sheet is wholly Russian
            for (const char* en : {"Setup sheet", "Tools", "Programs", "Cycle time", "turning", "Station"})
                QVERIFY2(!text.contains(QString::fromUtf8(en)), en);
    }

    void jsonIsTheSameSheetAsThePdf() {
        const CliResult r = runK528({"setup-sheet", "--db", db_, "--profile", "training-lathe", "--json", kShaft});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o["tools"].toArray().size(), 4);
        const QJsonArray programs = o["programs"].toArray();
        QVERIFY(programs.size() >= 2);
        QCOMPARE(programs[0].toObject()["cycle_time_s"].toDouble(), pathCycleTime("training-lathe", kShaft));
        QCOMPARE(programs[1].toObject()["main"].toBool(), false);
        // Both names of each tool and of the machine (the renderer chooses by --lang).
        QCOMPARE(o["tools"].toArray()[0].toObject()["name"].toString(), QString("Резец проходной упорный Т15К6"));
        QCOMPARE(o["tools"].toArray()[0].toObject()["name_en"].toString(), QString("Straight turning tool T15K6"));
        QVERIFY(o["machine_title_en"].toString().startsWith("Training lathe"));
        // The content survives its JSON.
        const std::string text = r.out.trimmed().toStdString();
        QCOMPARE(proveout::sheetJson(proveout::sheetFromJson(text)), text);
    }

    void aMachineWithoutToolsSaysSo() {
#ifndef K528_SHEET_RENDERER_BUILT
        QSKIP("the PDF is written by k528-sheet, built with the desktop program; this build (K528_BUILD_GUI=OFF) "
              "has none: withoutTheRendererItSaysSo checks the message instead");
#endif
        const QString pdf = dir_.filePath("grinder.pdf");
        const CliResult r = runK528({"setup-sheet", "--db", db_, "--profile", "grinder-205", "--lang", "en",
                                     "--out", pdf, kGrinder});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString text = pdfText(pdf);
        QVERIFY2(text.contains("The machine's tools are not described"), qPrintable(text));
        QVERIFY(text.contains("R207")); // the wheel's diameter is a preset of the grinder
    }

    // A build without the desktop program has no renderer: the command says
    // what it needs and where it looked, and writes nothing.
    void withoutTheRendererItSaysSo() {
#ifdef K528_SHEET_RENDERER_BUILT
        QSKIP("this build has the renderer k528-sheet");
#else
        const QString pdf = dir_.filePath("none.pdf");
        const CliResult r = runK528({"setup-sheet", "--db", db_, "--profile", "training-lathe", "--out", pdf, kShaft,
                                     "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("setup-sheet needs the renderer k528-sheet"), qPrintable(r.err));
        const CliResult ru = runK528({"setup-sheet", "--db", db_, "--profile", "training-lathe", "--out", pdf, kShaft});
        QVERIFY2(ru.err.contains(QStringLiteral("setup-sheet: нужна программа отрисовки k528-sheet")), qPrintable(ru.err));
        QVERIFY(!QFile::exists(pdf));
#endif
    }

    void usage() {
        QCOMPARE(runK528({"setup-sheet", "--db", db_, kShaft}).exitCode, 2); // no --out
        const CliResult bad = runK528({"setup-sheet", "--db", db_, "--out", dir_.filePath("x.pdf"),
                                       dir_.filePath("missing.k528")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(!QFile::exists(dir_.filePath("x.pdf")));
    }
};

QTEST_GUILESS_MAIN(TestSetupSheet)
#include "test_setup_sheet.moc"
