// The window speaks one language (studio.ui_language): every text of the
// main window in each workspace and of each dialog and menu it opens —
// labels, buttons, tool tips, window titles, menus and actions, table
// headers, tabs, placeholders, dock titles, the status bar — is walked in
// `--lang ru` and fails on a Latin word that is not a code, and in
// `--lang en` on a Cyrillic word. What is data, not the UI's words, is
// exempt by where it comes from: the K923's printed legends and its LCD
// (the manual's panel), the machine's name, title, technological and PLC
// message texts and its programs' titles (the profile), the positioner's
// message texts (appendix М), file names and paths the test itself made.
// The allow-list of codes is short and explicit (kAllowedLatin).
//
// Needs X: the backplot dock is a real one only with OpenGL.
#include "backplot/backplot_widget.h"
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "constants/constants_dock.h"
#include "controller/controller_dock.h"
#include "controller/push_preview.h"
#include "database/database_ui.h"
#include "session/shop_database.h"
#include "editor/editor_tab.h"
#include "editor/refactor_actions.h"
#include "editor/refactor_texts.h"
#include "editor/completion_texts.h"
#include "editing/completion.h"
#include "editor/listing_actions.h"
#include "editor/frame_master.h"
#include "editor/program_editor.h"
#include "history/history_dock.h"
#include "history/history_model.h"
#include "history/history_service.h"
#include "k923/k923_widget.h"
#include "k923/key_face.h"
#include "language.h"
#include "link_plugins.h"
#include "machine/fault_texts.h"
#include "machine/pendant_controls.h"
#include "machine/simulation.h"
#include "stock/stock.h"
#include "main_window.h"
#include "db/database.h"
#include "db/db_texts.h"
#include "db/error.h"
#include "link/client.h"
#include "profile/builtin.h"
#include "profile/calculator.h"
#include "proveout/proveout.h"
#include "plc/description_texts.h"
#include "profile/csv.h"
#include "profile/line.h"
#include "profile/problem.h"
#include "util/system_texts.h"
#include "profile/text_format.h"
#include "profile/tools.h"
#include "db/notes.h"
#include "proveout/proveout_pane.h"
#include "session/core_texts.h"
#include "session/catalog_texts.h"
#include "window_language.h"
#include "engine/views.h"
#include "proveout/setup_sheet.h"
#include "controller/link_texts.h"
#include "session/database_texts.h"
#include "session/diagnostic_texts.h"
#include "program/diagnostic_texts.h"
#include "proveout/rules.h"
#include "controller/simulated_controller.h"
#include "editor/program_editor.h"
#include "profile/diff.h"
#include "engine/refusal_texts.h"
#include "engine/types.h"
#include "program/model.h"
#include "program/refactor.h"
#include "session/machine_source.h"
#include "session/simulation_session.h"
#include "training/exercise.h"
#include "training/texts.h"
#include "training/training_texts.h"
#include "catalog/training_texts.h"
#include "workspace/workspaces.h"

#include <QAbstractButton>
#include <QSignalSpy>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDialog>
#include <QDockWidget>
#include <QFileDialog>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTextDocumentFragment>
#include <QTextEdit>
#include <QTimer>
#include <QToolButton>
#include <QtTest>
#include <QtCharts/QAbstractAxis>
#include <QtCharts/QAbstractSeries>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>

#include <filesystem>
#include <functional>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

using namespace k528;
using studio::MainWindow;

