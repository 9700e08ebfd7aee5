#include <QtTest>

#include "program/gfunctions.h"

using namespace k528::program;

class TestGFunctions : public QObject {
    Q_OBJECT
private slots:
    // Every row of table 5.
    void table5() {
        struct Row {
            int g;
            GGroup group;
            GFunction f;
            Axis axis;
            bool modal;
        };
        const Row rows[] = {
            {0, GGroup::Motion, GFunction::Rapid, Axis::None, true},
            {1, GGroup::Motion, GFunction::Feed, Axis::None, true},
            {4, GGroup::Dwell, GFunction::Dwell, Axis::None, false},
            {110, GGroup::Handwheel, GFunction::Handwheel, Axis::X, false},
            {210, GGroup::Handwheel, GFunction::Handwheel, Axis::Z, false},
            {136, GGroup::StopOnSignal, GFunction::StopOnSignal, Axis::X, false},
            {239, GGroup::StopOnSignal, GFunction::StopOnSignal, Axis::Z, false},
            {50, GGroup::Components, GFunction::OmitHandwheelOffset, Axis::None, true},
            {51, GGroup::Components, GFunction::OmitCorrection, Axis::None, true},
            {52, GGroup::Components, GFunction::OmitDressing, Axis::None, true},
            {53, GGroup::Components, GFunction::OmitZeroOffset, Axis::None, true},
            {54, GGroup::Components, GFunction::AllComponents, Axis::None, true},
            {55, GGroup::Override, GFunction::OverrideAllAxes, Axis::None, true},
            {156, GGroup::Override, GFunction::NoOverride, Axis::X, true},
            {256, GGroup::Override, GFunction::NoOverride, Axis::Z, true},
            {90, GGroup::Dimensions, GFunction::Absolute, Axis::None, true},
            {91, GGroup::Dimensions, GFunction::Incremental, Axis::None, true},
            {192, GGroup::SetPosition, GFunction::SetPosition, Axis::X, false},
            {292, GGroup::SetPosition, GFunction::SetPosition, Axis::Z, false},
            {180, GGroup::Oscillation, GFunction::OscillationStop, Axis::X, true},
            {181, GGroup::Oscillation, GFunction::OscillationStart, Axis::X, true},
            {280, GGroup::Oscillation, GFunction::OscillationStop, Axis::Z, true},
            {281, GGroup::Oscillation, GFunction::OscillationStart, Axis::Z, true},
        };
        for (const Row& r : rows) {
            const GInfo i = classifyG(r.g);
            QVERIFY2(i.known(), qPrintable(QString::number(r.g)));
            QCOMPARE(i.group, r.group);
            QCOMPARE(i.function, r.f);
            QCOMPARE(i.axis, r.axis);
            QCOMPARE(i.modal, r.modal);
        }
        QCOMPARE(classifyG(137).signal, 2);
        QCOMPARE(classifyG(239).signal, 4);
        QCOMPARE(groupNumber(classifyG(281).group), 11);
    }
    void powerOnDefaults() {
        int defaults = 0;
        for (int g = 0; g <= 299; ++g)
            defaults += classifyG(g).powerOnDefault ? 1 : 0;
        QCOMPARE(defaults, 3); // G01, G54, G55 (table 5 '**')
        QVERIFY(classifyG(1).powerOnDefault && classifyG(54).powerOnDefault && classifyG(55).powerOnDefault);
    }
    void everythingElseIsUnknown() {
        int known = 0;
        for (int g = -5; g <= 400; ++g)
            known += classifyG(g).known() ? 1 : 0;
        QCOMPARE(known, 11 + 2 * 9); // 11 plain + 9 per axis digit (10, 36..39, 56, 80, 81, 92)
        for (int g : {2, 3, 5, 10, 36, 56, 80, 81, 92, 100, 300, 310, 336, 381, 392, 199, 111})
            QVERIFY2(!classifyG(g).known(), qPrintable(QString::number(g)));
    }
    void names() {
        QCOMPARE(QString::fromStdString(gName(0)), QString("G00"));
        QCOMPARE(QString::fromStdString(gName(4)), QString("G04"));
        QCOMPARE(QString::fromStdString(gName(281)), QString("G281"));
        QVERIFY(!gMeaningRu(GFunction::Dwell).empty());
        QVERIFY(!gMeaningEn(GFunction::OscillationStart).empty());
    }
};

QTEST_APPLESS_MAIN(TestGFunctions)
#include "test_gfunctions.moc"
