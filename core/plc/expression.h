// Boolean conditions of the machine description (docs/machine-description.md),
// compiled once into a small stack program over the PLC's signal image.
//
//   expr    := or
//   or      := and { ("|" | "or") and }
//   and     := unary { ("&" | "and") unary }
//   unary   := ("!" | "not") unary | primary
//   primary := "(" expr ")" | "rise(" name ")" | "fall(" name ")" | "true" | "false" | name
//   name    := [A-Za-z_][A-Za-z0-9_]*  |  Z<word>.<bit>  (e.g. Z2000.8)
//
// rise(x) is 1 in the scan where signal x turned 1 (it was 0 at the end of
// the previous scan), fall(x) likewise for 1 -> 0. Names are resolved when
// compiling: an unknown name is an error naming it. Evaluation never
// allocates.
//
// The postfix code is the expression as written; eval() runs a branching
// program compiled from it: one test per leaf (a signal, its rise or its
// fall), each naming the test to go on with when it is true and when it is
// false, the negations folded into the branches. & and | therefore
// short-circuit, which gives the same value (no operand has an effect)
// with a fraction of the work: the PLC evaluates every condition of the
// description in every scan.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::plc {

class Expr {
public:
    enum class Op : std::uint8_t { Load, Rise, Fall, Not, And, Or, True, False };
    struct Instr {
        Op op;
        std::uint32_t signal; // for Load / Rise / Fall
    };

    // The value given the signal image now and at the end of the previous scan.
    bool eval(const std::uint8_t* now, const std::uint8_t* prev) const;
    bool empty() const { return code_.empty(); }
    const std::string& text() const { return text_; }
    // Signals the expression reads (for dependency checks).
    std::vector<std::uint32_t> reads() const;

    static constexpr int kMaxDepth = 32; // evaluation stack

private:
    friend class ExprCompiler;
    // One test of the branching program. onTrue / onFalse: the index of the
    // next test, or kTrue / kFalse, the value of the expression.
    struct Test {
        std::uint32_t signal;
        std::int32_t onTrue, onFalse;
        bool edge;          // rise or fall: the value at the previous scan counts too
        bool nowZero;       // the value is 1 when now[signal] is 0 (fall)
        bool prevZero;      // an edge's previous value must be 0 (rise) or 1 (fall)
    };
    static constexpr std::int32_t kTrue = -1, kFalse = -2;
    void buildTests(); // tests_ and entry_ from code_

    std::vector<Instr> code_;
    std::vector<Test> tests_;
    std::int32_t entry_ = kFalse;
    std::string text_;
};

// Inline: the PLC evaluates every condition of the description in every scan.
inline bool Expr::eval(const std::uint8_t* now, const std::uint8_t* prev) const {
    const Test* tests = tests_.data();
    std::int32_t i = entry_;
    while (i >= 0) {
        const Test& t = tests[i];
        bool v = (now[t.signal] == 0) == t.nowZero;
        if (t.edge)
            v = v && (prev[t.signal] == 0) == t.prevZero;
        i = v ? t.onTrue : t.onFalse;
    }
    return i == kTrue;
}

struct ExprError {
    int column = 0; // 1-based, in bytes of the expression text
    std::string message; // English
    std::string id;      // of description_texts.h ("expr.empty", "plc.unknown-signal")
    std::vector<std::string> args;
};

// Resolves a name to a signal index, or nullopt when the name is unknown.
using NameResolver = std::function<std::optional<std::uint32_t>(std::string_view name)>;

// Compiles `text`; nullopt and `error` filled when it is not a valid expression.
std::optional<Expr> compileExpr(std::string_view text, const NameResolver& resolve,
                                ExprError& error);

} // namespace k528::plc
