#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

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
bool& qtInstalled() {
    static bool installed = false;
    return installed;
}
QString& current() {
    static QString lang;
    return lang;
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
    // English is Qt's own language: no file (the Russian one is taken out).
    qtInstalled() = language != "en" &&
                    qtTranslator()->load("qtbase_" + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)) &&
                    QCoreApplication::installTranslator(qtTranslator());
    if (translator()->load(":/i18n/k528studio_" + language + ".qm"))
        QCoreApplication::installTranslator(translator());
    current() = language;
    QSettings().setValue("ui/language", language);
    return true;
}

QString currentLanguage() { return current(); }

bool qtTranslationsLoaded() { return qtInstalled(); }

} // namespace k528::studio