namespace {

QString fromView(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Latin words a Russian window may show: codes of the controller and the
// program language (matched by kCode), units, protocols and file formats,
// the panel's and the PC keyboard's key names, the product's name.
const QStringList kAllowedLatin = {
    // units, protocols, file formats, the product
    "mm", "µm", "Modbus", "RTU", "CRC", "K923", "K528", "UCG", "RS485", "PDF", "CSV", "PNG", "JSON", "Studio", "TCP", "MQTT",
    "GNU", "GPL",
    // the program language's words and a plane of its axes
    "IF", "GOTO", "XZ", "ISO", "3D",
    // the manual's formula symbols (table Е.1): Vmax, Tразг, Kд
    "Vmax", "Tразг", "Kд",
    // Qt's Russian translation keeps "OK" (qtbase_ru: QPlatformTheme, QDialogButtonBox)
    "OK",
    // A foreign database file's refusal: the library that wrote it and the
    // header field that says whose it is (they have no other names)
    "SQLite", "application_id",
    // the PC keyboard's keys as printed on them
    "Ctrl", "Shift", "Alt", "Esc", "Tab", "Enter", "Return", "Backspace", "Ins", "Del", "PgUp",
    "PgDown", "Home", "End", "Num",
};
// G01, M03, R12, C022, L5, N15, X, Z, FX, FZ, Gx81, Z1000, A01, F1: an address letter
// (or two) and its number; a lone capital is an axis or an address.
// A hexadecimal number (0x4B353238: a file's application_id) is a code too.
const QRegularExpression kCode(QStringLiteral("^(?:[A-Z]{1,2}[a-z]?\\d+[A-Z]?|[A-Z]|FX|FZ|0x[0-9A-Fa-f]+)$"));
const QRegularExpression kWord(QStringLiteral("[\\p{L}\\p{N}_µ]+"));
const QRegularExpression kLatin(QStringLiteral("[A-Za-z]"));
const QRegularExpression kCyrillic(QStringLiteral("[\\x{0400}-\\x{04FF}]"));
// Names, not words: file paths (absolute, or a relative one with an
// extension), file patterns and extensions ("*.k528", "(.k528m)"), and the
// command line's commands («k528 db import»).
const QRegularExpression kNames(QStringLiteral(
    "(?<![\\p{L}\\p{N}])/[\\w.+-]+(?:/[\\w.+-]*)*"
    "|[\\w.-]+(?:/[\\w.-]+)+\\.\\w+"
    "|(?<![\\p{L}\\p{N}])\\*?\\.[A-Za-z0-9]+"
    "|\\bk528(?:-[a-z]+)?(?: [a-z][a-z-]*)*"));

QString plain(QString text) {
    if (Qt::mightBeRichText(text))
        text = QTextDocumentFragment::fromHtml(text).toPlainText();
    // Mnemonics: "&File" is "File", "&&" is "&".
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
    return text;
}

class Walker {
public:
    QString language;
    QStringList leaks;
    int checked = 0;
    QSet<QString> exemptWords; // the manual's own words (manualWords)
    bool cells = true;         // the tables' cells too (once per window: they do not change by workspace)

    // Texts that are data, exempt wherever they stand as whole words.
    void setData(QStringList data) {
        data.removeAll(QString());
        data.removeDuplicates();
        // Longest first: a text that holds a shorter one is taken out whole.
        std::sort(data.begin(), data.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
        dataPatterns_.clear();
        for (const QString& d : data)
            dataPatterns_ << QRegularExpression(QStringLiteral("(?<![\\p{L}\\p{N}])") +
                                                QRegularExpression::escape(d) +
                                                QStringLiteral("(?![\\p{L}\\p{N}])"));
    }

    void check(const QString& where, const QString& raw) {
        QString text = plain(raw);
        if (text.trimmed().isEmpty())
            return;
        ++checked;
        QString rest = text;
        for (const QRegularExpression& d : dataPatterns_)
            rest.replace(d, QStringLiteral(" "));
        rest.replace(kNames, QStringLiteral(" "));
        QStringList bad;
        for (auto it = kWord.globalMatch(rest); it.hasNext();) {
            const QString w = it.next().captured();
            if (exemptWords.contains(w))
                continue;
            if (language == "ru") {
                if (!w.contains(kLatin) || kCode.match(w).hasMatch() || kAllowedLatin.contains(w))
                    continue;
                bad << w;
            } else if (w.contains(kCyrillic)) {
                bad << w;
            }
        }
        if (!bad.isEmpty()) {
            const QString line = QStringLiteral("%1: «%2» (%3)").arg(where, text.simplified().left(160), bad.join(' '));
            if (!leaks.contains(line))
                leaks << line;
        }
    }

    static QString nameOf(const QObject* o) {
        return o->objectName().isEmpty() ? QString::fromLatin1(o->metaObject()->className())
                                         : o->objectName();
    }
    static QString pathOf(const QWidget* w) {
        QStringList parts;
        for (const QWidget* p = w; p; p = p->parentWidget()) {
            if (!p->objectName().isEmpty() || p->isWindow())
                parts.prepend(nameOf(p));
            if (p->isWindow())
                break;
        }
        return parts.join('/');
    }

    void walkMenu(QMenu* m, const QString& where) {
        emit m->aboutToShow(); // menus that fill themselves as they open
        check(where + " menu title", m->title());
        for (QAction* a : m->actions())
            walkAction(a, where + " > " + plain(m->title()));
    }
    void walkAction(QAction* a, const QString& where) {
        // The language menu names each language in its own words.
        if (a->isSeparator() || a->objectName().startsWith(QLatin1String("action.language.")))
            return;
        check(where + " action " + nameOf(a), a->text());
        if (a->toolTip() != plain(a->text()).remove(QStringLiteral("...")).remove(QStringLiteral("…")))
            check(where + " action tool tip " + nameOf(a), a->toolTip());
        check(where + " action status tip " + nameOf(a), a->statusTip());
        if (QMenu* sub = a->menu(); sub && !walkedMenus.contains(sub)) {
            walkedMenus << sub;
            walkMenu(sub, where);
        }
    }
    QList<QMenu*> walkedMenus;

private:
    QList<QRegularExpression> dataPatterns_;

public:

    void walkModel(QAbstractItemView* v, const QString& where) {
        QAbstractItemModel* m = v->model();
        if (!m)
            return;
        for (int c = 0; c < m->columnCount(); ++c) {
            check(where + QStringLiteral(" header %1").arg(c), m->headerData(c, Qt::Horizontal).toString());
            check(where + QStringLiteral(" header tip %1").arg(c), m->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString());
        }
        // The cells too (the first rows of a long table): a table's words
        // are the UI's as much as its headers. A file dialog lists the file
        // system: names, the system's file types and dates.
        if (qobject_cast<QFileDialog*>(v->window()) || !cells)
            return;
        const int rows = std::min(m->rowCount(), 400);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < m->columnCount(); ++c) {
                const QModelIndex i = m->index(r, c);
                check(where + QStringLiteral(" cell %1,%2").arg(r).arg(c), m->data(i, Qt::DisplayRole).toString());
                check(where + QStringLiteral(" cell tip %1,%2").arg(r).arg(c), m->data(i, Qt::ToolTipRole).toString());
            }
    }

    // Every text of `root` and the widgets in it.
    void walkWidget(QWidget* root) {
        QList<QWidget*> all = root->findChildren<QWidget*>();
        all.prepend(root);
        for (QWidget* w : all) {
            const QString where = pathOf(w);
            if (w->isWindow() || qobject_cast<QDockWidget*>(w))
                check(where + " title", w->windowTitle());
            check(where + " tool tip", w->toolTip());
            check(where + " status tip", w->statusTip());
            check(where + " what's this", w->whatsThis());
            if (auto* l = qobject_cast<QLabel*>(w))
                check(where + " label", l->text());
            if (auto* b = qobject_cast<QAbstractButton*>(w))
                check(where + " button", b->text());
            if (auto* b = qobject_cast<studio::PendantButton*>(w))
                check(where + " legend", b->legend());
            if (auto* b = qobject_cast<studio::MushroomButton*>(w))
                check(where + " legend", b->legend());
            if (auto* b = qobject_cast<studio::PilotLamp*>(w))
                check(where + " legend", b->legend());
            if (auto* s = qobject_cast<studio::SelectorSwitch*>(w)) {
                check(where + " caption", s->caption());
                for (const QString& p : s->positions())
                    check(where + " position", p);
            }
            if (auto* g = qobject_cast<QGroupBox*>(w))
                check(where + " group", g->title());
            if (auto* e = qobject_cast<QLineEdit*>(w))
                check(where + " placeholder", e->placeholderText());
            if (auto* e = qobject_cast<QPlainTextEdit*>(w))
                check(where + " placeholder", e->placeholderText());
            if (auto* e = qobject_cast<QTextEdit*>(w))
                check(where + " placeholder", e->placeholderText());
            if (auto* c = qobject_cast<QComboBox*>(w)) {
                check(where + " placeholder", c->placeholderText());
                for (int i = 0; i < c->count(); ++i)
                    check(where + " item", c->itemText(i));
            }
            if (auto* s = qobject_cast<QSpinBox*>(w)) {
                check(where + " prefix", s->prefix());
                check(where + " suffix", s->suffix());
            }
            if (auto* s = qobject_cast<QAbstractSpinBox*>(w))
                check(where + " special value", s->specialValueText());
            if (auto* t = qobject_cast<QTabBar*>(w))
                for (int i = 0; i < t->count(); ++i) {
                    check(where + " tab", t->tabText(i));
                    check(where + " tab tip", t->tabToolTip(i));
                }
            if (auto* v = qobject_cast<QAbstractItemView*>(w))
                walkModel(v, where);
            if (auto* cv = qobject_cast<QChartView*>(w))
                if (QChart* chart = cv->chart()) {
                    check(where + " chart title", chart->title());
                    for (QAbstractAxis* a : chart->axes())
                        check(where + " axis title", a->titleText());
                    for (QAbstractSeries* series : chart->series())
                        check(where + " series", series->name());
                }
            if (auto* m = qobject_cast<QMenu*>(w)) {
                if (!walkedMenus.contains(m)) {
                    walkedMenus << m;
                    walkMenu(m, where);
                }
            }
            if (auto* bar = qobject_cast<QMenuBar*>(w))
                for (QAction* a : bar->actions())
                    walkAction(a, where);
            if (auto* bar = qobject_cast<QStatusBar*>(w))
                check(where + " message", bar->currentMessage());
            for (QAction* a : w->actions())
                walkAction(a, where);
        }
        for (QAction* a : root->findChildren<QAction*>())
            walkAction(a, pathOf(root));
    }
};

// The K923's printed legends and its LCD's mode names: the manual's panel texts.
QStringList panelTexts() {
    QStringList out;
    for (int k = 0; k < panel::kKeyCount; ++k) {
        const auto key = static_cast<panel::Key>(k);
        const studio::KeyFace f = studio::keyFace(key);
        out << studio::keyTitle(key) << f.legend << f.corner << f.sub;
    }
    for (int m = 1; m <= 7; ++m) {
        const auto mode = static_cast<engine::Mode>(m);
        out << fromView(engine::modeNameRu(mode)) << fromView(engine::modeTagRu(mode));
    }
    out << QStringLiteral("РАБОТА С ПЭВМ"); // F7's LCD item (panel/screens/data_control.cpp)
    for (const catalog::CParamDef& c : catalog::cParams())
        out << fromView(c.name); // ПАР's LCD names of the constants (table Е.1)
    return out;
}

// The training course's exercises (resources/exercises/: data a trainer
// writes, each title in Russian and in English as written).
QStringList courseTexts() {
    QStringList out;
    for (const training::Exercise& e : training::shippedExercises())
        out << QString::fromStdString(e.title.ru) << QString::fromStdString(e.title.en);
    return out;
}

// The machine's own texts (the profile: data, in the language it was
// written in) and the titles of the programs on its controller.
QStringList machineTexts(const profile::MachineProfile& p, const program::ProgramStore& store) {
    QStringList out;
    out << QString::fromStdString(p.name) << QString::fromStdString(p.title);
    for (const auto& [n, t] : p.messages)
        out << QString::fromStdString(t);
    for (auto g : {catalog::PlcGroup::Alarm, catalog::PlcGroup::Work, catalog::PlcGroup::System})
        for (const auto& [n, t] : p.plcTexts(g))
            out << QString::fromStdString(t);
    for (const program::Program& pr : store.programs())
        if (pr.title)
            out << QString::fromStdString(*pr.title);
    for (const program::Message& m : store.messages.entries)
        out << QString::fromStdString(m.text);
    return out;
}

// The manual's own words in core's catalog of its reference tables (C- and
// R-parameters, messages): in a Russian window the Latin symbols its Russian
// text uses (Ks, Ke, MX, DRF, x4…), in an English one the Cyrillic that our
// English keeps of it: the LCD names and preset lines it quotes («КОНТРОЛЬ
// …», УСТ screens) and the notes' quotes of the printed text.
QSet<QString> manualWords(const QString& language) {
    const bool ru = language == QLatin1String("ru");
    QSet<QString> out;
    const auto take = [&](std::string_view t) {
        for (auto it = kWord.globalMatch(fromView(t)); it.hasNext();) {
            const QString w = it.next().captured();
            if (ru ? w.contains(kLatin) : w.contains(kCyrillic))
                out << w;
        }
    };
    for (const catalog::CParamDef& c : catalog::cParams()) {
        if (ru) {
            take(c.name);
            take(c.descriptionRu);
            take(c.hintRu);
        } else {
            take(c.descriptionEn);
            take(c.hintEn);
            take(c.note);
        }
    }
    for (int n = 0; n < 300; ++n)
        if (const catalog::RParamDef* r = catalog::findRParam(n)) {
            take(ru ? r->meaningRu : r->meaningEn);
            take(r->panelHint);
            if (!ru)
                take(r->note);
        }
    for (int n = 1; n <= 64; ++n) {
        const catalog::PositionerMessage& m = catalog::positionerMessage(n);
        take(ru ? m.textRu : m.textEn);
        take(ru ? m.commentRu : m.commentEn);
    }
    return out;
}

// The positioner's message texts (appendix М) as the LCD shows them.
// The link plugins' names and versions (the Controller dock lists them).
QStringList pluginNames() {
    QStringList names;
    for (const k528::linkplugin::Found& f : k528::linkplugin::discover())
        names << f.name + QLatin1Char(' ') + f.version;
    return names;
}

QStringList positionerTexts() {
    QStringList out;
    for (int n = 1; n <= 64; ++n) {
        const catalog::PositionerMessage& m = catalog::positionerMessage(n);
        out << QString::fromStdString(m.panelText()) << fromView(m.textRu);
    }
    return out;
}

// Every id of one of core's catalogs has a text in the window (`has`), the
// same Russian as core's catalog (what `k528 … --lang ru` prints): `say(id)`
// is the window's text of the id with some arguments and core's. With a
// walker, the window's text is walked for words of another language too.
void checkCatalog(const util::TextCatalog& catalog, const std::function<bool(std::string_view)>& has,
                  const std::function<std::pair<QString, std::string>(std::string_view)>& say,
                  Walker* walker = nullptr, const QString& what = {}) {
    for (const util::CatalogText& t : catalog.texts()) {
        QVERIFY2(has(t.id), t.id.data());
        const auto [window, core] = say(t.id);
        QCOMPARE(window, QString::fromStdString(core));
        if (walker)
            walker->check(what.arg(fromView(t.id)), window);
    }
}

} // namespace

class TestUiLanguage : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioUiLanguageTest");
        QSettings().clear();
        QVERIFY(dir_.isValid());
        // A database of its own: what the window lists of it (the message
        // history, the database's programs, revisions) is what this test
        // made, not what other tests of the suite left in the shared one.
        qputenv("K528_DB", QFile::encodeName(dir_.filePath("k528.db")));
        // A file the editor and the controller load, and one with a warning
        // (a frame after the endless jump is never reached) for the load report.
        file_ = dir_.filePath("ui.k528");
        warnFile_ = dir_.filePath("warn.k528");
        QFile f(file_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("%L1 (UI)\nN1 G1 X60 FX2000\nN2 G1 Z-40 FZ2000\nN3 M30\n");
        QFile g(warnFile_);
        QVERIFY(g.open(QIODevice::WriteOnly));
        g.write("%L2 (UI)\nN1 G1 X60 FX2000\nN2 GOTO 1\nN3 M30\n");
    }
    void russian() { walkAll("ru", "ru"); }
    void english() { walkAll("en", "en"); }
    // Switched at run time: every text follows the new language.
    void russianAfterEnglish() { walkAll("en", "ru"); }
    void englishAfterRussian() { walkAll("ru", "en"); }
    // What fails is said in Russian too: the controller link's errors
    // (core says each in both languages), a transfer's parts and the push
    // preview, the database's (libpq in Russian through gettext; SQLite's
    // English only as the quoted detail of a Russian sentence).
    void russianErrors();
    // Core's texts that come as ids (a machine file's or a CSV's problems,
    // revision notes, a UCG line's and a tool's errors) have a Russian text
    // each, and the places that show them say them in Russian: File >
    // Machine with a bad machine file, the constants dock's import of a bad
    // file, the prove-out pane with a bad blank or a bad tool.
    void russianCoreTexts();
    // A UCG line's errors and the simulated machine's faults: every id of
    // core's catalog (what `k528` prints) has the same Russian in the window.
    void russianBlankAndFaultTexts();
    // The names and messages of core's catalogs the window says through
    // tr() (the positioner's messages, the modes, the kinds of tool): in
    // Russian letter by letter core's Russian, in English core's English.
    void catalogTextsAsCore();
    // A file the window cannot read or write says why in the window's
    // language — core's catalog of the system's reasons, not the C
    // library's English that Qt's errorString() gives: the editor saving
    // into a folder that is not there (the tests run as root, who may write
    // anywhere else) or over a folder, opening a file that is not there.
    void fileProblemsInTheWindowsLanguage();

private:
    QTemporaryDir dir_;
    QString file_, warnFile_;

