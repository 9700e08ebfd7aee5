#include "language.h"
#include "window_language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <clocale>
#include <cstdlib>
#include <string>

namespace k528::studio {

namespace {
QTranslator* translator() {
    static QTranslator* t = new QTranslator(QCoreApplication::instance());
    return t;
}
// Qt's own texts (file dialogs, Cancel/Close/Save/Discard): Debian's
// qt6-translations-l10n, qtbase_<lang>.qm in Qt's translations folder.
QTranslator* qtTranslator() {
    static QTranslator* t = new QTranslator(QCoreApplication::instance());
    return t;
}
// Qt Serial Port's (a port that cannot be opened: «Нет доступа», «Устройство
// не найдено»), which the controller link's plugin passes on.
QTranslator* serialTranslator() {
    static QTranslator* t = new QTranslator(QCoreApplication::instance());
    return t;
}
bool& qtInstalled() {
    static bool installed = false;
    return installed;
}
QString& current() {
    static QString lang;
    return lang;
}
// The libraries' own messages (gettext: libpq's «подключиться к серверу …
// не удалось», the C library's «В соединении отказано») in the window's
// language. gettext ignores LANGUAGE while the messages' locale is "C"
// (a server's, a test's, a container's default): then the messages take
// C.UTF-8, whose charset keeps the Cyrillic (C would transliterate it).
void setLibraryLanguage(const QString& language) {
    qputenv("LANGUAGE", language.toLatin1());
    const char* now = std::setlocale(LC_MESSAGES, nullptr);
    std::string messages = now ? now : "C";
    if (language != QLatin1String("en") && (messages == "C" || messages == "POSIX"))
        messages = "C.UTF-8";
    // Set again even when it stays: gettext forgets the translations it
    // looked up (they were in the language before) only when a locale is set.
    std::setlocale(LC_MESSAGES, messages.c_str());
}
} // namespace

QString savedOrSystemLanguage() {
    const QString saved = QSettings().value("ui/language").toString();
    if (saved == "ru" || saved == "en")
        return saved;
    return QLocale::system().language() == QLocale::Russian ? "ru" : "en";
}

bool setLanguage(const QString& language) {
    if (language != "ru" && language != "en")
        return false;
    QCoreApplication::removeTranslator(translator());
    QCoreApplication::removeTranslator(qtTranslator());
    QCoreApplication::removeTranslator(serialTranslator());
    // English is Qt's own language: no file (the Russian one is taken out).
    qtInstalled() = language != "en" &&
                    qtTranslator()->load("qtbase_" + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)) &&
                    QCoreApplication::installTranslator(qtTranslator());
    if (language != "en" &&
        serialTranslator()->load("qtserialport_" + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(serialTranslator());
    if (translator()->load(":/i18n/k528studio_" + language + ".qm"))
        QCoreApplication::installTranslator(translator());
    setLibraryLanguage(language);
    current() = language;
    QSettings().setValue("ui/language", language);
    return true;
}

QString currentLanguage() { return current(); }

bool russianWindow() { return current() == QLatin1String("ru"); }

QString coreText(std::string_view ru, std::string_view en) {
    const std::string_view s = inWindowLanguage(ru, en);
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

bool qtTranslationsLoaded() { return qtInstalled(); }

} // namespace k528::studio
