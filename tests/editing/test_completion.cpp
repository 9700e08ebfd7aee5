// The editor's completion catalog: table 5, the built-in and the machine's
// M's, appendix Л, and what the edited file holds.
#include <QtTest>

#include "editing/completion.h"
#include "plc/description.h"
#include "program/parser.h"

using namespace k528;
using namespace k528::editing;

namespace {
const CompletionItem* find(const std::vector<CompletionItem>& items, CompletionKind k, const std::string& w) {
    for (const auto& i : items)
        if (i.kind == k && i.word == w)
            return &i;
    return nullptr;
}
} // namespace

class TestCompletion : public QObject {
    Q_OBJECT
private slots:
    void tablesOfTheManual() {
        const auto items = completionCatalog({});
        const CompletionItem* g1 = find(items, CompletionKind::G, "G1");
        QVERIFY(g1);
        QCOMPARE(g1->group, 1);
        QVERIFY(!g1->detailEn.empty());
        const CompletionItem* g281 = find(items, CompletionKind::G, "G281");
        QVERIFY(g281);
        QCOMPARE(g281->group, 11);
        QVERIFY(QString::fromStdString(g281->detailEn).contains("Z"));
        QVERIFY(!find(items, CompletionKind::G, "G2")); // not in table 5
        QVERIFY(find(items, CompletionKind::M, "M17"));
        const CompletionItem* r204 = find(items, CompletionKind::R, "R204");
        QVERIFY(r204);
        QVERIFY(QString::fromStdString(r204->detailRu).contains("нового круга"));
        QVERIFY(QString::fromStdString(find(items, CompletionKind::R, "R240")->detailEn).contains("read only"));
        QCOMPARE(complete(items, CompletionKind::G, "g28").size(), std::size_t(2)); // G280, G281
    }
    void machineMCodes() {
        const plc::MachineDescription d = plc::loadDescription("grinder-205");
        CompletionContext c;
        c.machine = &d;
        const auto items = completionCatalog(c);
        const CompletionItem* m3 = find(items, CompletionKind::M, "M3");
        QVERIFY(m3);
        QVERIFY(!m3->detailEn.empty());
        QVERIFY(!find(completionCatalog({}), CompletionKind::M, "M3"));
    }
    void whatTheFileHolds() {
        const auto parsed = program::parse("%L1 (main)\nN10 L7\nN20 GOTO 10\nM30\n%L7 (dress)\nM17\n"
                                           "%MESSAGES\n#3=ПРАВКА\n");
        CompletionContext c;
        c.store = &parsed.store;
        c.currentProgram = 1;
        const auto items = completionCatalog(c);
        QCOMPARE(find(items, CompletionKind::Call, "L7")->detailEn, std::string("dress"));
        QVERIFY(find(items, CompletionKind::Call, "L1"));
        QCOMPARE(find(items, CompletionKind::JumpTarget, "20")->detailEn, std::string("N20 GOTO 10"));
        QVERIFY(!find(items, CompletionKind::JumpTarget, "30"));
        QCOMPARE(find(items, CompletionKind::Message, "#3")->detailRu, std::string("ПРАВКА"));
    }
};

QTEST_APPLESS_MAIN(TestCompletion)
#include "test_completion.moc"