    // Runs `open` (which may wait in a dialog's own loop) and walks each
    // window and popup menu that appears meanwhile, then closes it; `want`
    // windows at least must appear.
    void walkOpened(Walker& walker, const QString& what, const std::function<void()>& open, int want = 1) {
        QSet<QWidget*> seen;
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->isVisible())
                seen << w;
        int found = 0;
        QTimer poll;
        poll.setInterval(20);
        connect(&poll, &QTimer::timeout, [&] {
            for (QWidget* w : QApplication::topLevelWidgets()) {
                if (!w->isVisible() || seen.contains(w))
                    continue;
                seen << w;
                ++found;
                Walker one = walker;
                one.leaks.clear();
                one.checked = 0;
                one.walkWidget(w);
                for (QString& l : one.leaks)
                    walker.leaks << what + ": " + l;
                walker.checked += one.checked;
                if (auto* d = qobject_cast<QDialog*>(w))
                    d->done(QDialog::Rejected);
                else
                    w->close();
            }
        });
        poll.start();
        open();
        QTRY_VERIFY2_WITH_TIMEOUT(found >= want, qPrintable(what + ": no window opened"), 5000);
        poll.stop();
        QApplication::processEvents();
    }

    void walkWindow(Walker& walker, MainWindow& w) {
        for (const QString& id : {QStringLiteral("operator"), QStringLiteral("technologist"), QStringLiteral("training"),
                                 QStringLiteral("shop")}) {
            QVERIFY(w.workspaces()->activate(id));
            QApplication::processEvents();
            Walker one = walker;
            one.leaks.clear();
            one.checked = 0;
            one.cells = id == QLatin1String("operator");
            one.walkWidget(&w);
            for (const QString& l : one.leaks)
                if (!walker.leaks.contains(l))
                    walker.leaks << l;
            walker.checked += one.checked;
        }
    }

    void clickNamed(MainWindow& w, const char* name) {
        auto* b = w.findChild<QAbstractButton*>(name);
        QVERIFY2(b, name);
        // As the user does: the pane shown first.
        for (QWidget* p = b; p; p = p->parentWidget())
            if (auto* d = qobject_cast<QDockWidget*>(p)) {
                d->show();
                d->raise();
            }
        QApplication::processEvents();
        b->click();
    }

    void walkDialogs(Walker& walker, MainWindow& w) {
        auto* editor = w.programEditor();
        walkOpened(walker, "File > Load programs", [&] { w.findChild<QAction*>("action.loadPrograms")->trigger(); });
        walkOpened(walker, "File > Load programs: the report", [&] { w.loadProgramsFrom(warnFile_); });
        walkOpened(walker, "Help > About", [&] {
            for (QAction* a : w.menuBar()->actions().last()->menu()->actions())
                a->trigger();
        });
        walkOpened(walker, "File > Machine: one that cannot be loaded", [&] { w.switchMachine("no-such-machine"); });
        walkOpened(walker, "Editor > Open", [&] { editor->openDialog(); });
        walkOpened(walker, "Editor > Save as", [&] { editor->saveAs(); });
        walkOpened(walker, "Editor > Renumber", [&] { editor->refactor()->renumberDialog(); });
        walkOpened(walker, "Editor > Move a program", [&] { editor->refactor()->moveProgramDialog(); });
        walkOpened(walker, "Editor > PDF", [&] { editor->listing()->exportPdfDialog(); });
        walkOpened(walker, "Editor > Open from the database", [&] { editor->openDatabaseDialog(); });
        walkOpened(walker, "Editor: the context menu", [&] {
            QWidget* v = editor->currentEditor()->viewport();
            QContextMenuEvent e(QContextMenuEvent::Mouse, QPoint(5, 5), v->mapToGlobal(QPoint(5, 5)));
            QApplication::sendEvent(v, &e);
        });
        // The completion of an M: the built-in ones and the machine's PLC
        // M-codes, each with what it does in the window's language.
        QStringList items;
        walkOpened(walker, "Editor: the completion of an M", [&] {
            studio::ProgramEditor* e = editor->currentEditor();
            QVERIFY(e->hasMachine());
            e->append("N4 ");
            const int last = e->lines() - 1;
            e->setCursorPosition(last, static_cast<int>(e->text(last).size()));
            e->setFocus();
            QTest::keyClicks(e, "M");
            for (QWidget* t : QApplication::topLevelWidgets())
                if (auto* l = qobject_cast<QListWidget*>(t); l && l->isVisible())
                    for (int i = 0; i < l->count(); ++i)
                        items << l->item(i)->text();
        });
        // M0 M2 M17 M30, and the training lathe's M3 … M64
        QVERIFY2(items.size() >= 15, qPrintable(items.join('|')));
        const QString m3 = items.filter(QRegularExpression(QStringLiteral("^M3 "))).value(0);
        QVERIFY2(m3.contains(walker.language == QLatin1String("ru") ? QStringLiteral("шпинделя по часовой стрелке")
                                                                    : QStringLiteral("spindle clockwise")),
                 qPrintable(m3));
        walkOpened(walker, "Editor: close a changed file", [&] {
            editor->currentEditor()->append("\n");
            editor->closeDocument(editor->documentCount() - 1); // the current: the file opened last
        });
        for (int k = 0; k < studio::FrameMaster::KindCount; ++k) {
            walkOpened(walker, QStringLiteral("Frame master %1").arg(k), [&] {
                studio::FrameMaster m(&w);
                m.setKind(static_cast<studio::FrameMaster::Kind>(k));
                m.exec();
            });
        }
        walkOpened(walker, "K923: the context menu", [&] {
            studio::K923Widget* k = w.k923();
            QContextMenuEvent e(QContextMenuEvent::Mouse, QPoint(5, 5), k->mapToGlobal(QPoint(5, 5)));
            QApplication::sendEvent(k, &e);
        });
        walkOpened(walker, "K923: the keyboard map", [&] { w.k923()->showKeyboardMap(); });
        if (auto* pane = w.findChild<studio::ConstantsPane*>())
            pane->selectConstant(22); // the history is of the selected constant
        for (const char* b : {"constants.history", "constants.diff", "constants.calculator", "constants.import",
                              "constants.export", "scope.csv", "scope.png", "history.csv", "rparams.trialPart"})
            walkOpened(walker, QString::fromLatin1(b), [&] { clickNamed(w, b); });
    }

    void walkAll(const QString& first, const QString& language) {
        QVERIFY(studio::setLanguage(first));
        MainWindow w;
        w.placeOnScreen();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // A program on the controller and in the editor: the Program tab,
        // the backplot, the outline and the messages show it.
        QVERIFY(w.loadProgramsFrom(file_));
        w.programEditor()->openFile(file_);
        // A message of the positioner in the history (its text is the
        // manual's, in Russian and in English): the emergency stop, released.
        auto* history = w.findChild<studio::HistoryService*>();
        QVERIFY(history && history->isOpen());
        w.session()->simulation().pressEmergencyStop();
        w.session()->advance(50);
        w.session()->simulation().releaseEmergencyStop();
        w.session()->advance(50);
        history->flush();
        auto* historyView = w.findChild<studio::HistoryView*>();
        QVERIFY(historyView);
        const auto hasStop = [&] {
            const studio::HistoryModel& m = *historyView->model();
            for (int r = 0; r < m.rowCount(); ++r)
                if (m.record(r).source == db::MessageSource::Positioner && m.record(r).code() == "9")
                    return true;
            return false;
        };
        QTRY_VERIFY(hasStop());
        if (language != first) {
            QVERIFY(studio::setLanguage(language));
            QApplication::processEvents(); // LanguageChange reaches every widget
        }
        Walker walker;
        walker.language = language;
        walker.exemptWords = manualWords(language);
        walker.setData(panelTexts() +
                       machineTexts(w.session()->simulation().profile(), w.session()->controller().programs()) +
                       positionerTexts() + studio::machineNames() + courseTexts() +
                       QStringList{QFileInfo(file_).fileName(), QFileInfo(warnFile_).fileName(),
                                   studio::EditorTab::sampleFor("training-lathe"), // the first start's sample
                                   QString::fromStdString(db::defaultAuthor()), // the revisions' author: the OS user
                                   QStringLiteral("no-such-machine")} +          // the name File > Machine was asked for
                       pluginNames());                                        // the link plugins' own names
        walkWindow(walker, w);
        walkDialogs(walker, w);
        qInfo("%d texts checked in --lang %s (started in %s)", walker.checked, qPrintable(language), qPrintable(first));
        for (const QString& l : walker.leaks)
            qWarning("%s", qPrintable(l));
        // Closed as the user closes it (the layouts kept for the next window).
        w.programEditor()->setCloseQuestion([](const QString&) { return studio::EditorTab::CloseChoice::Discard; });
        w.close();
        QVERIFY(walker.checked > 1000);
        QVERIFY2(walker.leaks.isEmpty(),
                 qPrintable(QStringLiteral("%1 texts of another language in --lang %2 (listed above)")
                                .arg(walker.leaks.size())
                                .arg(language)));
    }
};

