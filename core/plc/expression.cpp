#include "plc/expression.h"

#include "plc/description_texts.h"

#include <algorithm>
#include <cctype>

namespace k528::plc {

// The branching program of the postfix code: the code is turned into its
// tree, then each node is laid out with the continuations of its value —
// a leaf becomes a test, ! swaps the continuations, a & b tests a and goes
// on with b when it is true, a | b goes on with b when a is false.
void Expr::buildTests() {
    struct Node {
        Op op;
        std::uint32_t signal;
        int left, right; // operands (Not: left)
    };
    std::vector<Node> nodes;
    std::vector<int> stack;
    for (const Instr& i : code_) {
        Node n{i.op, i.signal, -1, -1};
        if (i.op == Op::Not) {
            n.left = stack.back();
            stack.pop_back();
        } else if (i.op == Op::And || i.op == Op::Or) {
            n.right = stack.back();
            stack.pop_back();
            n.left = stack.back();
            stack.pop_back();
        }
        nodes.push_back(n);
        stack.push_back(static_cast<int>(nodes.size()) - 1);
    }
    tests_.clear();
    // The entry of node k given the continuations of its value; the right
    // operand is laid out first, so that after the reversal below a test
    // is mostly followed by the one it goes on with.
    const auto layout = [&](const auto& self, int k, std::int32_t onTrue,
                            std::int32_t onFalse) -> std::int32_t {
        const Node& n = nodes[static_cast<std::size_t>(k)];
        switch (n.op) {
        case Op::True:
            return onTrue;
        case Op::False:
            return onFalse;
        case Op::Not:
            return self(self, n.left, onFalse, onTrue);
        case Op::And:
            return self(self, n.left, self(self, n.right, onTrue, onFalse), onFalse);
        case Op::Or:
            return self(self, n.left, onTrue, self(self, n.right, onTrue, onFalse));
        case Op::Load:
        case Op::Rise:
        case Op::Fall:
            break;
        }
        tests_.push_back({n.signal, onTrue, onFalse, n.op != Op::Load, n.op == Op::Fall,
                          n.op == Op::Rise});
        return static_cast<std::int32_t>(tests_.size()) - 1;
    };
    entry_ = stack.empty() ? kFalse : layout(layout, stack.back(), kTrue, kFalse);
    // Reverse the order: the entry first.
    const auto last = static_cast<std::int32_t>(tests_.size()) - 1;
    const auto flip = [last](std::int32_t i) { return i >= 0 ? last - i : i; };
    std::reverse(tests_.begin(), tests_.end());
    for (Test& t : tests_) {
        t.onTrue = flip(t.onTrue);
        t.onFalse = flip(t.onFalse);
    }
    entry_ = flip(entry_);
}

std::vector<std::uint32_t> Expr::reads() const {
    std::vector<std::uint32_t> s;
    for (const Instr& i : code_)
        if (i.op == Op::Load || i.op == Op::Rise || i.op == Op::Fall)
            s.push_back(i.signal);
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

// Recursive descent over the text, emitting postfix code.
class ExprCompiler {
public:
    ExprCompiler(std::string_view t, const NameResolver& r) : t_(t), resolve_(r) {}

    std::optional<Expr> run(ExprError& err) {
        Expr e;
        e.text_ = std::string(t_);
        out_ = &e.code_;
        skip();
        if (atEnd())
            return fail(err, "expr.empty");
        if (!orExpr())
            return failWith(err);
        skip();
        if (!atEnd())
            return fail(err, "expr.unexpected", {std::string(1, t_[p_])});
        // Stack depth of the postfix program.
        int depth = 0, maxDepth = 0;
        for (const Expr::Instr& i : e.code_) {
            if (i.op == Expr::Op::And || i.op == Expr::Op::Or)
                --depth;
            else if (i.op != Expr::Op::Not)
                ++depth;
            maxDepth = std::max(maxDepth, depth);
        }
        if (maxDepth > Expr::kMaxDepth)
            return fail(err, "expr.deep", {std::to_string(Expr::kMaxDepth)});
        e.buildTests();
        return e;
    }

private:
    static void say(ExprError& err, std::string id, std::vector<std::string> args) {
        err.message = descriptionText(profile::problem(id, args), false);
        err.id = std::move(id);
        err.args = std::move(args);
    }
    std::optional<Expr> fail(ExprError& err, std::string id, std::vector<std::string> args = {}) {
        err.column = static_cast<int>(p_) + 1;
        say(err, std::move(id), std::move(args));
        return std::nullopt;
    }
    std::optional<Expr> failWith(ExprError& err) {
        err.column = errCol_;
        say(err, errId_, errArgs_);
        return std::nullopt;
    }
    bool error(std::string id, std::vector<std::string> args, std::size_t at) {
        if (errId_.empty()) {
            errId_ = std::move(id);
            errArgs_ = std::move(args);
            errCol_ = static_cast<int>(at) + 1;
        }
        return false;
    }
    bool atEnd() const { return p_ >= t_.size(); }
    void skip() {
        while (!atEnd() && (t_[p_] == ' ' || t_[p_] == '\t'))
            ++p_;
    }
    static bool identStart(char c) {
        return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
    }
    static bool identChar(char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    }
    // A word (identifier or Z-address) at p_, without consuming it.
    std::string_view peekWord() const {
        std::size_t q = p_;
        if (q >= t_.size() || !identStart(t_[q]))
            return {};
        while (q < t_.size() && identChar(t_[q]))
            ++q;
        // Z<digits>.<digits>
        if (t_[p_] == 'Z' && q > p_ + 1 && q < t_.size() && t_[q] == '.') {
            bool digits = true;
            for (std::size_t i = p_ + 1; i < q; ++i)
                digits = digits && std::isdigit(static_cast<unsigned char>(t_[i]));
            if (digits) {
                std::size_t r = q + 1;
                while (r < t_.size() && std::isdigit(static_cast<unsigned char>(t_[r])))
                    ++r;
                if (r > q + 1)
                    q = r;
            }
        }
        return t_.substr(p_, q - p_);
    }
    bool keyword(std::string_view w) {
        skip();
        if (peekWord() == w) {
            p_ += w.size();
            return true;
        }
        return false;
    }
    bool symbol(char c) {
        skip();
        if (!atEnd() && t_[p_] == c) {
            ++p_;
            return true;
        }
        return false;
    }
    void emit(Expr::Op op, std::uint32_t s = 0) { out_->push_back({op, s}); }

    bool orExpr() {
        if (!andExpr())
            return false;
        while (true) {
            if (symbol('|') || keyword("or")) {
                if (!andExpr())
                    return false;
                emit(Expr::Op::Or);
            } else {
                return true;
            }
        }
    }
    bool andExpr() {
        if (!unary())
            return false;
        while (true) {
            if (symbol('&') || keyword("and")) {
                if (!unary())
                    return false;
                emit(Expr::Op::And);
            } else {
                return true;
            }
        }
    }
    bool unary() {
        if (symbol('!') || keyword("not")) {
            if (!unary())
                return false;
            emit(Expr::Op::Not);
            return true;
        }
        return primary();
    }
    bool name(Expr::Op op) {
        skip();
        const std::size_t at = p_;
        const std::string_view w = peekWord();
        if (w.empty())
            return atEnd() ? error("expr.name-missing", {}, at)
                           : error("expr.name-expected", {std::string(1, t_[p_])}, at);
        if (w == "true" || w == "false" || w == "and" || w == "or" || w == "not" || w == "rise" ||
            w == "fall")
            return error("expr.keyword", {std::string(w)}, at);
        const auto s = resolve_(w);
        if (!s)
            return error("plc.unknown-signal", {std::string(w)}, at);
        p_ += w.size();
        emit(op, *s);
        return true;
    }
    bool primary() {
        skip();
        const std::size_t at = p_;
        if (symbol('(')) {
            if (!orExpr())
                return false;
            if (!symbol(')'))
                return error("expr.paren", {}, p_);
            return true;
        }
        if (atEnd())
            return error("expr.early", {}, at);
        for (const auto& [word, op] : {std::pair{std::string_view("rise"), Expr::Op::Rise},
                                       std::pair{std::string_view("fall"), Expr::Op::Fall}}) {
            if (peekWord() == word) {
                p_ += word.size();
                if (!symbol('('))
                    return error("expr.needs-paren", {std::string(word)}, p_);
                if (!name(op))
                    return false;
                if (!symbol(')'))
                    return error("expr.paren-after", {std::string(word)}, p_);
                return true;
            }
        }
        if (keyword("true")) {
            emit(Expr::Op::True);
            return true;
        }
        if (keyword("false")) {
            emit(Expr::Op::False);
            return true;
        }
        return name(Expr::Op::Load);
    }

    std::string_view t_;
    const NameResolver& resolve_;
    std::size_t p_ = 0;
    std::vector<Expr::Instr>* out_ = nullptr;
    std::string errId_;
    std::vector<std::string> errArgs_;
    int errCol_ = 0;
};

std::optional<Expr> compileExpr(std::string_view text, const NameResolver& resolve,
                                ExprError& error) {
    ExprCompiler c(text, resolve);
    return c.run(error);
}

} // namespace k528::plc
