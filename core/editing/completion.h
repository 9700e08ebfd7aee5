// The completion catalog of the program editor: what may be
// typed at a word, with its meaning. From core's own tables — table 5
// (program/gfunctions), the built-in M's, the machine description's PLC
// M-codes, appendix Л (catalog/rparams) — and from the file being edited:
// the programs that exist (L), the frame numbers of the current program
// (jump targets), its messages (#k). The completion's own words («параметр
// пользователя», «(только чтение)») are ids of completionTexts(): the
// desktop says them through its translators, anything else from here.
#pragma once

#include <string>
#include <vector>

#include "program/model.h"
#include "util/text_catalog.h"

namespace k528::plc {
struct MachineDescription;
}

namespace k528::editing {

enum class CompletionKind { G, M, R, Call, JumpTarget, Message };

// Words of two languages as core's tables hold them (table 5's meaning of a
// G, appendix Л's of an R, the machine description's M text), or one text
// shown in both (a program's title, a frame, a message).
struct CompletionWords {
    std::string ru, en;
    const std::string& in(bool russian) const { return russian ? ru : en; }
    bool operator==(const CompletionWords&) const = default;
};

struct CompletionItem {
    CompletionKind kind = CompletionKind::G;
    std::string word; // what is inserted: "G1", "M30", "R204", "L11", "120", "#3"
    // What it means: a text of completionTexts() with its arguments, or with
    // no id its one argument as it is (a meaning of table 5 or appendix Л,
    // the machine's M text, a program's title, a frame, a message).
    std::string detailId;
    std::vector<CompletionWords> detailArgs;
    int group = 0; // G: the group of table 5; R: the preset group 1..9; else 0

    // The arguments in a language, for the text's %1..%9.
    std::vector<std::string> detailArgsIn(bool russian) const;
    // «подача (ось X)», «параметр пользователя», the title …, from core's catalog.
    std::string detail(bool russian) const;
};

struct CompletionContext {
    const program::ProgramStore* store = nullptr; // the file being edited (may be null)
    int currentProgram = 0;                       // the program the cursor is in (0 = none)
    const plc::MachineDescription* machine = nullptr; // the machine chosen (may be null)
};

// The completion's own words: ids with their Russian and English.
util::TextCatalog completionTexts();

// Everything that may be completed, in the order G, M, R, L, jump targets, #.
std::vector<CompletionItem> completionCatalog(const CompletionContext& context);

// The items of one kind whose word starts with `prefix` (case-insensitive).
std::vector<CompletionItem> complete(const std::vector<CompletionItem>& catalog, CompletionKind kind,
                                     const std::string& prefix);

// Every G number of table 5 (0..299 that classifyG knows).
std::vector<int> knownGNumbers();

} // namespace k528::editing