namespace {

// A line on which nothing answers.
class SilentLine final : public link::RegisterTransport {
public:
    link::Reply read(int, int, std::vector<std::uint16_t>&) override { return link::Reply::lost(); }
    link::Reply write(int, std::span<const std::uint16_t>) override { return link::Reply::lost(); }
    link::Reply writeRead(int, std::span<const std::uint16_t>, int, int, std::vector<std::uint16_t>&) override {
        return link::Reply::lost();
    }
    link::Reply echo(std::uint16_t) override { return link::Reply::lost(); }
};

} // namespace

void TestUiLanguage::russianErrors() {
    QVERIFY(studio::setLanguage("ru"));
    Walker walker;
    walker.language = "ru";
    walker.exemptWords = manualWords("ru");
    // SQLite's own words, quoted as said (it has no Russian).
    const QStringList sqliteSaid = {QStringLiteral("file is not a database"),
                                    QStringLiteral("database disk image is malformed"), QStringLiteral("disk I/O error")};
    const QString pgLocation = QStringLiteral("postgresql://127.0.0.1:1/k528");
    const QString badFile = dir_.filePath("bad.k528"), emptyFile = dir_.filePath("empty.k528");
    // The K923's keys by their printed legends (ENTER), the manual's panel.
    walker.setData(panelTexts() + positionerTexts() + sqliteSaid + QStringList{pgLocation, QStringLiteral("%MESSAGES"), badFile, emptyFile});
    // Core's Russian, and the window's: the same words from the same id.
    const auto ru = [](const link::LinkError& e) {
        const QString core = QString::fromStdString(e.text(true));
        if (studio::linkErrorText(e) != core)
            qWarning("the window says «%s», core «%s»", qPrintable(studio::linkErrorText(e)), qPrintable(core));
        return studio::linkErrorText(e);
    };

    // Core's link errors in Russian, as the Controller dock and the views say them.
    {
        SilentLine line;
        link::Link l(line, link::k528Map(), 1);
        link::LiveState live;
        walker.check("link: no answer", ru(link::identify(l, live)));
        walker.check("link: R read only", ru(link::setRParameter(l, 158, 1)));
        walker.check("link: R outside 32 bits", ru(link::setRParameter(l, 5, 1LL << 40)));
        walker.check("link: C without an address", ru(link::setConstant(l, 0, 1)));
        link::PushPlan plan;
        walker.check("link: a file with an error", ru(link::planProgramFile(l, "%L1\nN1 G999\n", badFile.toStdString(), plan)));
        walker.check("link: a file without programs", ru(link::planProgramFile(l, "; nothing\n", emptyFile.toStdString(), plan)));
        for (int code : {1, 2, 3, 6, 9})
            walker.check(QStringLiteral("link: exception %1").arg(code), studio::linkText(link::exceptionSaid(code)));
        for (int status : {0, 1, 2, 16, 17, 18, 19, 20, 33})
            walker.check(QStringLiteral("link: status %1").arg(status), studio::linkText(link::statusSaid(status)));
        for (int mode : {0, 2, 7}) {
            link::LiveState m;
            m.mode = mode;
            walker.check(QStringLiteral("link: not ready in F%1").arg(mode),
                         studio::linkText(link::notReadySaid(m, link::say("link.action-push"))));
        }
        link::PushReport report;
        report.parts = {{"C-parameters", link::PushReport::State::New, link::say("link.part-c")},
                        {"program 5", link::PushReport::State::InDoubt, link::say("link.part-program", {"5"})},
                        {"messages", link::PushReport::State::AsItWas, link::say("link.part-messages")}};
        walker.check("link: a push's parts", studio::linkText(report.summary()));
        QCOMPARE(studio::linkText(report.summary()), QString::fromStdString(link::render(report.summary(), true)));
        // A line's failure (a plugin's, mapped from Qt's error code) in the window's words.
        walker.check("link: connection refused",
                     studio::lineErrorText(QString::fromStdString(link::lineError("line.refused"))));
        QCOMPARE(studio::lineErrorText(QString::fromStdString(link::lineError("line.connect-timeout", {"1000"}))),
                 QStringLiteral("нет соединения за 1000 мс"));
    }
    // Every text of the link's catalog: the window's Russian is core's.
    checkCatalog(link::linkTexts(), studio::hasLinkText, [](std::string_view id) {
        const link::Said s = link::say(id, {"R7", "5", "6000..6031", "L"});
        return std::pair(studio::linkText(s), link::render(s, true));
    }, &walker, QStringLiteral("link text %1"));
    if (QTest::currentTestFailed())
        return;

    // The push preview: what changes, in the window's words.
    {
        const profile::MachineProfile before = profile::builtin("training-lathe");
        profile::MachineProfile after = before;
        after.c[22] += 1;
        after.programs[77] = "%L77\nN1 G1 X10 FX100\nN2 M30\n";
        if (!after.programs.empty() && after.programs.begin()->first != 77)
            after.programs.erase(after.programs.begin());
        after.r.erase(after.r.begin(), after.r.end());
        after.r[10] = 5;
        const QString text = studio::diffText(profile::diff(before, after));
        QVERIFY(!text.isEmpty());
        Walker diff = walker;
        diff.setData(positionerTexts() + panelTexts() + machineTexts(after, {}) +
                     machineTexts(before, {}));
        for (const QString& line : text.split('\n'))
            if (!line.startsWith(QLatin1String("    "))) // a program's own lines are its text
                diff.check("push preview", line);
        walker.leaks << diff.leaks;
        QDialog* d = studio::showPushPreview(nullptr, QStringLiteral("L77"), before, after, QStringLiteral("Передать"),
                                             [](bool) {});
        Walker dialog = diff;
        dialog.leaks.clear();
        dialog.cells = false;
        dialog.walkWidget(d);
        walker.leaks << dialog.leaks;
        d->close();
    }

    // The database dialog: a server that refuses, a file that is not a database.
    {
        studio::DatabaseDialog d;
        d.setLocation(pgLocation);
        d.accept();
        const QString pg = d.error();
        QVERIFY2(pg.contains(QStringLiteral("Подробности")), qPrintable(pg));
        // libpq's own words in Russian (its gettext catalogue, libpq5-15.mo).
        QVERIFY2(pg.contains(QStringLiteral("не удалось")), qPrintable(pg));
        qInfo("%s", qPrintable(pg));
        walker.check("File > Database: a server that refuses", pg);
        QFile junk(dir_.filePath("junk.db"));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        // SQLite's header, then nothing SQLite can read: SQLite's own words.
        junk.write(QByteArray("SQLite format 3", 16) + QByteArray(4080, 'x'));
        junk.close();
        d.setLocation(junk.fileName());
        d.accept();
        const QString sq = d.error();
        QVERIFY2(sq.contains(junk.fileName()), qPrintable(sq));
        qInfo("%s", qPrintable(sq));
        walker.check("File > Database: not a database", sq);
        walker.check("a database error of the window", studio::databaseErrorText(
                                                             db::Error(db::ErrorKind::Io, "cannot open x: disk I/O error",
                                                                       "disk I/O error")));
        d.reject();
    }
    // The database's own errors: its catalog's sentence, in Russian (the
    // same as `k528 db … --lang ru`).
    {
        const QString file = dir_.filePath("errors.db");
        db::OpenOptions o;
        o.create = true;
        db::Database d = db::Database::open(db::Location(file.toStdString()), o);
        try {
            (void)d.loadMachine("no-such-machine");
            QFAIL("loaded a machine the database lacks");
        } catch (const db::Error& e) {
            const QString text = studio::databaseErrorText(e);
            QCOMPARE(text, QString::fromStdString(e.text(db::Lang::Ru)));
            QVERIFY2(text.startsWith(QStringLiteral("нет станка «no-such-machine» в ")), qPrintable(text));
        }
        try {
            (void)d.loadMachine("training-lathe", 99);
            QFAIL("loaded a revision the machine lacks");
        } catch (const db::Error& e) {
            QCOMPARE(studio::databaseErrorText(e), QStringLiteral("у станка training-lathe ревизии 1..1; ревизии 99 нет"));
        }
    }

    // Controller > Connect on a port that does not exist, then on one where
    // nothing answers (a pseudo-terminal whose other end is silent).
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<studio::ControllerDock*>();
        QVERIFY(dock);
        auto* port = w.findChild<QComboBox*>("controller.port");
        QVERIFY(port && port->isEditable());
        const auto tryPort = [&](const QString& path, int ms) {
            port->setEditText(path);
            const QString before = dock->lastMessage();
            dock->connectLine();
            QTRY_VERIFY_WITH_TIMEOUT(dock->lastMessage() != before &&
                                         !dock->lastMessage().isEmpty(),
                                     ms);
            qInfo("%s", qPrintable(dock->lastMessage()));
            walker.check(QStringLiteral("Controller > Connect to %1").arg(path), dock->lastMessage());
        };
        tryPort(dir_.filePath("no-such-port"), 10000);
        const int master = posix_openpt(O_RDWR | O_NOCTTY);
        if (master >= 0 && grantpt(master) == 0 && unlockpt(master) == 0) {
            tryPort(QString::fromLocal8Bit(ptsname(master)), 60000);
            dock->disconnectLine();
            ::close(master);
        }
        w.close();
    }

    for (const QString& l : std::as_const(walker.leaks))
        qWarning("%s", qPrintable(l));
    QVERIFY2(walker.leaks.isEmpty(),
             qPrintable(QStringLiteral("%1 texts of another language in --lang ru (listed above)").arg(walker.leaks.size())));
    QVERIFY(studio::setLanguage("en"));
}

