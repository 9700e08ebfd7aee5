#include "editing/completion.h"

#include <algorithm>

#include "catalog/rparams.h"
#include "plc/description.h"
#include "program/formatter.h"
#include "program/gfunctions.h"

namespace k528::editing {
namespace {

using program::Axis;

std::string axisSuffixRu(Axis a) { return a == Axis::X ? " (ось X)" : a == Axis::Z ? " (ось Z)" : ""; }
std::string axisSuffixEn(Axis a) { return a == Axis::X ? " (axis X)" : a == Axis::Z ? " (axis Z)" : ""; }

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }

} // namespace

std::vector<int> knownGNumbers() {
    std::vector<int> out;
    for (int g = 0; g <= program::kMaxG; ++g)
        if (program::classifyG(g).known())
            out.push_back(g);
    return out;
}

std::vector<CompletionItem> completionCatalog(const CompletionContext& ctx) {
    std::vector<CompletionItem> out;
    for (int g : knownGNumbers()) {
        const program::GInfo info = program::classifyG(g);
        CompletionItem it;
        it.kind = CompletionKind::G;
        it.word = "G" + std::to_string(g);
        it.group = static_cast<int>(info.group);
        it.detailRu = std::string(program::gMeaningRu(info.function)) + axisSuffixRu(info.axis);
        it.detailEn = std::string(program::gMeaningEn(info.function)) + axisSuffixEn(info.axis);
        out.push_back(std::move(it));
    }
    // Built-in M's (program-language.md), then the machine's PLC M-codes.
    struct BuiltIn {
        int m;
        const char* ru;
        const char* en;
    };
    static const BuiltIn kBuiltIn[] = {
        {program::mfunc::kStop, "останов до «Пуск»", "stop until «Пуск» (START)"},
        {program::mfunc::kEnd, "конец программы", "end of program"},
        {program::mfunc::kSubprogramEnd, "конец подпрограммы", "end of subprogram"},
        {program::mfunc::kEndRewind, "конец программы", "end of program"},
    };
    std::vector<int> seenM;
    for (const BuiltIn& b : kBuiltIn) {
        out.push_back({CompletionKind::M, "M" + std::to_string(b.m), b.ru, b.en, 0});
        seenM.push_back(b.m);
    }
    if (ctx.machine) {
        std::vector<plc::MFunctionDef> ms = ctx.machine->mFunctions;
        std::sort(ms.begin(), ms.end(), [](const auto& a, const auto& b) { return a.m < b.m; });
        for (const plc::MFunctionDef& m : ms) {
            if (m.text.empty() || std::find(seenM.begin(), seenM.end(), m.m) != seenM.end())
                continue;
            // The description names it in English only: both languages show it.
            out.push_back({CompletionKind::M, "M" + std::to_string(m.m), m.text, m.text, 0});
            seenM.push_back(m.m);
        }
    }
    for (int r = 0; r < catalog::kRParamCount; ++r) {
        const catalog::RParamDef& d = catalog::rParam(r);
        CompletionItem it;
        it.kind = CompletionKind::R;
        it.word = "R" + std::to_string(r);
        it.group = d.group;
        if (d.user()) {
            it.detailRu = "параметр пользователя";
            it.detailEn = "user parameter";
        } else {
            it.detailRu = d.meaningRu.empty() ? "зарезервирован" : std::string(d.meaningRu);
            it.detailEn = d.meaningEn.empty() ? "reserved" : std::string(d.meaningEn);
            if (d.readOnly()) {
                it.detailRu += " (только чтение)";
                it.detailEn += " (read only)";
            }
        }
        out.push_back(std::move(it));
    }
    if (ctx.store) {
        for (const program::Program& p : ctx.store->programs()) {
            const std::string title = p.title.value_or("");
            out.push_back({CompletionKind::Call, "L" + std::to_string(p.number),
                           title.empty() ? "программа " + std::to_string(p.number) : title,
                           title.empty() ? "program " + std::to_string(p.number) : title, 0});
        }
        if (const program::Program* p = ctx.store->find(ctx.currentProgram)) {
            for (const program::Frame& f : p->frames) {
                if (f.number() == 0 || p->indexOfN(f.number()) < 0)
                    continue;
                const std::string text = program::formatFrame(f);
                out.push_back({CompletionKind::JumpTarget, std::to_string(f.number()), text, text, 0});
            }
        }
        for (const program::Message& m : ctx.store->messages.entries)
            out.push_back({CompletionKind::Message, "#" + std::to_string(m.number), m.text, m.text, 0});
    }
    return out;
}

std::vector<CompletionItem> complete(const std::vector<CompletionItem>& catalog, CompletionKind kind,
                                     const std::string& prefix) {
    std::vector<CompletionItem> out;
    for (const CompletionItem& it : catalog) {
        if (it.kind != kind || it.word.size() < prefix.size())
            continue;
        bool match = true;
        for (std::size_t i = 0; i < prefix.size() && match; ++i)
            match = upper(it.word[i]) == upper(prefix[i]);
        if (match)
            out.push_back(it);
    }
    return out;
}

} // namespace k528::editing
