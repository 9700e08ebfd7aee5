#include "program/formatter.h"

#include <algorithm>

namespace k528::program {

namespace {

void appendInt(std::string& out, long long v) {
    char buf[24];
    int n = 0;
    const bool negative = v < 0;
    unsigned long long u = negative ? 0ULL - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
    do {
        buf[n++] = static_cast<char>('0' + u % 10);
        u /= 10;
    } while (u != 0);
    if (negative)
        out += '-';
    while (n > 0)
        out += buf[--n];
}

void appendOperand(std::string& out, const Operand& o) {
    if (o.isR()) {
        out += 'R';
        appendInt(out, o.rIndex);
    } else {
        appendInt(out, o.literal);
    }
}

void appendComment(std::string& out, const Comment& c) {
    if (c.style == Comment::Style::Semicolon) {
        out += ';';
        out += c.text;
    } else {
        out += '(';
        out += c.text;
        out += ')';
    }
}

void appendComments(std::string& out, const std::vector<Comment>& comments, bool leadingSpace) {
    for (const Comment& c : comments) {
        if (leadingSpace)
            out += ' ';
        appendComment(out, c);
        leadingSpace = true;
    }
}

// Writes trivia lines with runs of blank lines collapsed to one. `atStart`:
// nothing has been written in this block yet (leading blank lines dropped);
// `dropTrailingBlank`: a blank line at the end is dropped.
class Writer {
public:
    std::string out;

    void blank() { pendingBlank_ = wrote_; }
    void line(const std::string& text) {
        if (pendingBlank_)
            out += '\n';
        pendingBlank_ = false;
        out += text;
        out += '\n';
        wrote_ = true;
    }
    void trivia(const std::vector<TriviaLine>& lines) {
        for (const TriviaLine& t : lines) {
            if (t.blank()) {
                blank();
                continue;
            }
            std::string s;
            appendComments(s, t.comments, false);
            line(s);
        }
    }
    // Starts a new section: exactly one blank line after what was written.
    void section() { pendingBlank_ = wrote_; }
    // Drops a pending blank line (end of a block).
    void endBlock() { pendingBlank_ = false; }

private:
    bool wrote_ = false;
    bool pendingBlank_ = false;
};

void writeProgram(Writer& w, const Program& p, bool header) {
    w.section();
    w.trivia(p.leading);
    if (header) {
        std::string h = "%L";
        appendInt(h, p.number);
        if (p.title) {
            h += " (";
            h += *p.title;
            h += ')';
        }
        appendComments(h, p.headerComments, true);
        w.line(h);
    }
    for (const Frame& f : p.frames) {
        w.trivia(f.leading);
        std::string s;
        appendFrame(s, f);
        appendComments(s, f.comments, !s.empty());
        w.line(s);
    }
    w.trivia(p.trailing);
    w.endBlock();
}

} // namespace

void appendValue(std::string& out, std::string_view address, const Value& v) {
    out += address;
    if (v.isR()) {
        out += "=R";
        appendInt(out, v.rIndex);
    } else {
        v.literal.appendTo(out);
    }
}

void appendFrame(std::string& out, const Frame& f) {
    const std::size_t start = out.size();
    auto sep = [&] {
        if (out.size() > start && out.back() != '/')
            out += ' ';
    };
    if (f.skip)
        out += '/';
    if (f.n) {
        out += 'N';
        appendInt(out, f.n->number);
    }
    switch (f.kind()) {
    case FrameKind::Iso: {
        const IsoFrame& iso = *f.iso();
        for (const Word& g : iso.g) {
            sep();
            out += 'G';
            appendInt(out, g.number);
        }
        for (const Word& m : iso.m) {
            sep();
            out += 'M';
            appendInt(out, m.number);
        }
        if (iso.message) {
            sep();
            out += '#';
            appendInt(out, iso.message->number);
        }
        if (iso.call) {
            sep();
            out += 'L';
            appendInt(out, iso.call->number);
        }
        if (iso.x) {
            sep();
            appendValue(out, "X", *iso.x);
        }
        if (iso.fx) {
            sep();
            appendValue(out, "FX", *iso.fx);
        }
        if (iso.z) {
            sep();
            appendValue(out, "Z", *iso.z);
        }
        if (iso.fz) {
            sep();
            appendValue(out, "FZ", *iso.fz);
        }
        break;
    }
    case FrameKind::Compute: {
        const ComputeFrame& c = *f.compute();
        sep();
        out += 'R';
        appendInt(out, c.target.number);
        out += '=';
        appendOperand(out, c.a);
        if (c.op != ArithOp::None) {
            out += arithOpChar(c.op);
            appendOperand(out, c.b);
        }
        break;
    }
    case FrameKind::IfGoto: {
        const IfGotoFrame& j = *f.ifGoto();
        sep();
        out += "IF R";
        appendInt(out, j.r.number);
        out += ">0 GOTO ";
        appendInt(out, j.target.number);
        break;
    }
    case FrameKind::Goto:
        sep();
        out += "GOTO ";
        appendInt(out, f.jumpTarget());
        break;
    }
}

std::string formatFrame(const Frame& frame) {
    std::string s;
    appendFrame(s, frame);
    return s;
}

std::string format(const ProgramStore& store) {
    Writer w;
    w.trivia(store.preamble);
    w.endBlock();
    const bool header = !(store.headerless && store.size() <= 1);
    // In the order written, not by number: `run` starts the first program of
    // a file, and formatting must not change which one that is.
    for (const Program* p : store.inWrittenOrder())
        writeProgram(w, *p, header);
    const MessageTable& t = store.messages;
    if (t.present || !t.entries.empty()) {
        w.section();
        w.trivia(t.leading);
        std::string h = "%MESSAGES";
        appendComments(h, t.headerComments, true);
        w.line(h);
        // Entries by number; each keeps the comment lines above it.
        std::vector<const Message*> sorted;
        sorted.reserve(t.entries.size());
        for (const Message& m : t.entries)
            sorted.push_back(&m);
        std::stable_sort(sorted.begin(), sorted.end(),
                         [](const Message* a, const Message* b) { return a->number < b->number; });
        for (const Message* m : sorted) {
            w.trivia(m->leading);
            std::string s = "#";
            appendInt(s, m->number);
            s += '=';
            s += m->text;
            w.line(s);
        }
        w.trivia(t.trailing);
        w.endBlock();
    }
    return w.out;
}

} // namespace k528::program