namespace {

// The machine file's and the CSV's own words (section headers, keys, the
// kinds a value may name): syntax, written as the file must have it.
QStringList fileSyntax() {
    return {"[machine]", "[c]", "[r]", "[messages]", "[plc-messages]", "[simulation]", "[program N]",
            "[end program]", "format=", "name=", "#k", "machine, c, r, program N, messages, plc-messages, simulation",
            "format, name, title", "UTF-8", "U+FEFF", "a-z", "LF", "true/false", "cat", "%MESSAGES",
            "turning, facing, grooving, boring, drill, threading", "+z+x, -z+x, +z-x, -z-x",
            "tool.<позиция 1..8>.<ключ>", "tool.%1.kind", "tool.1.kind", "tool.1.width_mm", "x.kv",
            "training-lathe", "grinder-205", "number;axis;name;value;unit",
            // a line= value (profile/line.h) and an MQTT broker's address, as typed
            // (also as the walker reads it, '&' being a mnemonic's mark)
            "tcp://ХОСТ:ПОРТ/УСТРОЙСТВО", "serial:УСТРОЙСТВО?baud=115200&parity=none&address=1",
            "serial:УСТРОЙСТВО?baud=115200parity=noneaddress=1", "tcp://", "serial:",
            "baud, parity, stop_bits, address", "baud", "parity", "none", "even", "odd", "stop_bits", "address",
            "mqtt://ХОСТ[:ПОРТ]", "mqtt://",
            // the kinds of file a name may be and a protocol it is not
            "FIFO", "TLS"};
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const std::string& text) {
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text.data(), static_cast<qint64>(text.size()));
    return f.fileName();
}

} // namespace

