// k528studio — the K528 Studio desktop workstation.
#include <QApplication>
#include <QCoreApplication>
#include <QCommandLineParser>
#include <QGuiApplication>
#include <QScreen>
#include <QEvent>
#include <QSocketNotifier>
#include <QTimer>
#include <csignal>
#include <cstdio>
#include <memory>
#include <sys/socket.h>
#include <unistd.h>

#include "backplot/vtk_gl_widget.h"
#include "editor/debug_panel.h"
#include "editor/debug_session.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "session/simulation_session.h"
#include "language.h"
#include "link_plugins.h"
#include "main_window.h"
#include "workspace/workspaces.h"
#include "profile/builtin.h"
#include "database/database_ui.h"
#include "session/core_texts.h"
#include "session/machine_source.h"
#include "util/version.h"

namespace {

int listPlugins() {
    for (const k528::linkplugin::Found& f : k528::linkplugin::discover())
        if (f.plugin)
            std::printf("plugin %s %s: %s (%s)\n", qPrintable(f.name), qPrintable(f.version),
                        qPrintable(f.transport), qPrintable(f.file));
        else
            std::printf("refused %s: %s\n", qPrintable(f.file), qPrintable(f.refused));
    std::printf("searched: %s\n", qPrintable(k528::linkplugin::searchPath().join(", ")));
    return 0;
}

// SIGTERM, SIGINT, SIGHUP (a session's end, a service manager, Ctrl+C in a
// terminal) end the event loop as quitting does, so what the window says
// when it goes is said (the Shop page's MQTT goodbye and its time in each
// state): the handler only writes a byte, the loop reads it.
int quitSignalPipe[2] = {-1, -1};

void onQuitSignal(int) {
    const char c = 1;
    [[maybe_unused]] const auto n = ::write(quitSignalPipe[1], &c, 1);
}

void quitOnSignals(QApplication& app) {
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, quitSignalPipe) != 0)
        return;
    auto* notifier = new QSocketNotifier(quitSignalPipe[0], QSocketNotifier::Read, &app);
    QObject::connect(notifier, &QSocketNotifier::activated, &app, [] {
        char c;
        [[maybe_unused]] const auto n = ::read(quitSignalPipe[0], &c, 1);
        QApplication::exit(0); // the loop ends; no window is asked whether it may close
    });
    struct sigaction sa {};
    sa.sa_handler = onQuitSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (const int sig : {SIGTERM, SIGINT, SIGHUP})
        sigaction(sig, &sa, nullptr);
}

} // namespace

