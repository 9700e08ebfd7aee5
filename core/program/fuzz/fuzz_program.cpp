// libFuzzer target: any bytes through the parser, the validator (whole
// store and program by program) and the formatter. Checks, besides "no
// crash, no hang, no sanitizer report":
//  - a text the parser accepts formats to a text it accepts again, with the
//    same programs and frames (canonical frame text and comments equal);
//  - format is a fixed point: format(parse(format(x))) == format(x);
//  - format never changes what `k528 run` starts by default: the first
//    program in written order is the same number with the same frames;
//  - validateProgram over every program gives what validate gives;
//  - every message is valid UTF-8 (input text is quoted escaped).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "program/formatter.h"
#include "program/diagnostic_texts.h"
#include "program/parser.h"
#include "program/validator.h"
#include "util/utf8.h"

using namespace k528::program;

namespace {

void require(bool ok) {
    if (!ok)
        std::abort();
}

void sameStore(const ProgramStore& a, const ProgramStore& b) {
    require(a.numbers() == b.numbers());
    for (const Program& p : a.programs()) {
        const Program* q = b.find(p.number);
        require(q != nullptr);
        require(p.frames.size() == q->frames.size());
        require(p.title == q->title);
        for (std::size_t i = 0; i < p.frames.size(); ++i) {
            require(formatFrame(p.frames[i]) == formatFrame(q->frames[i]));
            require(p.frames[i].comments == q->frames[i].comments);
        }
    }
    require(a.messages.entries.size() == b.messages.entries.size());
    for (const Message& m : a.messages.entries) {
        const Message* n = b.messages.find(m.number);
        require(n != nullptr && n->text == m.text);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    ParseOptions po;
    po.programNumber = size > 0 ? 1 + data[0] % kMaxPrograms : 1;
    const ParseResult parsed = parse(text, po);
    for (const Diagnostic& d : parsed.diagnostics) {
        require(d.line >= 1 && d.column >= 1 && d.endColumn > d.column);
        require(k528::utf8::isValid(k528::program::diagnosticText(d, true)) && k528::utf8::isValid(k528::program::diagnosticText(d, false)));
    }

    ValidateOptions vo;
    if (size > 1 && (data[1] & 1)) {
        MachineLimits m;
        m.x.softLimits = true;
        m.x.minMm = Decimal::fromInt(-100);
        m.x.maxMm = Decimal::fromScaled(2500005, 4);
        m.x.maxFeedMmPerMin = Decimal::fromInt(5000);
        m.x.decimals = 3;
        m.x.diameter = true;
        m.z.present = (data[1] & 2) != 0;
        m.z.decimals = 2;
        vo.machine = m;
        vo.nestingLimit = 1 + data[1] % 9;
    }
    const auto all = validate(parsed.store, vo);
    for (const Diagnostic& d : all)
        require(k528::utf8::isValid(k528::program::diagnosticText(d, true)) && k528::utf8::isValid(k528::program::diagnosticText(d, false)));
    const CallGraph graph(parsed.store);
    std::size_t perProgram = 0;
    for (const Program& p : parsed.store.programs())
        perProgram += validateProgram(parsed.store, p.number, graph, vo).size();
    require(perProgram + validateMessages(parsed.store.messages).size() == all.size());

    if (!parsed.hasErrors()) {
        const std::string once = format(parsed.store);
        const ParseResult again = parse(once, po);
        require(!again.hasErrors());
        sameStore(parsed.store, again.store);
        const int first = parsed.store.firstWritten();
        require(again.store.firstWritten() == first);
        if (first > 0) {
            const Program* a = parsed.store.find(first);
            const Program* b = again.store.find(first);
            require(a && b && a->frames.size() == b->frames.size());
            for (std::size_t i = 0; i < a->frames.size(); ++i)
                require(formatFrame(a->frames[i]) == formatFrame(b->frames[i]));
        }
        require(format(again.store) == once);
    }
    return 0;
}