void TestUiLanguage::russianCoreTexts() {
    QVERIFY(studio::setLanguage("ru"));
    Walker walker;
    walker.language = "ru";
    walker.exemptWords = manualWords("ru");
    // Keys of the machine file that its syntax glues to other text
    // ("format:", "tool.3.kind"): names, as the file must have them.
    walker.exemptWords += QSet<QString>{QStringLiteral("format"), QStringLiteral("tool"), QStringLiteral("kind"),
                                        QStringLiteral("offset_r")};
    const std::string good = profile::builtinText("training-lathe").data();
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const std::size_t at = t.find(from);
        return at == std::string::npos ? std::string() : t.replace(at, from.size(), to);
    };
    const std::size_t c22 = good.find("\nC022=");
    QVERIFY(c22 != std::string::npos);
    const std::string c22Line = good.substr(c22 + 1, good.find('\n', c22 + 1) - c22 - 1);
    const QString outOfRange = writeFile(dir_, "range.k528m", replaced(c22Line, "C022=999999999"));
    const QString notWhole = writeFile(dir_, "whole.k528m", replaced(c22Line, "C022=1.5"));
    const QString badCsv = writeFile(dir_, "bad.csv", "number;axis;name;value;unit\n999;X;x;1;\n");
    const QString noFile = dir_.filePath("absent.k528m");
    QVERIFY(!outOfRange.isEmpty() && !notWhole.isEmpty() && !badCsv.isEmpty());
    walker.setData(panelTexts() + positionerTexts() + fileSyntax() +
                   QStringList{outOfRange, notWhole, badCsv, noFile, dir_.path(), QStringLiteral("no-such-machine"),
                               QStringLiteral("range.k528m"), QStringLiteral("whole.k528m"),
                               QStringLiteral("bad.csv"), QStringLiteral("absent.k528m"),
                               QString::fromStdString(db::defaultAuthor()), // the revisions' author
                               QStringLiteral("training-lathe"), QStringLiteral("Tilte")});

    // Every id of core's catalogs has a text of the window, in Russian.
    const std::vector<std::string> someArgs = {"C022", "12", "34", "L3"};
    checkCatalog(profile::problemTexts(), studio::hasProblemText, [&](std::string_view id) {
        const profile::Problem p = profile::problem(std::string(id), someArgs);
        return std::pair(studio::problemText(p), profile::problemText(p, true));
    }, &walker, QStringLiteral("core problem %1"));
    if (QTest::currentTestFailed())
        return;
    // A file that cannot be read or written, the system's reason, an MQTT
    // broker's address (util/system_texts.h): the same Russian as core's
    // catalog (what `k528 --lang ru` prints).
    checkCatalog(util::systemTexts(), studio::hasSystemText, [&](std::string_view id) {
        const util::Message m = util::message(std::string(id), {"/dev/full", "12"});
        return std::pair(studio::systemText(m), util::systemText(m, true));
    }, &walker, QStringLiteral("system text %1"));
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(studio::systemText(util::message("io.cannot-write", {"/dev/full"}, {util::systemError(ENOSPC)})),
             QStringLiteral("не удаётся записать /dev/full: на устройстве не осталось места"));
    // A line= value of the machine's settings (the controller dialog, the
    // database's refusal of a revision): core's line.* problems in Russian.
    QCOMPARE(studio::problemText(profile::lineProblem("tcp://10.0.0.5:0/1")),
             QStringLiteral("линия «tcp://10.0.0.5:0/1»: порт после хоста — 1..65535"));
    walker.check("a line= value", studio::problemText(profile::lineProblem("serial:/dev/ttyS0?baud=1")));
    // A machine file that is a device: the file's problem with the system's reason.
    try {
        profile::readMachineFile("/dev/zero");
        QFAIL("/dev/zero read as a machine file");
    } catch (const std::exception& e) {
        QCOMPARE(studio::coreErrorText(e), QStringLiteral("/dev/zero: файл нельзя прочитать: это символьное устройство, а не "
                                                          "обычный файл (k528 читает только файлы программ и станков)"));
    }
    {
        std::string text;
        QString error;
        QVERIFY(!studio::readTextFile(dir_.filePath("absent.k528m"), text, error));
        QCOMPARE(error, dir_.filePath("absent.k528m") + QStringLiteral(" не читается: нет такого файла или папки"));
    }
    for (const db::NoteText& t : db::noteTexts()) {
        QVERIFY2(studio::hasNoteText(t.id), t.id.data());
        // As stored (English), read back and said in the window's language.
        const db::Note n = t.id == "trial" ? db::Note{"trial", {"2", "X", "40.060", "40.000", "100", "0", "-30"}}
                           : db::Note{std::string(t.id), {t.id == "changed-more" ? "C022, R12" : "C022", "3"}};
        const std::string stored = db::noteText(n);
        const std::optional<db::Note> back = db::readNote(stored);
        QVERIFY2(back && back->id == t.id, stored.c_str());
        walker.check(QStringLiteral("revision note %1").arg(fromView(t.id)), studio::revisionNoteText(stored));
    }
    // A user's own note is shown as written, even one that begins as ours.
    QCOMPARE(studio::revisionNoteText("set the feed lower"), QStringLiteral("set the feed lower"));
    // The constants dock's own notes, and its undo of one, stored in English
    // and said in the reader's language (the note undone too).
    {
        const std::string set = db::noteText({"studio.set", {"C022", "5"}});
        const std::string undo = db::noteText({"studio.undo", {set}});
        QCOMPARE(QString::fromStdString(undo), QStringLiteral("undo: set C022 = 5 (K528 Studio)"));
        QCOMPARE(studio::revisionNoteText(undo), QStringLiteral("отмена: задано: C022 = 5 (K528 Studio)"));
    }

    // Every prove-out finding in the window's language: the same Russian as
    // core's catalog (what `k528 check --lang ru` prints).
    for (const proveout::Text& t : proveout::texts()) {
        QVERIFY2(studio::hasFindingText(t.id), t.id.data());
        proveout::Finding f;
        f.text = t.id;
        f.args = {"40", "-2", "1"};
        QCOMPARE(studio::findingText(f), QString::fromStdString(f.message(true)));
        walker.check(QStringLiteral("prove-out finding %1").arg(fromView(t.id)), studio::findingText(f));
    }

    // Every text of a machine description's errors: the same Russian as
    // core's catalog (what `k528 run --lang ru` prints).
    checkCatalog(plc::descriptionTexts(), studio::hasDescriptionText, [](std::string_view id) {
        const profile::Problem p = profile::problem(std::string(id), {"x1", "12", "34"});
        return std::pair(studio::descriptionProblemText(p), plc::descriptionText(p, true));
    });
    // Every text of a program's diagnostics: the same Russian as core's
    // catalog (what `k528 check --lang ru` prints), a text inside another
    // one too; every rule's short name in Russian (the Problems list).
    checkCatalog(program::diagnosticTexts(), studio::hasDiagnosticText, [](std::string_view id) {
        program::Diagnostic d;
        d.textId = std::string(id);
        d.args = {"X", "12", "34", "56"};
        d.within = {{"frame.numbered", {"5"}, {}}, {"chain.call", {"1"}, {{"chain.end", {"2"}, {}}}}};
        return std::pair(studio::diagnosticText(d), program::diagnosticText(d, true));
    });
    // Every text of a training grade, an argument of two languages in Russian.
    checkCatalog(
        catalog::trainingTexts(), [](std::string_view id) { return !studio::trainingTextPattern(std::string(id)).isEmpty(); },
        [](std::string_view id) {
            const training::Text t{std::string(id), {"12", training::TextArg("Нет смазки", "No lube"), "34", "L1 N5", "7"}};
            return std::pair(studio::trainingText(t), training::render(t, training::Language::Ru));
        });
    if (QTest::currentTestFailed())
        return;
    for (int r = 0; r <= static_cast<int>(program::Rule::DiscreteRounding); ++r) {
        const auto rule = static_cast<program::Rule>(r);
        QVERIFY2(studio::ruleName(rule) != QString::fromStdString(std::string(program::ruleId(rule))),
                 program::ruleId(rule).data());
        walker.check(QStringLiteral("rule %1").arg(fromView(program::ruleId(rule))), studio::ruleName(rule));
    }
    for (const proveout::Rule rule : proveout::allRules()) {
        QVERIFY2(studio::ruleName(rule) != QString::fromStdString(std::string(proveout::ruleId(rule))),
                 proveout::ruleId(rule).data());
        walker.check(QStringLiteral("prove-out rule %1").arg(fromView(proveout::ruleId(rule))), studio::ruleName(rule));
    }
    // Broken hand-made machine descriptions, as the controller and File >
    // Machine say them.
    {
        const QString syntax = writeFile(dir_, "syntax.json", "{\"format\": 1,\n");
        const QString badName = writeFile(
            dir_, "name.json", R"({"format": 1, "name": "b", "inputs": [{"name": "1x", "signal": "door.closed"}]})");
        const QString notString = writeFile(dir_, "type.json", R"({"format": 1, "name": 5})");
        const QString badWhen = writeFile(dir_, "when.json",
                                          R"({"format": 1, "name": "b", "alarms": [{"k": 1, "when": "nosuch"}]})");
        walker.setData(panelTexts() + positionerTexts() + fileSyntax() +
                       QStringList{outOfRange, notWhole, badCsv, noFile, dir_.path(), QStringLiteral("no-such-machine"),
                                   QStringLiteral("range.k528m"), QStringLiteral("whole.k528m"),
                                   QStringLiteral("bad.csv"), QStringLiteral("absent.k528m"),
                                   QString::fromStdString(db::defaultAuthor()), QStringLiteral("training-lathe"),
                                   QStringLiteral("Tilte"), syntax, badName, notString, badWhen,
                                   QStringLiteral("1x"), QStringLiteral("nosuch"),
                                   QStringLiteral("inputs[0].name"), QStringLiteral("alarms[0].when"), QStringLiteral("name"),
                                   QStringLiteral("broken.k528m")});
        const std::vector<std::pair<QString, QString>> cases = {
            {syntax, QStringLiteral("ошибка синтаксиса JSON: строка 2, столбец 1")},
            {badName, QStringLiteral("inputs[0].name: «1x» — недопустимое имя")},
            {notString, QStringLiteral("name: ожидается строка, а здесь число")},
            {badWhen, QStringLiteral("alarms[0].when: столбец 1: неизвестный сигнал «nosuch» в \"nosuch\"")},
        };
        for (const auto& [file, want] : cases) {
            profile::MachineProfile lathe = profile::builtin("training-lathe");
            lathe.simulation.set("machine", file.toStdString());
            try {
                studio::SimulationSession session(lathe);
                QFAIL(qPrintable(file + ": loaded"));
            } catch (const std::exception& e) {
                const QString text = studio::coreErrorText(e);
                qInfo("%s", qPrintable(text));
                QVERIFY2(text.contains(want), qPrintable(text));
                walker.check(QStringLiteral("a broken machine description"), text);
            }
        }
        // File > Machine with a machine file whose simulation uses the last one.
        const std::string withDescription = replaced("\nmachine=training-lathe\n", "\nmachine=" + badWhen.toStdString() + "\n");
        QVERIFY(!withDescription.empty());
        const QString broken = writeFile(dir_, "broken.k528m", withDescription);
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        walkOpened(walker, "File > Machine: a broken machine description", [&] { w.switchMachine(broken); });
        w.close();
    }

    // A refusal of its kind only: each kind is a text of core's catalog,
    // said as core says it.
    for (int r = 1; r <= static_cast<int>(engine::Refusal::NotPowered); ++r) {
        const auto refusal = static_cast<engine::Refusal>(r);
        QVERIFY2(engine::refusalTexts().find(engine::refusalKindId(refusal)), qPrintable(QString::number(r)));
        QCOMPARE(studio::refusalText(refusal),
                 QString::fromStdString(engine::refusalTexts().render(engine::refusalKindId(refusal), {}, true)));
    }
    // The database's texts: the same Russian as core's catalog (`k528 db … --lang ru`).
    checkCatalog(db::dbTexts(), studio::hasDatabaseText, [](std::string_view id) {
        const std::vector<std::string> args = {"lathe", "12", "34", "L3", "5", "6"};
        return std::pair(studio::databaseText(id, args), db::dbText(id, args, true));
    });
    // Why, with the value and the limit: the same Russian as core's catalog.
    checkCatalog(engine::refusalTexts(), studio::hasRefusalText, [](std::string_view id) {
        const engine::OpResult r = engine::OpResult::refused(engine::Refusal::WrongMode, std::string(id), {"C022", "9", "10...5000", "X"});
        return std::pair(studio::refusalText(r), r.text(true));
    }, &walker, QStringLiteral("refusal %1"));
    // Why a refactoring changed nothing (what `k528 format --renumber --lang ru` prints).
    checkCatalog(program::refactorTexts(), studio::hasRefactorText, [](std::string_view id) {
        program::RefactorResult r;
        r.ok = false;
        r.textId = std::string(id);
        r.args = {"7"};
        return std::pair(studio::refactorText(r), r.text(true));
    }, &walker, QStringLiteral("refactoring %1"));
    // What a completion of the editor means (its popup), a meaning of table 5
    // in the window's language (what core's catalog says in Russian).
    checkCatalog(editing::completionTexts(), studio::hasCompletionText, [](std::string_view id) {
        editing::CompletionItem item;
        item.detailId = std::string(id);
        item.detailArgs = {{"подача", "feed"}, {"X", "X"}};
        return std::pair(studio::completionDetail(item), item.detail(true));
    }, &walker, QStringLiteral("completion %1"));
    if (QTest::currentTestFailed())
        return;
    // The simulated controller refuses in the window's language, naming the
    // value and the limit.
    {
        studio::SimulationSession session(profile::builtin("training-lathe"));
        studio::SimulatedController sim(session);
        QString why;
        sim.setR(300, 1, [&](bool ok, const QString& w) { QVERIFY(!ok); why = w; });
        QCOMPARE(why, QStringLiteral("R-параметры — R0..R299, а не R300"));
        sim.setC(29, 5000, [&](bool ok, const QString& w) { QVERIFY(!ok); why = w; });
        QVERIFY2(why.contains(QStringLiteral("вне диапазона 0...2047")), qPrintable(why));
        walker.check("the simulated controller's refusal", why);
    }

    // The constants calculator's refusals.
    {
        const units::AxisScale scale = profile::axisScale(profile::builtin("training-lathe"), catalog::Axis::X);
        for (const auto& calc : std::vector<std::function<void()>>{
                 [&] { profile::calc::accelByValue(0, scale); },
                 [&] { profile::calc::encoderRatio(5.0004, 1, 2500, scale); },
                 [&] { profile::calc::speedParam(-1, scale); }}) {
            try {
                calc();
                QFAIL("the calculator took a bad input");
            } catch (const std::exception& e) {
                walker.check("the constants calculator", studio::coreErrorText(e));
            }
        }
    }

    // A database's refusal of an edit the machine cannot hold (no findings).
    {
        db::OpenOptions o;
        db::Database d = db::Database::open(std::filesystem::path(dir_.filePath("refusal.db").toStdString()), o);
        db::Edit e;
        e.simulation["Tilte"] = "oops";
        try {
            d.applyEdit("training-lathe", e);
            QFAIL("a bad simulation key was kept");
        } catch (const db::ValidationError& v) {
            QVERIFY(v.findings().empty());
            const QString text = studio::coreErrorText(v);
            qInfo("db set refused: %s", qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral("ничего не записано")), qPrintable(text));
            walker.check("a database's refusal without findings", text);
        }
    }

    // A machine that cannot be loaded, as File > Machine and the controller say it.
    const auto loadError = [&](const QString& what, const QString& nameOrPath) {
        try {
            profile::load(nameOrPath.toStdString());
            QFAIL(qPrintable(what + ": loaded"));
        } catch (const std::exception& e) {
            const QString text = studio::coreErrorText(e);
            qInfo("%s: %s", qPrintable(what), qPrintable(text));
            walker.check(what, text);
        }
    };
    loadError("an unknown machine", QStringLiteral("no-such-machine"));
    loadError("a machine file that is not there", noFile);
    loadError("a value out of range", outOfRange);
    loadError("a value that is not whole", notWhole);
    try {
        profile::readCParamsCsv(std::string("number;axis;name;value;unit\n999;X;x;1;\n"), "bad.csv");
        QFAIL("a bad CSV read");
    } catch (const std::exception& e) {
        walker.check("a bad constants CSV", studio::coreErrorText(e));
    }

    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // File > Machine with a bad machine file: the message box.
        walkOpened(walker, "File > Machine: a value out of range", [&] { w.switchMachine(outOfRange); });
        // The constants dock's import of a bad file and of one that is not there.
        auto* pane = w.findChild<studio::ConstantsPane*>();
        QVERIFY(pane);
        int done = 0;
        connect(pane, &studio::ConstantsPane::finished, this, [&done] { ++done; });
        for (const QString& f : {notWhole, badCsv, noFile, dir_.path()}) {
            const int before = done;
            pane->importFile(f);
            QTRY_VERIFY_WITH_TIMEOUT(done > before, 10000);
            qInfo("import %s: %s", qPrintable(f), qPrintable(pane->statusText()));
            walker.check(QStringLiteral("constants: import %1").arg(f), pane->statusText());
        }
        // Its revision history: the first start's note.
        pane->selectConstant(22);
        walkOpened(walker, "constants: the history", [&] { clickNamed(w, "constants.history"); });
        w.close();
    }

    // The prove-out pane: a blank that is not one, a machine with a bad tool.
    {
        profile::MachineProfile lathe = profile::builtin("training-lathe");
        studio::SimulationSession session(lathe);
        studio::SimulatedController sim(session);
        studio::ViewedController seam(sim);
        studio::EditorTab tab(&seam);
        studio::ProveoutPane pane(&tab);
        tab.newFile();
        tab.currentEditor()->setText(QStringLiteral("%L1 (FACE)\nN1 G90 G0 M3 X44 Z2\nN2 G1 X-1 FX150\nN3 M30\n"));
        tab.currentEditor()->validateNow();
        for (const char* ucg : {"UCG,2,Z-80", "UCG,2,Z-80Z0,X40X0,S0S0,7", "UCG,2,Z-80Z0,X40X60,S0S0"}) {
            pane.blankEdit()->setText(QString::fromLatin1(ucg));
            pane.proveNow();
            qInfo("%s: %s", ucg, qPrintable(pane.summary()->text()));
            walker.check(QStringLiteral("prove-out: the blank %1").arg(QString::fromLatin1(ucg)), pane.summary()->text());
        }
        pane.blankEdit()->clear();
        lathe.simulation.set("tool.1.width_mm", "0");
        try {
            profile::tools(lathe);
            QFAIL("a tool 0 mm wide");
        } catch (const profile::ToolError& e) {
            walker.check("prove-out: a tool 0 mm wide", studio::problemText(e.problem()));
        }
    }

    for (const QString& l : std::as_const(walker.leaks))
        qWarning("%s", qPrintable(l));
    QVERIFY2(walker.leaks.isEmpty(),
             qPrintable(QStringLiteral("%1 texts of another language in --lang ru (listed above)").arg(walker.leaks.size())));
    QVERIFY(studio::setLanguage("en"));
}

