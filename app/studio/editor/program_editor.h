// One program file in a QScintilla editor: line numbers, a
// margin for breakpoints and the executing frame, folding by %L program and
// %MESSAGES, colours from core's tokenizer (ProgramLexer), and live
// validation — debounced, on a worker thread so typing never waits — by
// core's one validator (program::check, or engine::checkFileForMachine
// when a machine is chosen, as `k528 check --profile`). Diagnostics become
// squiggles on their exact column span and hover text «[Mnn] text»;
// completion of G, M, R, L, jump targets and #k comes from core's catalog.
// The prove-out's findings on the file's lines (setProveoutFindings): a red
// box on the line and the finding's text in the same hover.
#pragma once

#include "program/diagnostic.h"
#include "program/model.h"
#include "profile/profile.h"

#include <Qsci/qsciscintilla.h>
#include <QTimer>
#include <memory>
#include <optional>
#include <vector>

namespace k528::proveout {
struct Finding;
}
namespace k528::plc {
struct MachineDescription;
}

namespace k528::studio {

class ProgramLexer;

class ProgramEditor : public QsciScintilla {
    Q_OBJECT
public:
    static constexpr int kDebounceMs = 150;
    static constexpr int kBreakpointMarker = 0;
    static constexpr int kExecutingMarker = 1;
    static constexpr int kExecutingLineMarker = 2; // the executing line's background
    static constexpr int kErrorIndicator = 8;
    static constexpr int kWarningIndicator = 9;
    static constexpr int kProveoutIndicator = 10; // a red box on a finding's line

    explicit ProgramEditor(QWidget* parent = nullptr);
    ~ProgramEditor() override;

    // The machine the file is for: its limits, feeds and axes are checked
    // too, over the programs it holds; its PLC's M-codes are completed with
    // the built-in ones. nullopt = the language only.
    void setMachine(std::optional<profile::MachineProfile> machine, program::ProgramStore machinePrograms = {});
    bool hasMachine() const { return machine_.has_value(); }
    const std::optional<profile::MachineProfile>& machine() const { return machine_; }

    // The whole text replaced (a file opened or reloaded); Scintilla's
    // buffers get room to grow (see kGrowthRoom).
    void setText(const QString& text) override;

    // Validates now, on this thread (tests, benchmarks, before sending).
    void validateNow();
    // The diagnostics of the last validation, and the store it read.
    const std::vector<program::Diagnostic>& diagnostics() const { return diagnostics_; }
    const program::ProgramStore& store() const { return store_; }
    int validations() const { return validations_; }

    // Document positions of a diagnostic's span.
    std::pair<int, int> spanPositions(const program::Diagnostic& d) const;
    // The prove-out's findings of this file (proveout_pane.h): those of
    // its own programs are kept, their lines boxed in red; the others (a
    // program of the machine the file calls) have no line here.
    void setProveoutFindings(const std::vector<proveout::Finding>& findings);
    const std::vector<proveout::Finding>& proveoutFindings() const { return findings_; }
    // Text of the diagnostics covering `position`, and of the findings on
    // its line when it is boxed ("" if none).
    QString hoverText(int position) const;
    // The program (%L number) the 0-based line is in, 0 if none.
    int programAtLine(int line) const;

    // Breakpoints: 0-based lines with the marker.
    QList<int> breakpointLines() const;
    void toggleBreakpoint(int line);
    void setExecutingLine(int line); // -1 = none

    // The input method's questions about the text around the caret, answered
    // from the caret's line (a «paragraph» of the input method is a line of
    // a program). QScintilla's own answer counts the characters from the
    // previous blank line — in a program without blank lines from the start
    // of the file — after every key and repaint: 30 ms deep in a 2.9 MB file.
    QVariant inputMethodQuery(Qt::InputMethodQuery query) const override;

signals:
    void validated(); // diagnostics() and store() are new
    void breakpointsChanged(); // a breakpoint was set or cleared

private:
    struct Result;
    void scheduleValidation();
    void startValidation();
    // Takes a validation's result. The squiggles of the lines on screen are
    // drawn at once, the others (all when `all`) in slices of kSquiggleSlice
    // between events, so that 9000 diagnostics never hold the event loop.
    void apply(Result&& r, bool all);
    void drawSquiggles(std::size_t from, std::size_t to);
    void drawNextSlice();
    static constexpr std::size_t kSquiggleSlice = 1000;
    // The document's bytes (UTF-8), copied without a detour through QString
    // into a buffer kept for the next validation.
    QByteArray documentBytes() const;
    // Room for typing given to Scintilla's buffers (text and styles) when a
    // text is set: a fraction of the text, at least kGrowthRoomMin bytes.
    // Scintilla itself grows a buffer filled by SCI_SETTEXT by 8 bytes at
    // first, so the 8th key typed would copy a 2.9 MB text and its styles
    // into new, never-touched memory (20-30 ms on a VM whose page faults are
    // slow); with the room it never grows while someone types.
    static constexpr int kGrowthRoomDivisor = 4;
    static constexpr int kGrowthRoomMin = 64 * 1024;
    void charAdded(int ch);
    void completionChosen(int id, const QString& text);
    void dwellStart(int position, int x, int y);

    ProgramLexer* lexer_ = nullptr;
    QTimer debounce_;
    std::optional<profile::MachineProfile> machine_;
    // The description of machine_'s PLC (its M-codes for completion); null
    // without a machine or when it cannot be read (the check says why).
    std::shared_ptr<const plc::MachineDescription> description_;
    program::ProgramStore machinePrograms_;
    std::vector<program::Diagnostic> diagnostics_;
    std::vector<std::pair<int, int>> diagnosticPositions_;
    std::vector<proveout::Finding> findings_;
    program::ProgramStore store_;
    std::uint64_t generation_ = 0;
    std::uint64_t applied_ = 0;        // counts apply(): a slice of an older one stops
    std::size_t squiggledTo_ = 0;      // diagnostics [0, squiggledTo_) have their squiggles
    bool workerBusy_ = false;
    bool pendingAgain_ = false;
    bool changePending_ = false; // textChanged() is queued
    int validations_ = 0;
    int executingLine_ = -1;
    std::shared_ptr<bool> alive_;
    mutable QByteArray snapshot_; // documentBytes()'s buffer, reused when no worker holds it
};

} // namespace k528::studio
