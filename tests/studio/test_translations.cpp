// Every text of the desktop UI has a Russian translation (operators' language)
// and an English one (the sources' own words unless a source is the manual's Russian).
#include <QtTest>

#include <QFile>
#include <QXmlStreamReader>

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void russianIsComplete() { checkComplete(QStringLiteral("ru")); }
    void englishIsComplete() { checkComplete(QStringLiteral("en")); }

private:
    static void checkComplete(const QString& language) {
        QFile f(QStringLiteral(K528_SOURCE_DIR "/translations/k528studio_") + language + QStringLiteral(".ts"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&f);
        QString source;
        QStringList unfinished;
        int messages = 0;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement())
                continue;
            if (xml.name() == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (xml.name() == QLatin1String("translation")) {
                ++messages;
                const bool isUnfinished = xml.attributes().value("type") == QLatin1String("unfinished");
                const bool isVanished = xml.attributes().value("type") == QLatin1String("vanished") ||
                                        xml.attributes().value("type") == QLatin1String("obsolete");
                const QString text = xml.readElementText();
                if (!isVanished && (isUnfinished || text.isEmpty()))
                    unfinished << source;
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(messages > 0);
        QVERIFY2(unfinished.isEmpty(), qPrintable("untranslated: " + unfinished.join(" | ")));
    }
};

QTEST_APPLESS_MAIN(TestTranslations)
#include "test_translations.moc"