int main(int argc, char** argv) {
    // Set before any application object: the texts --version and --help print.
    QCoreApplication::setOrganizationName("K528Studio");
    QCoreApplication::setApplicationName("k528studio");
    QCoreApplication::setApplicationVersion(QString::fromLatin1(k528::version_string));

    QCommandLineParser cli;
    cli.setApplicationDescription("K528 Studio: workstation for the Konstar K528-05 controller.");
    cli.addHelpOption();
    cli.addVersionOption();
    QCommandLineOption langOption("lang", "User interface language: ru or en.", "ru|en");
    QCommandLineOption shotOption("screenshot", "Save a PNG of the main window after start-up and exit.",
                                  "file.png");
    QCommandLineOption delayOption("screenshot-delay", "Milliseconds to run before the screenshot (default 800).",
                                   "ms", "800");
    QCommandLineOption profileOption(
        "profile",
        "Machine to simulate: a machine of the database, a built-in profile (training-lathe, "
        "grinder-205) or a machine file (default: the last one chosen, else training-lathe).",
        "name|path");
    QCommandLineOption workspaceOption(
        "workspace", "Workspace to start in: operator, technologist, training or shop (default: the one left last time).",
        "name");
    QCommandLineOption firstFrameOption(
        "first-frame", "Print 'k528studio: first frame' once the main window's first frame is painted, then quit "
                       "(bench/studio_startup measures the start with it).");
    QCommandLineOption pluginsOption("list-plugins",
                                     "List the controller-link plugins found (the Controller menu's) and exit.");
    QCommandLineOption runOption("run",
                                 "Open a program file in the editor and run its first program on the "
                                 "simulated machine, as the debugger's Run does (drives on, homing, "
                                 "AUTOMATIC, Start).",
                                 "file.k528");
    QCommandLineOption dbOption("db",
                                "The database: a file, sqlite:PATH or postgresql://HOST/NAME (default: $K528_DB, "
                                "else the one chosen last in File > Database..., else the user's file).",
                                "location");
    cli.addOptions({langOption, profileOption, workspaceOption, shotOption, delayOption, firstFrameOption, pluginsOption,
                    runOption, dbOption});
    // --help, --version and --list-plugins only print: they are answered with
    // a QCoreApplication, before QApplication opens a display, so that they
    // work where there is none (a build server, ssh, a package check).
    // Anything else — a parse error too, since QApplication first takes its
    // own options (-platform, -display) out of argv — goes on to QApplication.
    {
        QStringList raw;
        for (int i = 0; i < argc; ++i)
            raw << QString::fromLocal8Bit(argv[i]);
        if (cli.parse(raw) && (cli.isSet("help") || cli.isSet("help-all") || cli.isSet("version") ||
                               cli.isSet(pluginsOption))) {
            QCoreApplication core(argc, argv);
            cli.process(core); // prints help or the version and exits
            return listPlugins();
        }
    }

    k528::studio::backplot::VtkGlWidget::setDefaultSurfaceFormat(); // before QApplication (VTK)
    QApplication app(argc, argv);
    QApplication::setApplicationDisplayName("K528 Studio");
    cli.process(app);
    quitOnSignals(app);
    if (cli.isSet(pluginsOption))
        return listPlugins();

    const QString lang = cli.isSet(langOption) ? cli.value(langOption) : k528::studio::savedOrSystemLanguage();
    if (!k528::studio::setLanguage(lang)) {
        std::fprintf(stderr, "k528studio: unknown language '%s' (use ru or en)\n", qPrintable(lang));
        return 2;
    }

    QString databaseWarning;
    try {
        k528::studio::chooseStartDatabase(cli.value(dbOption), &databaseWarning);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "k528studio: --db: %s\n", e.what());
        return 2;
    }
    if (!databaseWarning.isEmpty())
        std::fprintf(stderr, "k528studio: %s\n", qPrintable(databaseWarning));
    const QString wanted =
        cli.isSet(profileOption) ? cli.value(profileOption) : k528::studio::startMachineName();
    k528::studio::MachineChoice machine;
    try {
        machine = k528::studio::loadMachine(wanted);
    } catch (const std::exception& e) {
        if (cli.isSet(profileOption)) {
            std::fprintf(stderr, "k528studio: %s\n", qPrintable(k528::studio::coreErrorText(e)));
            return 2;
        }
        // The remembered machine is gone (deleted from the database): the default.
        std::fprintf(stderr, "k528studio: %s; starting %s\n", qPrintable(k528::studio::coreErrorText(e)),
                     k528::profile::kDefaultProfile.data());
        machine = k528::studio::loadMachine(QString::fromLatin1(k528::profile::kDefaultProfile.data()));
    }
    auto* window = new k528::studio::MainWindow(machine);
    window->setAttribute(Qt::WA_DeleteOnClose);
    if (cli.isSet(workspaceOption) && !window->workspaces()->activate(cli.value(workspaceOption))) {
        std::fprintf(stderr, "k528studio: unknown workspace '%s' (use operator, technologist, training or shop)\n",
                     qPrintable(cli.value(workspaceOption)));
        return 2;
    }
    window->placeOnScreen();
    if (cli.isSet(firstFrameOption)) {
        // The window's first paint, then its flush to the screen (the same
        // pass of the repaint manager: a zero timer runs after it).
        struct FirstPaint : QObject {
            bool seen = false;
            bool eventFilter(QObject*, QEvent* e) override {
                if (e->type() == QEvent::Paint && !seen) {
                    seen = true;
                    QTimer::singleShot(0, qApp, [] {
                        std::printf("k528studio: first frame\n");
                        std::fflush(stdout);
                        QApplication::exit(0);
                    });
                }
                return false;
            }
        };
        window->installEventFilter(new FirstPaint);
    }
    window->show();

    if (cli.isSet(runOption)) {
        const QString file = cli.value(runOption);
        QTimer::singleShot(0, window, [window, file] {
            k528::studio::EditorTab* editor = window->programEditor();
            k528::studio::DebugPanel* debug = editor->debugPanel();
            if (!editor->openFile(file) || !debug || !debug->run()) {
                std::fprintf(stderr, "k528studio: --run: %s cannot be run (see the status bar)\n",
                             qPrintable(file));
                return;
            }
            // Said once the program is under way (bench/studio_cpu.cpp waits for it).
            k528::studio::DebugSession* session = debug->debugger();
            auto said = std::make_shared<bool>(false);
            QObject::connect(session, &k528::studio::DebugSession::changed, window, [session, said] {
                if (!*said && session->phase() == k528::studio::DebugSession::Phase::Active) {
                    *said = true;
                    std::fprintf(stderr, "k528studio: --run: L%d runs\n",
                                 session->session()->controller().programView().program);
                    std::fflush(stderr);
                }
            });
        });
    }
    if (cli.isSet(shotOption)) {
        const QString file = cli.value(shotOption);
        QTimer::singleShot(cli.value(delayOption).toInt(), &app, [file] {
            // The main window shown now (File > Machine may have replaced it).
            QWidget* shown = nullptr;
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w->isVisible() && qobject_cast<k528::studio::MainWindow*>(w))
                    shown = w;
            // On an X server: what the screen shows (the OpenGL docks as
            // composed there); offscreen: the widgets rendered again.
            QImage image;
            if (shown && QGuiApplication::platformName() == QLatin1String("xcb") && shown->screen())
                image = shown->screen()->grabWindow(shown->winId()).toImage();
            if (shown && image.isNull())
                image = shown->grab().toImage();
            const bool ok = !image.isNull() && image.save(file, "PNG");
            if (!ok)
                std::fprintf(stderr, "k528studio: cannot write %s\n", qPrintable(file));
            QApplication::exit(ok ? 0 : 2);
        });
    }
    return app.exec();
}
