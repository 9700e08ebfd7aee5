// k528studio — the K528 Studio desktop workstation.
#include <QApplication>
#include <QCommandLineParser>
#include <QGuiApplication>
#include <QScreen>
#include <QTimer>
#include <cstdio>

#include "language.h"
#include "main_window.h"
#include "util/version.h"

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("K528Studio");
    QApplication::setApplicationName("k528studio");
    QApplication::setApplicationDisplayName("K528 Studio");
    QApplication::setApplicationVersion(QString::fromLatin1(k528::version_string));

    QCommandLineParser cli;
    cli.setApplicationDescription("K528 Studio: workstation for the Konstar K528-05 controller.");
    cli.addHelpOption();
    cli.addVersionOption();
    QCommandLineOption langOption("lang", "User interface language: ru or en.", "ru|en");
    QCommandLineOption shotOption("screenshot", "Save a PNG of the main window after start-up and exit.",
                                  "file.png");
    QCommandLineOption delayOption("screenshot-delay", "Milliseconds to run before the screenshot (default 800).",
                                   "ms", "800");
    cli.addOptions({langOption, shotOption, delayOption});
    cli.process(app);

    const QString lang = cli.isSet(langOption) ? cli.value(langOption) : k528::studio::savedOrSystemLanguage();
    if (!k528::studio::setLanguage(lang)) {
        std::fprintf(stderr, "k528studio: unknown language '%s' (use ru or en)\n", qPrintable(lang));
        return 2;
    }

    k528::studio::MainWindow window;
    window.show();

    if (cli.isSet(shotOption)) {
        const QString file = cli.value(shotOption);
        QTimer::singleShot(cli.value(delayOption).toInt(), &window, [&window, file] {
            const bool ok = window.grab().save(file, "PNG");
            if (!ok)
                std::fprintf(stderr, "k528studio: cannot write %s\n", qPrintable(file));
            QApplication::exit(ok ? 0 : 2);
        });
    }
    return app.exec();
}