void TestUiLanguage::russianBlankAndFaultTexts() {
    QVERIFY(studio::setLanguage("ru"));
    checkCatalog(stock::ucgTexts(), studio::hasUcgText, [](std::string_view id) {
        return std::pair(studio::ucgErrorText(id), stock::ucgErrorText(id, {}, true));
    });
    checkCatalog(machine::faultTexts(), studio::hasFaultText, [](std::string_view id) {
        const machine::FaultText t{std::string(id), {"X", "2"}};
        return std::pair(studio::faultTitle(t), machine::faultTextIn(t, true));
    });
    // A shipped machine's equipment by its Russian name, in both.
    const machine::FaultText pump{"pump_overload", {"coolant"}, true};
    QCOMPARE(studio::faultTitle(pump), QStringLiteral("Перегрузка двигателя: насос СОЖ"));
    QCOMPARE(studio::faultTitle(pump), QString::fromStdString(machine::faultTextIn(pump, true)));
    QVERIFY(studio::setLanguage("en"));
}

void TestUiLanguage::catalogTextsAsCore() {
    const auto view = [](std::string_view v) { return QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size())); };
    const std::vector<engine::Mode> modes = {engine::Mode::Auto,        engine::Mode::Manual,      engine::Mode::Reference,
                                             engine::Mode::SetActual,   engine::Mode::MachineData, engine::Mode::ProgramEdit,
                                             engine::Mode::DataControl};
    const std::vector<profile::ToolKind> kinds = {profile::ToolKind::Turning, profile::ToolKind::Facing,
                                                  profile::ToolKind::Grooving, profile::ToolKind::Boring,
                                                  profile::ToolKind::Drill, profile::ToolKind::Threading};
    for (const bool russian : {true, false}) {
        QVERIFY(studio::setLanguage(russian ? "ru" : "en"));
        for (const catalog::PositionerMessage& m : catalog::positionerMessages()) {
            QCOMPARE(studio::positionerMessageText(m.number), view(russian ? m.textRu : m.textEn));
            engine::AlarmView a;
            a.number = m.number;
            // The line's form is the panel's (table М.1: «37. Ошибка N ДОС», «39.Ошибка N маховика»).
            QCOMPARE(studio::alarmLine(a), russian ? QString::fromStdString(m.panelText())
                                                   : QStringLiteral("%1. %2").arg(m.number).arg(view(m.textEn)));
        }
        QVERIFY(studio::positionerMessageText(catalog::kPositionerMessageCount + 1).isEmpty());
        engine::AlarmView outside; // a number the catalog lacks: what the alarm carries
        outside.number = catalog::kPositionerMessageCount + 6;
        outside.textRu = outside.textEn = "#70";
        QCOMPARE(studio::alarmLine(outside), QStringLiteral("70. #70"));
        for (const engine::Mode m : modes)
            QCOMPARE(studio::modeName(m), view(russian ? engine::modeNameRu(m) : engine::modeNameEn(m)));
        for (const profile::ToolKind k : kinds)
            QCOMPARE(studio::toolKindText(k), view(proveout::toolKindText(k, russian)));
        for (int g = 1; g <= 9; ++g)
            QCOMPARE(studio::rGroupName(g), view(russian ? catalog::rGroupNameRu(g) : catalog::rGroupNameEn(g)));
        QVERIFY(studio::rGroupName(10).isEmpty());
        // A text core keeps in both languages as data: the window's one.
        QCOMPARE(studio::coreText("ручной", "manual"), russian ? QStringLiteral("ручной") : QStringLiteral("manual"));
    }
    QVERIFY(studio::setLanguage("en"));
}

