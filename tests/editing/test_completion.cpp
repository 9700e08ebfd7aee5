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
        QVERIFY(!g1->detail(false).empty());
        const CompletionItem* g281 = find(items, CompletionKind::G, "G281");
        QVERIFY(g281);
        QCOMPARE(g281->group, 11);
        QVERIFY(QString::fromStdString(g281->detail(false)).endsWith(" (axis Z)"));
        QVERIFY(QString::fromStdString(g281->detail(true)).endsWith(" (ось Z)"));
        QVERIFY(!find(items, CompletionKind::G, "G2")); // not in table 5
        QVERIFY(find(items, CompletionKind::M, "M17"));
        const CompletionItem* r204 = find(items, CompletionKind::R, "R204");
        QVERIFY(r204);
        QVERIFY(QString::fromStdString(r204->detail(true)).contains("нового круга"));
        QVERIFY(QString::fromStdString(find(items, CompletionKind::R, "R240")->detail(false)).endsWith(" (read only)"));
        QVERIFY(QString::fromStdString(find(items, CompletionKind::R, "R240")->detail(true)).endsWith(" (только чтение)"));
        QCOMPARE(complete(items, CompletionKind::G, "g28").size(), std::size_t(2)); // G280, G281
    }
    void machineMCodes() {
        const plc::MachineDescription d = plc::loadDescription("grinder-205");
        CompletionContext c;
        c.machine = &d;
        const auto items = completionCatalog(c);
        const CompletionItem* m3 = find(items, CompletionKind::M, "M3");
        QVERIFY(m3);
        // The description says what it does in each language.
        QCOMPARE(m3->detail(true), std::string("включение шпинделя круга; ожидание выхода на скорость"));
        QCOMPARE(m3->detail(false), std::string("wheel spindle on; waits until it is at speed"));
        QVERIFY(!find(completionCatalog({}), CompletionKind::M, "M3"));
    }
    void whatTheFileHolds() {
        const auto parsed = program::parse("%L1 (main)\nN10 L7\nN20 GOTO 10\nM30\n%L7 (dress)\nM17\n"
                                           "%MESSAGES\n#3=ПРАВКА\n");
        CompletionContext c;
        c.store = &parsed.store;
        c.currentProgram = 1;
        const auto items = completionCatalog(c);
        QCOMPARE(find(items, CompletionKind::Call, "L7")->detail(false), std::string("dress"));
        QCOMPARE(find(items, CompletionKind::Call, "L7")->detail(true), std::string("dress"));
        QCOMPARE(find(items, CompletionKind::Call, "L1")->detail(true), std::string("main"));
        QCOMPARE(find(items, CompletionKind::JumpTarget, "20")->detail(false), std::string("N20 GOTO 10"));
        QVERIFY(!find(items, CompletionKind::JumpTarget, "30"));
        QCOMPARE(find(items, CompletionKind::Message, "#3")->detail(true), std::string("ПРАВКА"));
        QCOMPARE(find(items, CompletionKind::Message, "#3")->detail(false), std::string("ПРАВКА"));
    }
    // The completion's own words come from its catalog, in each language;
    // every item means something in both.
    void ownWordsInEachLanguage() {
        const auto parsed = program::parse("%L4\nN10 M30\n");
        CompletionContext c;
        c.store = &parsed.store;
        c.currentProgram = 4;
        const auto items = completionCatalog(c);
        const CompletionItem* m30 = find(items, CompletionKind::M, "M30");
        QVERIFY(m30);
        QCOMPARE(m30->detail(true), std::string("конец программы"));
        QCOMPARE(m30->detail(false), std::string("end of program"));
        const CompletionItem* l4 = find(items, CompletionKind::Call, "L4"); // no title
        QVERIFY(l4);
        QCOMPARE(l4->detail(true), std::string("программа 4"));
        QCOMPARE(l4->detail(false), std::string("program 4"));
        const CompletionItem* r0 = find(items, CompletionKind::R, "R0");
        QVERIFY(r0);
        QCOMPARE(r0->detail(true), std::string("параметр пользователя"));
        QCOMPARE(r0->detail(false), std::string("user parameter"));
        for (const CompletionItem& it : items) {
            QVERIFY2(!it.detail(true).empty() && !it.detail(false).empty(), it.word.c_str());
            if (!it.detailId.empty())
                QVERIFY2(completionTexts().find(it.detailId), it.detailId.c_str());
        }
    }
};

QTEST_APPLESS_MAIN(TestCompletion)
#include "test_completion.moc"
