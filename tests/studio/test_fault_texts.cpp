// The desktop's fault names: translated from core's stable fault id
// (machine::faultText) in one place, app/studio/machine/fault_texts.cpp.
#include "language.h"
#include "machine/fault_texts.h"
#include "machine/simulation.h"

#include <QSettings>
#include <QtTest>

#include <set>

using namespace k528;
using namespace k528::studio;

class TestFaultTexts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
    }

    // Every fault the shipped machines offer has a translated name in both
    // languages (never core's English fallback), distinct within a machine.
    void everyFaultHasItsName() {
        for (const char* language : {"en", "ru"}) {
            QVERIFY(setLanguage(language));
            for (const char* name : {"training-lathe", "grinder-205"}) {
                machine::Simulation sim(name);
                std::set<QString> titles;
                for (const machine::FaultSpec& f : sim.availableFaults()) {
                    const QString title = faultTitle(f);
                    QVERIFY2(!title.isEmpty(), machine::faultText(f).id.c_str());
                    // Russian: a pattern of its own, never core's English fallback.
                    if (QString(language) == "ru")
                        QVERIFY2(title != QString::fromStdString(machine::describeFault(f)),
                                 qPrintable(title));
                    QVERIFY2(!title.contains('%'), qPrintable(title));
                    QVERIFY2(titles.insert(title).second, qPrintable(title));
                }
            }
        }
    }

    void argumentsInTheirPlaces() {
        QVERIFY(setLanguage("en"));
        using machine::Fault;
        using machine::FaultSpec;
        QCOMPARE(faultTitle(FaultSpec(Fault::EncoderChannelBreak, engine::AxisId::Z, 2)),
                 QString("Encoder Z: channel 2 broken"));
        QCOMPARE(faultTitle(FaultSpec(Fault::LimitSwitch, engine::AxisId::X, -1)),
                 QString("Limit switch X- hit"));
        QCOMPARE(faultTitle(FaultSpec(Fault::PumpOverload, engine::AxisId::X, 0, "coolant")),
                 QString("Motor overload: coolant pump"));
        QCOMPARE(faultTitle(FaultSpec(Fault::K923, engine::AxisId::X, 1)),
                 QString("K923: no link to the PLC"));
        QVERIFY(setLanguage("ru"));
        QCOMPARE(faultTitle(FaultSpec(Fault::EncoderChannelBreak, engine::AxisId::X, 1)),
                 QString("ДОС X: обрыв канала 1"));
        QCOMPARE(faultTitle(FaultSpec(Fault::PumpOverload, engine::AxisId::X, 0, "coolant")),
                 QString("Перегрузка двигателя: насос СОЖ"));
    }
};

QTEST_MAIN(TestFaultTexts)
#include "test_fault_texts.moc"
