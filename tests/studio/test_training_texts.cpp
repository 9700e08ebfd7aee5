// The texts of a training grade in the desktop: core's catalog ids rendered
// through tr() (app/studio/training/training_texts.cpp) — every id of the
// catalog has its desktop template, in Russian the catalog's Russian, and a
// text renders as the CLI renders it (training::render).
#include "catalog/training_texts.h"
#include "language.h"
#include "training/texts.h"
#include "training/training_texts.h"

#include <QSettings>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

class TestTrainingTexts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTestTrainingTexts");
        QSettings().clear();
    }

    void everyCatalogIdInBothLanguages() {
        for (const char* language : {"en", "ru"}) {
            QVERIFY(setLanguage(language));
            const bool ru = QString(language) == QLatin1String("ru");
            for (const util::CatalogText& t : catalog::trainingTexts().texts()) {
                const std::string id(t.id);
                const QString pattern = trainingTextPattern(id);
                const QString expected = QString::fromUtf8(ru ? t.ru.data() : t.en.data(),
                                                           static_cast<qsizetype>(ru ? t.ru.size() : t.en.size()));
                QVERIFY2(pattern == expected, qPrintable(QStringLiteral("%1 [%2]: «%3», the catalog «%4»")
                                                             .arg(QString::fromStdString(id), QString(language),
                                                                  pattern, expected)));
            }
        }
    }

    void rendersAsTheCliDoes() {
        const training::Text overcut{"overcut", {"120", "0.35", "30", "-12.5", "L1 N15", "17"}};
        const training::Text message{"message.machine", {"Z1900.3", training::TextArg("Нет смазки", "No lube")}};
        for (const char* language : {"en", "ru"}) {
            QVERIFY(setLanguage(language));
            const training::Language l =
                QString(language) == QLatin1String("ru") ? training::Language::Ru : training::Language::En;
            for (const training::Text& t : {overcut, message})
                QCOMPARE(trainingText(t), QString::fromStdString(training::render(t, l)));
        }
        QVERIFY(setLanguage("en"));
        QVERIFY(trainingText(overcut).contains(QStringLiteral("L1 N15, line 17")) ||
                trainingText(overcut).contains(QStringLiteral("frame L1 N15")));
        // An id the desktop does not know: core's rendering, never lost.
        QCOMPARE(trainingText(training::Text{"no-such", {"1"}}), QStringLiteral("no-such 1"));
    }
};

QTEST_MAIN(TestTrainingTexts)
#include "test_training_texts.moc"
