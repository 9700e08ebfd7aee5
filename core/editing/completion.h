// The completion catalog of the program editor: what may be
// typed at a word, with its meaning in Russian and English. From core's
// own tables — table 5 (program/gfunctions), the built-in M's, the
// machine description's PLC M-codes, appendix Л (catalog/rparams) — and
// from the file being edited: the programs that exist (L), the frame
// numbers of the current program (jump targets), its messages (#k).
#pragma once

#include <string>
#include <vector>

#include "program/model.h"

namespace k528::plc {
struct MachineDescription;
}

namespace k528::editing {

enum class CompletionKind { G, M, R, Call, JumpTarget, Message };

struct CompletionItem {
    CompletionKind kind = CompletionKind::G;
    std::string word;      // what is inserted: "G1", "M30", "R204", "L11", "120", "#3"
    std::string detailRu;  // meaning: «подача», «диаметр нового круга в дискр X», the title …
    std::string detailEn;
    int group = 0;         // G: the group of table 5; R: the preset group 1..9; else 0
};

struct CompletionContext {
    const program::ProgramStore* store = nullptr; // the file being edited (may be null)
    int currentProgram = 0;                       // the program the cursor is in (0 = none)
    const plc::MachineDescription* machine = nullptr; // the machine chosen (may be null)
};

// Everything that may be completed, in the order G, M, R, L, jump targets, #.
std::vector<CompletionItem> completionCatalog(const CompletionContext& context);

// The items of one kind whose word starts with `prefix` (case-insensitive).
std::vector<CompletionItem> complete(const std::vector<CompletionItem>& catalog, CompletionKind kind,
                                     const std::string& prefix);

// Every G number of table 5 (0..299 that classifyG knows).
std::vector<int> knownGNumbers();

} // namespace k528::editing
