#include "plc/expression.h"

#include <algorithm>
#include <cctype>

namespace k528::plc {

bool Expr::eval(const std::uint8_t* now, const std::uint8_t* prev) const {
    bool stack[kMaxDepth];
    int sp = 0;
    for (const Instr& i : code_) {
        switch (i.op) {
        case Op::Load:
            stack[sp++] = now[i.signal] != 0;
            break;
        case Op::Rise:
            stack[sp++] = now[i.signal] != 0 && prev[i.signal] == 0;
            break;
        case Op::Fall:
            stack[sp++] = now[i.signal] == 0 && prev[i.signal] != 0;
            break;
        case Op::True:
            stack[sp++] = true;
            break;
        case Op::False:
            stack[sp++] = false;
            break;
        case Op::Not:
            stack[sp - 1] = !stack[sp - 1];
            break;
        case Op::And:
            --sp;
            stack[sp - 1] = stack[sp - 1] && stack[sp];
            break;
        case Op::Or:
            --sp;
            stack[sp - 1] = stack[sp - 1] || stack[sp];
            break;
        }
    }
    return sp > 0 && stack[sp - 1];
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
            return fail(err, "empty condition");
        if (!orExpr())
            return failWith(err);
        skip();
        if (!atEnd())
            return fail(err, "unexpected '" + std::string(1, t_[p_]) + "'");
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
            return fail(err, "condition nested too deeply (more than " +
                                 std::to_string(Expr::kMaxDepth) + " levels)");
        return e;
    }

private:
    std::optional<Expr> fail(ExprError& err, std::string msg) {
        err.column = static_cast<int>(p_) + 1;
        err.message = std::move(msg);
        return std::nullopt;
    }
    std::optional<Expr> failWith(ExprError& err) {
        err.column = errCol_;
        err.message = errMsg_;
        return std::nullopt;
    }
    bool error(std::string msg, std::size_t at) {
        if (errMsg_.empty()) {
            errMsg_ = std::move(msg);
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
            return error(atEnd() ? "a signal name is missing at the end"
                                 : "expected a signal name, found '" + std::string(1, t_[p_]) + "'",
                         at);
        if (w == "true" || w == "false" || w == "and" || w == "or" || w == "not" || w == "rise" ||
            w == "fall")
            return error("'" + std::string(w) + "' is a keyword, not a signal", at);
        const auto s = resolve_(w);
        if (!s)
            return error("unknown signal '" + std::string(w) + "'", at);
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
                return error("missing ')'", p_);
            return true;
        }
        if (atEnd())
            return error("the condition ends too early", at);
        for (const auto& [word, op] : {std::pair{std::string_view("rise"), Expr::Op::Rise},
                                       std::pair{std::string_view("fall"), Expr::Op::Fall}}) {
            if (peekWord() == word) {
                p_ += word.size();
                if (!symbol('('))
                    return error(std::string(word) + " needs a signal in parentheses: " +
                                     std::string(word) + "(name)",
                                 p_);
                if (!name(op))
                    return false;
                if (!symbol(')'))
                    return error("missing ')' after the signal of " + std::string(word), p_);
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
    std::string errMsg_;
    int errCol_ = 0;
};

std::optional<Expr> compileExpr(std::string_view text, const NameResolver& resolve,
                                ExprError& error) {
    ExprCompiler c(text, resolve);
    return c.run(error);
}

} // namespace k528::plc
