// The conditions of the machine description: syntax, precedence, edges, errors.
#include "plc/expression.h"

#include <QtTest>
#include <map>

using namespace k528::plc;

namespace {

const std::map<std::string, std::uint32_t, std::less<>> kNames = {
    {"a", 0}, {"b", 1}, {"c", 2}, {"door_closed", 3}, {"Z2000.8", 4}};

std::optional<std::uint32_t> resolve(std::string_view n) {
    const auto it = kNames.find(n);
    if (it == kNames.end())
        return std::nullopt;
    return it->second;
}

bool eval(const std::string& text, std::array<std::uint8_t, 5> now,
          std::array<std::uint8_t, 5> prev = {}) {
    ExprError err;
    const auto e = compileExpr(text, resolve, err);
    if (!e)
        qFatal("%s: %s", text.c_str(), err.message.c_str());
    return e->eval(now.data(), prev.data());
}

ExprError error(const std::string& text) {
    ExprError err;
    const auto e = compileExpr(text, resolve, err);
    if (e)
        qFatal("'%s' compiled", text.c_str());
    return err;
}

} // namespace

class TestExpression : public QObject {
    Q_OBJECT
private slots:
    void operators() {
        QVERIFY(eval("a", {1, 0, 0, 0, 0}));
        QVERIFY(!eval("!a", {1, 0, 0, 0, 0}));
        QVERIFY(eval("not a", {0, 0, 0, 0, 0}));
        QVERIFY(eval("a & b", {1, 1, 0, 0, 0}));
        QVERIFY(!eval("a and b", {1, 0, 0, 0, 0}));
        QVERIFY(eval("a | b", {0, 1, 0, 0, 0}));
        QVERIFY(eval("a or b", {1, 0, 0, 0, 0}));
        QVERIFY(eval("true", {}));
        QVERIFY(!eval("false", {}));
        QVERIFY(eval("Z2000.8 & door_closed", {0, 0, 0, 1, 1}));
    }
    // & binds tighter than |, ! tighter than &.
    void precedence() {
        // a | b & c  ==  a | (b & c)
        QVERIFY(eval("a | b & c", {1, 0, 0, 0, 0}));
        QVERIFY(!eval("a | b & c", {0, 1, 0, 0, 0}));
        QVERIFY(!eval("(a | b) & c", {1, 0, 0, 0, 0}));
        QVERIFY(eval("!a & b", {0, 1, 0, 0, 0}));
        QVERIFY(!eval("!(a & b)", {1, 1, 0, 0, 0}));
        QVERIFY(eval("!!a", {1, 0, 0, 0, 0}));
        QVERIFY(eval("((a))|((b))", {0, 1, 0, 0, 0}));
    }
    void edges() {
        QVERIFY(eval("rise(a)", {1, 0, 0, 0, 0}, {0, 0, 0, 0, 0}));
        QVERIFY(!eval("rise(a)", {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}));
        QVERIFY(eval("fall(a)", {0, 0, 0, 0, 0}, {1, 0, 0, 0, 0}));
        QVERIFY(!eval("fall(a)", {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}));
        QVERIFY(eval("rise(Z2000.8) & b", {0, 1, 0, 0, 1}, {0, 0, 0, 0, 0}));
    }
    void signalsRead() {
        ExprError err;
        const auto e = compileExpr("a & !c | rise(b) | a", resolve, err);
        QVERIFY(e);
        QCOMPARE(e->reads(), (std::vector<std::uint32_t>{0, 1, 2}));
        QCOMPARE(e->text(), std::string("a & !c | rise(b) | a"));
    }
    void errors() {
        ExprError e = error("a & frobnicate");
        QCOMPARE(e.column, 5);
        QVERIFY(e.message.find("unknown signal 'frobnicate'") != std::string::npos);
        e = error("");
        QVERIFY(e.message.find("empty") != std::string::npos);
        e = error("a &");
        QVERIFY(e.message.find("missing") != std::string::npos ||
                e.message.find("ends") != std::string::npos);
        e = error("(a | b");
        QVERIFY(e.message.find("')'") != std::string::npos);
        e = error("a b");
        QCOMPARE(e.column, 3);
        e = error("rise a");
        QVERIFY(e.message.find("rise(name)") != std::string::npos);
        e = error("rise(a & b)");
        QVERIFY(e.message.find("missing ')'") != std::string::npos);
        e = error("a & or");
        QVERIFY(e.message.find("keyword") != std::string::npos);
        e = error("a # b");
        QVERIFY(e.message.find("'#'") != std::string::npos);
        e = error("Z2000.9");
        QVERIFY(e.message.find("Z2000.9") != std::string::npos);
        // A long chain is evaluated as it goes; deep right nesting is refused.
        std::string chain = "a";
        for (int i = 0; i < 100; ++i)
            chain += " & b | c";
        ExprError err;
        QVERIFY(compileExpr(chain, resolve, err));
        std::string deep = "b";
        for (int i = 0; i < 40; ++i)
            deep = "a & (" + deep + ")";
        e = error(deep);
        QVERIFY(e.message.find("nested too deeply") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestExpression)
#include "test_expression.moc"
