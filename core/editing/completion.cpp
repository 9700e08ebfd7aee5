#include "editing/completion.h"

#include <algorithm>
#include <string_view>

#include "catalog/rparams.h"
#include "plc/description.h"
#include "program/formatter.h"
#include "program/gfunctions.h"

namespace k528::editing {
namespace {

constexpr util::CatalogText kTexts[] = {
    {"completion.on-axis", "%1 (ось %2)", "%1 (axis %2)"},
    {"completion.m-stop", "останов до «Пуск»", "stop until CYCLE START"},
    {"completion.m-end-program", "конец программы", "end of program"},
    {"completion.m-end-subprogram", "конец подпрограммы", "end of subprogram"},
    {"completion.r-user", "параметр пользователя", "user parameter"},
    {"completion.r-reserved", "резерв", "reserved"},
    {"completion.r-reserved-read-only", "резерв (только чтение)", "reserved (read only)"},
    {"completion.r-read-only", "%1 (только чтение)", "%1 (read only)"},
    {"completion.program", "программа %1", "program %1"},
};

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }

// One text shown as it is in both languages.
CompletionWords both(std::string text) { return {text, std::move(text)}; }

CompletionWords words(std::string_view ru, std::string_view en) { return {std::string(ru), std::string(en)}; }

CompletionItem item(CompletionKind kind, std::string word, std::string detailId,
                    std::vector<CompletionWords> detailArgs, int group = 0) {
    return {kind, std::move(word), std::move(detailId), std::move(detailArgs), group};
}

} // namespace

util::TextCatalog completionTexts() { return util::TextCatalog(kTexts); }

std::vector<std::string> CompletionItem::detailArgsIn(bool russian) const {
    std::vector<std::string> out;
    out.reserve(detailArgs.size());
    for (const CompletionWords& w : detailArgs)
        out.push_back(w.in(russian));
    return out;
}

std::string CompletionItem::detail(bool russian) const {
    if (detailId.empty())
        return detailArgs.empty() ? std::string() : detailArgs.front().in(russian);
    return completionTexts().render(detailId, detailArgsIn(russian), russian);
}

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
        const CompletionWords meaning = words(program::gMeaningRu(info.function), program::gMeaningEn(info.function));
        CompletionItem it = item(CompletionKind::G, "G" + std::to_string(g), "", {meaning}, static_cast<int>(info.group));
        if (info.axis != program::Axis::None) {
            it.detailId = "completion.on-axis";
            it.detailArgs.push_back(both(info.axis == program::Axis::X ? "X" : "Z"));
        }
        out.push_back(std::move(it));
    }
    // Built-in M's (program-language.md), then the machine's PLC M-codes.
    struct BuiltIn {
        int m;
        const char* text; // an id of completionTexts()
    };
    static const BuiltIn kBuiltIn[] = {
        {program::mfunc::kStop, "completion.m-stop"},
        {program::mfunc::kEnd, "completion.m-end-program"},
        {program::mfunc::kSubprogramEnd, "completion.m-end-subprogram"},
        {program::mfunc::kEndRewind, "completion.m-end-program"},
    };
    std::vector<int> seenM;
    for (const BuiltIn& b : kBuiltIn) {
        out.push_back(item(CompletionKind::M, "M" + std::to_string(b.m), b.text, {}));
        seenM.push_back(b.m);
    }
    if (ctx.machine) {
        std::vector<plc::MFunctionDef> ms = ctx.machine->mFunctions;
        std::sort(ms.begin(), ms.end(), [](const auto& a, const auto& b) { return a.m < b.m; });
        for (const plc::MFunctionDef& m : ms) {
            if (m.textRu.empty() || std::find(seenM.begin(), seenM.end(), m.m) != seenM.end())
                continue;
            out.push_back(item(CompletionKind::M, "M" + std::to_string(m.m), "", {words(m.textRu, m.textEn)}));
            seenM.push_back(m.m);
        }
    }
    for (int r = 0; r < catalog::kRParamCount; ++r) {
        const catalog::RParamDef& d = catalog::rParam(r);
        std::string word = "R" + std::to_string(r);
        if (d.user())
            out.push_back(item(CompletionKind::R, std::move(word), "completion.r-user", {}, d.group));
        else if (d.meaningRu.empty())
            out.push_back(item(CompletionKind::R, std::move(word),
                               d.readOnly() ? "completion.r-reserved-read-only" : "completion.r-reserved", {}, d.group));
        else
            out.push_back(item(CompletionKind::R, std::move(word), d.readOnly() ? "completion.r-read-only" : "",
                               {words(d.meaningRu, d.meaningEn.empty() ? d.meaningRu : d.meaningEn)}, d.group));
    }
    if (ctx.store) {
        for (const program::Program& p : ctx.store->programs()) {
            const std::string title = p.title.value_or("");
            out.push_back(title.empty() ? item(CompletionKind::Call, "L" + std::to_string(p.number), "completion.program",
                                               {both(std::to_string(p.number))})
                                        : item(CompletionKind::Call, "L" + std::to_string(p.number), "", {both(title)}));
        }
        if (const program::Program* p = ctx.store->find(ctx.currentProgram)) {
            for (const program::Frame& f : p->frames) {
                if (f.number() == 0 || p->indexOfN(f.number()) < 0)
                    continue;
                out.push_back(item(CompletionKind::JumpTarget, std::to_string(f.number()), "",
                                   {both(program::formatFrame(f))}));
            }
        }
        for (const program::Message& m : ctx.store->messages.entries)
            out.push_back(item(CompletionKind::Message, "#" + std::to_string(m.number), "", {both(m.text)}));
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
