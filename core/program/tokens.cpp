#include "program/tokens.h"

#include <algorithm>

namespace k528::program {
namespace {

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }
bool isCont(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

struct Span {
    int column = 0, endColumn = 0;
    TokenKind kind = TokenKind::Default;
};

// One line of the text: byte range, and a column -> byte map.
struct Line {
    std::size_t begin = 0, end = 0; // without "\r\n"
    std::vector<std::size_t> colByte; // colByte[c-1] = byte of column c; one past the end too
};

class Tokenizer {
public:
    Tokenizer(std::string_view text, const ParseResult& parsed) : text_(text), parsed_(parsed) {}

    std::vector<Token> run() {
        splitLines();
        perLine_.resize(lines_.size() + 1);
        for (const Program& p : parsed_.store.programs()) {
            if (p.headerLine > 0)
                headerLine(p.headerLine);
            for (const Frame& f : p.frames)
                frame(f);
        }
        const MessageTable& mt = parsed_.store.messages;
        if (mt.present && mt.headerLine > 0)
            headerLine(mt.headerLine);
        for (const Message& m : mt.entries)
            if (m.span.line > 0) {
                add(m.span.line, m.span.column, m.textColumn, TokenKind::MessageNumber);
                add(m.span.line, m.textColumn, m.span.endColumn, TokenKind::MessageText);
            }
        std::vector<Token> out;
        for (std::size_t ln = 1; ln <= lines_.size(); ++ln)
            emitLine(static_cast<int>(ln), out);
        return out;
    }

private:
    void splitLines() {
        std::size_t pos = text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
        while (pos <= text_.size()) {
            std::size_t eol = text_.find('\n', pos);
            const bool last = eol == std::string_view::npos;
            if (last)
                eol = text_.size();
            Line l;
            l.begin = pos;
            l.end = eol;
            if (l.end > l.begin && text_[l.end - 1] == '\r')
                --l.end;
            for (std::size_t b = l.begin; b < l.end; ++b)
                if (!isCont(text_[b]))
                    l.colByte.push_back(b);
            l.colByte.push_back(l.end);
            if (!(last && l.begin == l.end && !lines_.empty()))
                lines_.push_back(std::move(l));
            if (last)
                break;
            pos = eol + 1;
        }
    }

    void add(int line, int col, int endCol, TokenKind k) {
        if (line < 1 || line > static_cast<int>(lines_.size()) || endCol <= col || col < 1)
            return;
        perLine_[static_cast<std::size_t>(line)].push_back({col, endCol, k});
    }
    void add(int line, const ColSpan& s, TokenKind k) { add(line, s.column, s.endColumn, k); }

    void headerLine(int line) {
        // "%L12" or "%MESSAGES": the word after '%'; the rest is trivia.
        const Line& l = lines_[static_cast<std::size_t>(line - 1)];
        const int cols = static_cast<int>(l.colByte.size()) - 1;
        int c = 1;
        while (c <= cols && (text_[l.colByte[c - 1]] == ' ' || text_[l.colByte[c - 1]] == '\t'))
            ++c;
        int e = c + 1;
        while (e <= cols) {
            const char ch = text_[l.colByte[e - 1]];
            if (!((ch >= '0' && ch <= '9') || (upper(ch) >= 'A' && upper(ch) <= 'Z')))
                break;
            ++e;
        }
        add(line, c, e, TokenKind::Header);
        headerLines_.push_back(line);
    }

    void value(int line, const std::optional<Value>& v, TokenKind k) {
        if (v)
            add(line, v->span, k);
    }

    void frame(const Frame& f) {
        const int line = f.span.line;
        if (line <= 0)
            return;
        if (f.n)
            add(line, f.n->span, TokenKind::FrameNumber);
        if (const auto iso = f.iso()) {
            for (const Word& g : iso->g)
                add(line, g.span, TokenKind::GWord);
            for (const Word& m : iso->m)
                add(line, m.span, TokenKind::MWord);
            if (iso->message)
                add(line, iso->message->span, TokenKind::MessageRef);
            if (iso->call)
                add(line, iso->call->span, TokenKind::Call);
            value(line, iso->x, TokenKind::AxisValue);
            value(line, iso->z, TokenKind::AxisValue);
            value(line, iso->fx, TokenKind::Feed);
            value(line, iso->fz, TokenKind::Feed);
        } else if (const auto c = f.compute()) {
            add(line, c->target.span, TokenKind::RParam);
            add(line, c->a.span, c->a.isR() ? TokenKind::RParam : TokenKind::Literal);
            if (c->op != ArithOp::None)
                add(line, c->b.span, c->b.isR() ? TokenKind::RParam : TokenKind::Literal);
        } else if (const auto j = f.ifGoto()) {
            add(line, j->r.span, TokenKind::RParam);
            add(line, j->target.span, TokenKind::JumpTarget);
        } else if (const auto g = f.gotoFrame()) {
            add(line, g->target.span, TokenKind::JumpTarget);
        }
    }

    // The gaps between the parser's words: comments by the parser's trivia
    // rules (';' to the end, '(' to ')'), keywords, operators, '/'.
    void gap(int line, int from, int to, bool header, std::vector<Span>& out) {
        const Line& l = lines_[static_cast<std::size_t>(line - 1)];
        int c = from;
        auto ch = [&](int col) { return text_[l.colByte[static_cast<std::size_t>(col - 1)]]; };
        const int cols = static_cast<int>(l.colByte.size()) - 1;
        while (c < to) {
            const char x = ch(c);
            if (x == ';') {
                out.push_back({c, cols + 1, TokenKind::Comment});
                return;
            }
            if (x == '(') {
                int e = c + 1;
                while (e <= cols && ch(e) != ')')
                    ++e;
                e = std::min(e + 1, cols + 1);
                out.push_back({c, e, header && !sawTitle_ ? TokenKind::Title : TokenKind::Comment});
                if (header)
                    sawTitle_ = true;
                c = e;
                continue;
            }
            if (upper(x) >= 'A' && upper(x) <= 'Z') {
                int e = c;
                while (e < to && upper(ch(e)) >= 'A' && upper(ch(e)) <= 'Z')
                    ++e;
                std::string w;
                for (int k = c; k < e; ++k)
                    w += upper(ch(k));
                out.push_back({c, e, (w == "IF" || w == "GOTO") ? TokenKind::Keyword : TokenKind::Default});
                c = e;
                continue;
            }
            if (x == '/' && !sawWord_) {
                out.push_back({c, c + 1, TokenKind::Skip});
            } else if (x == '=' || x == '+' || x == '-' || x == '*' || x == '/' || x == '>') {
                out.push_back({c, c + 1, TokenKind::Operator});
            }
            if (x != ' ' && x != '\t')
                sawWord_ = true;
            ++c;
        }
    }

    void emitLine(int line, std::vector<Token>& out) {
        auto& spans = perLine_[static_cast<std::size_t>(line)];
        std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.column < b.column; });
        const Line& l = lines_[static_cast<std::size_t>(line - 1)];
        const int cols = static_cast<int>(l.colByte.size()) - 1;
        const bool header = std::find(headerLines_.begin(), headerLines_.end(), line) != headerLines_.end();
        std::vector<Span> all;
        sawWord_ = false;
        sawTitle_ = false;
        int c = 1;
        for (const Span& s : spans) {
            if (s.column < c)
                continue; // overlapping: keep the first
            gap(line, c, s.column, header, all);
            if (!all.empty() && all.back().kind == TokenKind::Comment && all.back().endColumn > s.column)
                break; // a ';' comment swallowed the rest (cannot happen with parser spans)
            all.push_back(s);
            sawWord_ = true;
            c = std::min(s.endColumn, cols + 1);
        }
        if (all.empty() || all.back().kind != TokenKind::Comment || all.back().endColumn <= cols)
            gap(line, c, cols + 1, header, all);
        for (const Span& s : all) {
            if (s.kind == TokenKind::Default)
                continue;
            const int e = std::min(s.endColumn, cols + 1);
            if (e <= s.column)
                continue;
            Token t;
            t.line = line;
            t.column = s.column;
            t.endColumn = e;
            t.begin = l.colByte[static_cast<std::size_t>(s.column - 1)];
            t.end = l.colByte[static_cast<std::size_t>(e - 1)];
            t.kind = s.kind;
            out.push_back(t);
        }
    }

    std::string_view text_;
    const ParseResult& parsed_;
    std::vector<Line> lines_;
    std::vector<std::vector<Span>> perLine_;
    std::vector<int> headerLines_;
    bool sawWord_ = false;
    bool sawTitle_ = false;
};

} // namespace

std::vector<Token> tokensOf(std::string_view text, const ParseResult& parsed) {
    return Tokenizer(text, parsed).run();
}

TokenizeResult tokenize(std::string_view text, const ParseOptions& options) {
    TokenizeResult r;
    r.parse = parse(text, options);
    r.tokens = tokensOf(text, r.parse);
    return r;
}

const char* tokenKindName(TokenKind k) {
    static const char* const names[kTokenKindCount] = {
        "default", "comment", "header", "title", "skip", "frame-number", "g", "m", "message-ref", "call",
        "axis", "feed", "r", "literal", "keyword", "jump-target", "operator", "message-number", "message-text"};
    const auto i = static_cast<std::size_t>(k);
    return i < kTokenKindCount ? names[i] : "?";
}

} // namespace k528::program
