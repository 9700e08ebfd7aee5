// k528-sheet --out FILE.pdf [--lang ru|en]: the renderer of `k528 setup-sheet`
// (app/cli/cmd_setup_sheet.cpp), which feeds it the sheet as JSON on standard
// input (proveout::sheetJson). A helper, not a command; it needs no display
// (the offscreen platform unless QT_QPA_PLATFORM says otherwise).
#include "sheet/sheet_render.h"
#include "util/system_texts.h"

#include <QGuiApplication>

#include <cstdio>
#include <iostream>
#include <iterator>
#include <string>

namespace {

// Qt's notes on stderr, but not that the offscreen platform found no
// XDG_RUNTIME_DIR (a batch job or a container has none): nothing is wrong.
void quietHandler(QtMsgType type, const QMessageLogContext&, const QString& text) {
    if (type == QtDebugMsg || type == QtInfoMsg || text.contains(QLatin1String("XDG_RUNTIME_DIR")))
        return;
    std::fprintf(stderr, "k528-sheet: %s\n", qPrintable(text));
}

} // namespace

int main(int argc, char** argv) {
    qInstallMessageHandler(quietHandler);
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QString out;
    bool russian = true;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--out") && i + 1 < args.size())
            out = args[++i];
        else if (args[i] == QLatin1String("--lang") && i + 1 < args.size())
            russian = args[++i] != QLatin1String("en");
        else {
            std::fprintf(stderr, "k528-sheet: unknown argument %s\n", qPrintable(args[i]));
            return 2;
        }
    }
    if (out.isEmpty()) {
        std::fprintf(stderr, "k528-sheet: --out FILE.pdf needed\n");
        return 2;
    }
    const std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    k528::proveout::SetupSheet sheet;
    try {
        sheet = k528::proveout::sheetFromJson(text);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "k528-sheet: %s\n", e.what());
        return 2;
    }
    const QString error = k528::studio::writeSetupSheetPdf(sheet, russian, out);
    if (!error.isEmpty()) {
        // The reason comes in the command's language: the sentence too.
        const std::string text = k528::util::systemText(
            k528::util::message("io.cannot-write", {out.toStdString(), error.toStdString()}), russian);
        std::fprintf(stderr, "k528: %s\n", text.c_str());
        return 2;
    }
    return 0;
}
