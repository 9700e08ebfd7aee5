// Seeded generator of random program stores, for the round-trip tests and
// the benchmarks. Deterministic on every platform (own PRNG, no <random>
// distributions). Everything it builds is what the parser can read back
// exactly: frames, comments, blank lines and messages in canonical shape.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "program/gfunctions.h"
#include "program/model.h"

namespace k528::program::testing {

class Rng {
public:
    explicit Rng(std::uint64_t seed) : s_(seed ? seed : 0x9E3779B97F4A7C15ULL) {}
    std::uint64_t next() { // splitmix64
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    // 0..n-1
    int below(int n) { return n <= 0 ? 0 : static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    int range(int lo, int hi) { return lo + below(hi - lo + 1); }
    bool chance(int percent) { return below(100) < percent; }

private:
    std::uint64_t s_;
};

struct GeneratorOptions {
    bool comments = true;      // comments and blank lines
    bool validOnly = false;    // only frames the validator accepts (in-range values, known G)
    int maxFrameNumber = 999;
};

class ProgramGenerator {
public:
    explicit ProgramGenerator(std::uint64_t seed, GeneratorOptions options = {})
        : rng_(seed), opt_(options) {}

    Rng& rng() { return rng_; }

    // Up to maxIntDigits digits before the point and maxScale after it.
    Decimal decimal(int maxIntDigits, int maxScale) {
        const int scale = rng_.range(0, maxScale);
        std::int64_t m = 0;
        const int digits = rng_.range(1, maxIntDigits + scale);
        for (int i = 0; i < digits; ++i)
            m = m * 10 + rng_.below(10);
        if (rng_.chance(40))
            m = -m;
        return Decimal::fromScaled(m, scale);
    }

    std::string commentText(bool parens) {
        static const char* words[] = {"подвод", "черновой проход", "rough", "finish", "R=2.5", "Ø40",
                                      "x;y", "#1", "N10", "G04 X1", "резец T1", "..."};
        std::string s = rng_.chance(50) ? " " : "";
        const int n = rng_.range(1, 3);
        for (int i = 0; i < n; ++i) {
            if (i)
                s += ' ';
            s += words[rng_.below(12)];
        }
        if (parens && rng_.chance(20))
            s += " ";
        return s;
    }

    Comment comment(bool allowSemicolon) {
        Comment c;
        c.style = allowSemicolon && rng_.chance(50) ? Comment::Style::Semicolon : Comment::Style::Parens;
        c.text = commentText(c.style == Comment::Style::Parens);
        return c;
    }

    // Comment lines, optionally with single blank lines between them.
    std::vector<TriviaLine> trivia(int maxLines, bool blankFirst, bool blankLast) {
        std::vector<TriviaLine> lines;
        if (!opt_.comments)
            return lines;
        const int n = rng_.below(maxLines + 1);
        for (int i = 0; i < n; ++i) {
            const bool blank = rng_.chance(30);
            if (blank) {
                if ((lines.empty() && !blankFirst) || (!lines.empty() && lines.back().blank()))
                    continue;
                lines.emplace_back();
                continue;
            }
            TriviaLine t;
            const int c = rng_.range(1, 2);
            for (int k = 0; k < c; ++k)
                t.comments.push_back(comment(k == c - 1));
            lines.push_back(std::move(t));
        }
        if (!blankLast)
            while (!lines.empty() && lines.back().blank())
                lines.pop_back();
        return lines;
    }

    Value value(bool feed) {
        if (rng_.chance(10)) {
            Value v = Value::rParam(rng_.below(opt_.validOnly ? 150 : 300));
            return v;
        }
        if (feed) {
            Decimal d = decimal(4, 3);
            if (d.mantissa < 0)
                d.mantissa = -d.mantissa;
            if (d.isZero())
                d = Decimal::fromInt(1);
            return Value::lit(d);
        }
        return Value::lit(decimal(4, 3));
    }

    Word word(int lo, int hi) {
        Word w;
        w.number = rng_.range(lo, hi);
        return w;
    }

    IsoFrame iso() {
        IsoFrame f;
        static const int valid[] = {0, 1, 4, 50, 51, 52, 53, 54, 55, 90, 91, 110, 210, 136, 137, 138,
                                    139, 236, 237, 238, 239, 156, 256, 180, 181, 280, 281, 192, 292};
        const int gCount = rng_.below(4);
        for (int i = 0; i < gCount; ++i)
            f.g.push_back({opt_.validOnly ? valid[rng_.below(29)] : rng_.range(0, 400), {}});
        if (opt_.validOnly) { // keep one G of a group, and leave out the ones needing a value
            IsoFrame clean;
            for (const Word& w : f.g) {
                bool dup = false;
                for (const Word& o : clean.g)
                    dup |= classifyGroup(o.number) == classifyGroup(w.number);
                const int fn = w.number % 100;
                if (!dup && w.number != 4 && fn != 36 && fn != 37 && fn != 38 && fn != 39 && fn != 81 &&
                    fn != 92)
                    clean.g.push_back(w);
            }
            f.g = clean.g;
        }
        const int mCount = rng_.below(4);
        for (int i = 0; i < mCount; ++i) {
            int m = rng_.range(0, opt_.validOnly ? 99 : 150);
            if (opt_.validOnly && (m == 2 || m == 17 || m == 30))
                m = 8;
            f.m.push_back({m, {}});
        }
        if (rng_.chance(10))
            f.message = word(1, opt_.validOnly ? 99 : 120);
        const bool call = !opt_.validOnly && rng_.chance(5);
        if (call)
            f.call = word(1, 99);
        if (rng_.chance(60) && !(opt_.validOnly && call))
            f.x = value(false);
        if (rng_.chance(40))
            f.fx = value(true);
        if (rng_.chance(60) && !(opt_.validOnly && call))
            f.z = value(false);
        if (rng_.chance(40))
            f.fz = value(true);
        return f;
    }

    Frame frame(const std::vector<int>& numbers) {
        Frame f;
        f.skip = rng_.chance(5);
        int kind = rng_.below(100);
        if (kind >= 88 && numbers.empty())
            kind = 80; // no frame number to jump to: a computational frame
        if (kind < 70) {
            f.body = iso();
        } else if (kind < 88) {
            ComputeFrame c;
            c.target = word(0, opt_.validOnly ? 231 : 299);
            auto operand = [&]() {
                return rng_.chance(50) ? Operand::rParam(rng_.below(300))
                                       : Operand::lit(static_cast<std::int32_t>(rng_.range(-100000, 100000)));
            };
            c.a = operand();
            c.op = static_cast<ArithOp>(rng_.below(5));
            if (c.op != ArithOp::None) {
                c.b = operand();
                if (c.op == ArithOp::Div && !c.b.isR() && c.b.literal == 0)
                    c.b.literal = 7;
                if (opt_.validOnly && !c.a.isR() && !c.b.isR())
                    c.b = Operand::rParam(5);
            }
            f.body = c;
        } else if (kind < 96) {
            IfGotoFrame j;
            j.r = word(0, 299);
            j.target.number = numbers[static_cast<std::size_t>(rng_.below(static_cast<int>(numbers.size())))];
            f.body = j;
        } else {
            GotoFrame j;
            j.target.number = numbers[static_cast<std::size_t>(rng_.below(static_cast<int>(numbers.size())))];
            f.body = j;
        }
        // Never an empty frame: it would read back as a blank line.
        if (const auto i = f.iso(); i && i->empty() && !f.skip)
            f.body = [&] { IsoFrame e = *f.iso(); e.m.push_back({0, {}}); return e; }();
        if (opt_.comments && rng_.chance(15)) {
            const int c = rng_.range(1, 2);
            for (int k = 0; k < c; ++k)
                f.comments.push_back(comment(k == c - 1));
        }
        return f;
    }

    // A program of `frames` frames; about half of them numbered (N ascending
    // by 1..3, unique), jumps only to existing numbers.
    Program program(int number, int frames, bool header = true) {
        Program p;
        p.number = number;
        if (header && opt_.comments) {
            if (rng_.chance(60))
                p.title = commentText(true);
            if (rng_.chance(20))
                p.headerComments.push_back({Comment::Style::Semicolon, commentText(false)});
            p.leading = trivia(2, false, false);
            for (auto it = p.leading.begin(); it != p.leading.end();)
                it = it->blank() ? p.leading.erase(it) : it + 1;
        }
        std::vector<int> numbers;
        int n = 0;
        std::vector<bool> numbered(static_cast<std::size_t>(frames));
        for (int i = 0; i < frames; ++i) {
            if (rng_.chance(50) && n + 3 <= opt_.maxFrameNumber) {
                n += rng_.range(1, 3);
                numbers.push_back(n);
                numbered[static_cast<std::size_t>(i)] = true;
            }
        }
        int k = 0;
        for (int i = 0; i < frames; ++i) {
            Frame f = frame(numbers);
            if (numbered[static_cast<std::size_t>(i)])
                f.n = Word{numbers[static_cast<std::size_t>(k++)], {}};
            if (opt_.comments && rng_.chance(10))
                f.leading = trivia(2, !(i == 0 && !header), false);
            p.frames.push_back(std::move(f));
        }
        if (header)
            p.trailing = trivia(2, true, false);
        p.reindex();
        return p;
    }

    ProgramStore store(int programs, int frames) {
        ProgramStore s;
        if (opt_.comments)
            s.preamble = trivia(3, false, false);
        for (int i = 1; i <= programs; ++i)
            s.insert(program(i, frames));
        if (opt_.comments && rng_.chance(70)) {
            s.messages.present = true;
            for (int k = 1; k <= 99; ++k) {
                if (!rng_.chance(20))
                    continue;
                Message m;
                m.number = k;
                m.text = rng_.chance(50) ? "ПРАВКА КРУГА" : "  rough pass " + std::to_string(k);
                m.leading = trivia(1, true, false);
                s.messages.entries.push_back(std::move(m));
            }
        }
        return s;
    }

private:
    Rng rng_;
    GeneratorOptions opt_;

    static int classifyGroup(int g) {
        const GInfo i = classifyG(g);
        return i.known() ? groupNumber(i.group) : 1000 + g;
    }
};

} // namespace k528::program::testing
