// The R-parameter map of appendix Л.
#include "catalog/rparams.h"

#include <QtTest>

using namespace k528::catalog;

class TestRParams : public QObject {
    Q_OBJECT
private slots:
    void userReservedReadOnly() {
        for (int n = 0; n < kRParamCount; ++n) {
            const RParamDef& d = rParam(n);
            QCOMPARE(d.number, n);
            QCOMPARE(d.user(), n <= 149);
            QCOMPARE(d.readOnly(), n >= 232 && n <= 262);
            QCOMPARE(d.reserved(), n >= 150);
            if (n >= 263)
                QVERIFY(d.access == RAccess::Unassigned);
        }
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, rParam(300));
        QVERIFY(findRParam(-1) == nullptr);
    }

    void meaningsOfAppendixL() {
        QCOMPARE(rParam(204).meaningRu, std::string_view("Диаметр нового круга в дискр X"));
        QVERIFY(rParam(204).unit == RUnit::DiscX && rParam(204).group == 5);
        QCOMPARE(rParam(204).panelHint, std::string_view("ДИАМЕТР НОВ.КРУГА"));
        QVERIFY(rParam(212).unit == RUnit::DiscZPerMin && rParam(212).group == 4);
        QVERIFY(rParam(210).unit == RUnit::DiscX && rParam(210).group == 4);
        QVERIFY(rParam(218).group == 3 && rParam(219).unit == RUnit::DiscZ);
        QVERIFY(rParam(220).group == 2 && rParam(221).unit == RUnit::DiscZ);
        for (int n = 224; n <= 231; ++n)
            QVERIFY(rParam(n).group == 1 && rParam(n).access == RAccess::System);
        for (int n = 184; n <= 199; ++n)
            QCOMPARE(rParam(n).group, 7);
        QCOMPARE(rParam(174).group, 8);
        QCOMPARE(rParam(164).group, 9);
        QCOMPARE(rParam(200).group, 6);
        QVERIFY(rParam(186).unit == RUnit::DiscXPerMin && rParam(194).unit == RUnit::DiscZPerMin);
        QVERIFY(rParam(232).unit == RUnit::DiscX && rUnitAxis(rParam(232).unit) == Axis::X);
        QVERIFY(rParam(240).unit == RUnit::DacUnits);
        QVERIFY(rParam(254).unit == RUnit::FrameNumber);
        QCOMPARE(rParam(158).meaningRu,
                 std::string_view("Указатель текущего уровня вложения программ"));
        QVERIFY(rParam(150).unit == RUnit::Flag);
        QVERIFY(rParam(155).access == RAccess::Unassigned && rParam(155).meaningRu.empty());
        QVERIFY(rParam(248).readOnly() && rParam(248).meaningRu.empty());
        QCOMPARE(rGroupNameRu(5), std::string_view("ШЛИФ.КРУГ"));
        QCOMPARE(rGroupNameEn(1), std::string_view("coordinates and offsets"));
        QCOMPARE(rGroupNameRu(0), std::string_view());
    }

    void everyAssignedHasBothLanguages() {
        for (int n = 150; n <= 262; ++n) {
            const RParamDef& d = rParam(n);
            QCOMPARE(d.meaningRu.empty(), d.meaningEn.empty());
            QVERIFY(!rUnitRu(d.unit).empty() && !rUnitEn(d.unit).empty());
        }
    }
};

QTEST_APPLESS_MAIN(TestRParams)
#include "test_rparams.moc"
