#include "language.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace k528::studio {

namespace {
QTranslator* translator() {
    static QTranslator* t = new QTranslator(QCoreApplication::instance());
    return t;
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
    if (translator()->load(":/i18n/k528studio_" + language + ".qm"))
        QCoreApplication::installTranslator(translator());
    current() = language;
    QSettings().setValue("ui/language", language);
    return true;
}

QString currentLanguage() { return current(); }

} // namespace k528::studio