QTEST_MAIN(TestUiLanguage)

void TestUiLanguage::fileProblemsInTheWindowsLanguage() {
    studio::SimulationSession session(profile::builtin("training-lathe"));
    studio::SimulatedController sim(session);
    studio::ViewedController seam(sim);
    studio::EditorTab tab(&seam);
    tab.newFile();
    tab.currentEditor()->setText(QStringLiteral("%L1\nN1 M30\n"));
    QSignalSpy said(&tab, &studio::EditorTab::statusMessage);
    const QString nowhere = dir_.filePath(QStringLiteral("no-such-folder/part.k528"));
    const QString folder = dir_.path();
    const QString absent = dir_.filePath(QStringLiteral("absent.k528"));
    const auto last = [&] { return said.isEmpty() ? QString() : said.last().at(0).toString(); };
    for (const bool ru : {true, false}) {
        QVERIFY(studio::setLanguage(ru ? QStringLiteral("ru") : QStringLiteral("en")));
        QVERIFY(!tab.saveTo(0, nowhere));
        QCOMPARE(last(), ru ? nowhere + QStringLiteral(" не записывается: нет такого файла или папки")
                            : nowhere + QStringLiteral(" cannot be written: No such file or directory"));
        QVERIFY(!tab.saveTo(0, folder));
        QCOMPARE(last(), ru ? folder + QStringLiteral(" не записывается: это папка; укажите имя файла")
                            : folder + QStringLiteral(" cannot be written: it is a directory; give a file name"));
        QVERIFY(!tab.openFile(absent));
        QCOMPARE(last(), ru ? absent + QStringLiteral(" не читается: нет такого файла или папки")
                            : absent + QStringLiteral(" cannot be read: No such file or directory"));
    }
    // Written where it can be: nothing said against it.
    QVERIFY(tab.saveTo(0, dir_.filePath(QStringLiteral("part.k528"))));
    QVERIFY(QFile::exists(dir_.filePath(QStringLiteral("part.k528"))));
}

#include "test_ui_language.moc"
