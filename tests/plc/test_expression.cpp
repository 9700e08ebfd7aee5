// The conditions of the machine description: syntax, precedence, edges, errors.
#include "plc/expression.h"

#include <QtTest>
#include <array>
#include <functional>
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

    // eval() runs a short-circuiting branching program compiled from the
    // postfix code: random conditions (every operator and spelling, nested,
    // constants, edges) give, for every signal image now and before, the
    // value of the condition as written.
    void branchingProgramGivesTheWrittenValue() {
        std::uint32_t seed = 2024;
        const auto rnd = [&](unsigned n) {
            seed = seed * 1103515245u + 12345u;
            return ((seed >> 16) & 0x7FFF) % n;
        };
        const char* names[] = {"a", "b", "c", "door_closed", "Z2000.8"};
        using Value = std::function<bool(const std::uint8_t*, const std::uint8_t*)>;
        // A random condition: its text and its value, written out directly.
        const auto make = [&](const auto& self, int depth) -> std::pair<std::string, Value> {
            const unsigned kind = depth >= 5 ? rnd(5) : rnd(9);
            const std::uint32_t s = rnd(5);
            const std::string n = names[s];
            switch (kind) {
            case 0:
            case 1:
                return {n, [s](const std::uint8_t* now, const std::uint8_t*) { return now[s] != 0; }};
            case 2:
                return {"rise(" + n + ")", [s](const std::uint8_t* now, const std::uint8_t* prev) {
                            return now[s] != 0 && prev[s] == 0;
                        }};
            case 3:
                return {"fall(" + n + ")", [s](const std::uint8_t* now, const std::uint8_t* prev) {
                            return now[s] == 0 && prev[s] != 0;
                        }};
            case 4: {
                const bool v = rnd(2) != 0;
                return {v ? "true" : "false", [v](const std::uint8_t*, const std::uint8_t*) { return v; }};
            }
            case 5: {
                auto [t, f] = self(self, depth + 1);
                return {std::string(rnd(2) ? "!" : "not ") + "(" + t + ")",
                        [f](const std::uint8_t* now, const std::uint8_t* prev) { return !f(now, prev); }};
            }
            case 6:
            case 7: {
                auto [lt, lf] = self(self, depth + 1);
                auto [rt, rf] = self(self, depth + 1);
                return {"(" + lt + ")" + (rnd(2) ? " & " : " and ") + "(" + rt + ")",
                        [lf, rf](const std::uint8_t* now, const std::uint8_t* prev) {
                            const bool l = lf(now, prev), r = rf(now, prev);
                            return l && r;
                        }};
            }
            default: {
                auto [lt, lf] = self(self, depth + 1);
                auto [rt, rf] = self(self, depth + 1);
                return {"(" + lt + ")" + (rnd(2) ? " | " : " or ") + "(" + rt + ")",
                        [lf, rf](const std::uint8_t* now, const std::uint8_t* prev) {
                            const bool l = lf(now, prev), r = rf(now, prev);
                            return l || r;
                        }};
            }
            }
        };
        for (int n = 0; n < 400; ++n) {
            const auto [text, value] = make(make, 0);
            ExprError err;
            const auto e = compileExpr(text, resolve, err);
            QVERIFY2(e, qPrintable(QString::fromStdString(text + ": " + err.message)));
            for (unsigned bits = 0; bits < 1024; ++bits) {
                std::array<std::uint8_t, 5> now{}, prev{};
                for (std::size_t i = 0; i < 5; ++i) {
                    now[i] = static_cast<std::uint8_t>((bits >> i) & 1u);
                    prev[i] = static_cast<std::uint8_t>((bits >> (5 + i)) & 1u);
                }
                QVERIFY2(e->eval(now.data(), prev.data()) == value(now.data(), prev.data()),
                         qPrintable(QString::fromStdString(text)));
            }
        }
        // Plain chains as the descriptions write them.
        QVERIFY(eval("a & b & !c & door_closed", {1, 1, 0, 1, 0}));
        QVERIFY(!eval("a & b & !c & door_closed", {1, 1, 1, 1, 0}));
        QVERIFY(eval("!a | !b | Z2000.8", {1, 1, 0, 0, 1}));
        QVERIFY(!eval("!a | !b | Z2000.8", {1, 1, 0, 0, 0}));
        QVERIFY(eval("(a & !b) | (c & !door_closed)", {0, 0, 1, 0, 0}));
    }
};

QTEST_APPLESS_MAIN(TestExpression)
#include "test_expression.moc"
