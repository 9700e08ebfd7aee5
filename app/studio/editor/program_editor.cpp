#include "editor/program_editor.h"

#include "editing/completion.h"
#include "editor/completion_texts.h"
#include "session/diagnostic_texts.h"
#include "editor/program_lexer.h"
#include "engine/program_check.h"
#include "machine/simulation.h"
#include "plc/description.h"
#include "window_language.h"
#include "program/validator.h"
#include "proveout/proveout.h"
#include "session/core_texts.h"

#include <QAccessibleWidget>
#include <QCoreApplication>
#include <QFontDatabase>
#include <QPointer>
#include <QThreadPool>
#include <QToolTip>
#include <algorithm>
#include <cstring>

namespace k528::studio {

namespace {

// One validation: what the worker computes from a copy of the text.
struct Validation {
    std::vector<program::Diagnostic> diagnostics;
    program::ProgramStore store;
};

Validation validateText(const QByteArray& text, const std::optional<profile::MachineProfile>& machine,
                        const program::ProgramStore& machinePrograms) {
    const std::string_view t(text.constData(), static_cast<std::size_t>(text.size()));
    Validation v;
    if (machine) {
        engine::FileCheck c = engine::checkFileForMachine(t, {}, *machine, machinePrograms);
        v.diagnostics = std::move(c.diagnostics);
        v.store = std::move(c.parsed.store);
    } else {
        program::CheckResult c = program::check(t);
        v.diagnostics = std::move(c.diagnostics);
        v.store = std::move(c.store);
    }
    return v;
}

// QScintilla's accessible text interface answers every caret move (at each
// repaint, SCN_UPDATEUI) with the caret's character offset from the start of
// the document, counted anew each time (SCI_COUNTCHARACTERS from 0): ~30 ms
// deep in a 2.9 MB file, on the GUI thread, with or without a screen reader.
// The editor gets the plain widget interface instead (an editable text with
// its name). Qt asks the factories for the most derived class first, so
// QScintilla's factory is not asked for a ProgramEditor; ours is installed
// before the QsciScintilla part is built.
QAccessibleInterface* editorAccessible(const QString& className, QObject* object) {
    if (className == QLatin1String("k528::studio::ProgramEditor") && object && object->isWidgetType())
        return new QAccessibleWidget(static_cast<QWidget*>(object), QAccessible::EditableText);
    return nullptr;
}

QWidget* withEditorAccessible(QWidget* parent) {
    static const bool installed = [] {
        QAccessible::installFactory(editorAccessible);
        return true;
    }();
    (void)installed;
    return parent;
}

constexpr int kUserListG = 1, kUserListM = 2, kUserListR = 3, kUserListL = 4, kUserListTarget = 5,
              kUserListMessage = 6;
const QString kDetailSeparator = QStringLiteral("  — ");

} // namespace

struct ProgramEditor::Result {
    std::uint64_t generation = 0;
    Validation v;
};

ProgramEditor::ProgramEditor(QWidget* parent) : QsciScintilla(withEditorAccessible(parent)), alive_(std::make_shared<bool>(true)) {
    setObjectName("programEditor");
    setUtf8(true);
    lexer_ = new ProgramLexer(this);
    setLexer(lexer_);
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    setMarginsFont(mono);
    // Margin 0: line numbers; 1: breakpoints and the executing frame; 2: folding.
    setMarginType(0, NumberMargin);
    setMarginWidth(0, "99999");
    setMarginLineNumbers(0, true);
    setMarginType(1, SymbolMargin);
    setMarginWidth(1, 16);
    setMarginSensitivity(1, true);
    setMarginMarkerMask(1, (1 << kBreakpointMarker) | (1 << kExecutingMarker));
    markerDefine(Circle, kBreakpointMarker);
    setMarkerBackgroundColor(QColor(0xd0, 0x20, 0x20), kBreakpointMarker);
    setMarkerForegroundColor(QColor(0x80, 0x00, 0x00), kBreakpointMarker);
    markerDefine(RightArrow, kExecutingMarker);
    setMarkerBackgroundColor(QColor(0xf0, 0xc0, 0x00), kExecutingMarker);
    markerDefine(Background, kExecutingLineMarker);
    setMarkerBackgroundColor(QColor(0xff, 0xf0, 0xa0), kExecutingLineMarker);
    setFolding(BoxedTreeFoldStyle, 2);
    connect(this, &QsciScintilla::marginClicked, this, [this](int margin, int line, Qt::KeyboardModifiers) {
        if (margin == 1)
            toggleBreakpoint(line);
    });
    // Squiggles.
    indicatorDefine(SquiggleIndicator, kErrorIndicator);
    setIndicatorForegroundColor(QColor(0xe0, 0x00, 0x00), kErrorIndicator);
    indicatorDefine(SquiggleIndicator, kWarningIndicator);
    setIndicatorForegroundColor(QColor(0xe0, 0x90, 0x00), kWarningIndicator);
    SendScintilla(SCI_INDICSETSTYLE, kProveoutIndicator, INDIC_BOX);
    SendScintilla(SCI_INDICSETFORE, kProveoutIndicator, QColor(220, 20, 20));
    setCaretLineVisible(true);
    // Scintilla keeps the layout of the lines on screen (not only the
    // caret's): a repaint for new squiggles, or a key that changes one line,
    // does not measure and shape the other 50 lines again (half of the
    // longest stall while typing in a 2.9 MB file went there).
    SendScintilla(SCI_SETLAYOUTCACHE, SC_CACHE_PAGE);
    setCaretLineBackgroundColor(QColor(0xf4, 0xf4, 0xff));
    setAutoIndent(false);
    SendScintilla(SCI_SETMOUSEDWELLTIME, 400);
    connect(this, &QsciScintilla::SCN_DWELLSTART, this, &ProgramEditor::dwellStart);
    connect(this, &QsciScintilla::SCN_DWELLEND, this, [](int, int, int) { QToolTip::hideText(); });
    connect(this, &QsciScintilla::SCN_CHARADDED, this, &ProgramEditor::charAdded);
    connect(this, &QsciScintilla::SCN_UPDATEUI, this, [this](int) {
        const int first = static_cast<int>(SendScintilla(SCI_GETFIRSTVISIBLELINE));
        const int shown = static_cast<int>(SendScintilla(SCI_LINESONSCREEN));
        lexer_->styleVisible(static_cast<int>(SendScintilla(SCI_DOCLINEFROMVISIBLE, first)),
                             static_cast<int>(SendScintilla(SCI_DOCLINEFROMVISIBLE, first + shown)));
    });
    connect(this, &QsciScintilla::userListActivated, this, &ProgramEditor::completionChosen);

    debounce_.setSingleShot(true);
    debounce_.setInterval(kDebounceMs);
    connect(&debounce_, &QTimer::timeout, this, &ProgramEditor::startValidation);
    // SCN_MODIFIED is asked for fold changes (what QsciScintilla needs to
    // keep folds open) and for the notices *before* an insertion or deletion,
    // not for the insertion or deletion itself: for each of those QScintilla
    // tells the accessibility layer the character offset from the start of
    // the document, counted anew each time (SCI_COUNTCHARACTERS from 0),
    // ~30 ms a keystroke deep in a 2.9 MB file, with or without a screen
    // reader. The notices before a change still make Scintilla send
    // SCEN_CHANGE for every change: it restarts the validation's debounce
    // (the text is read when the change is done), and textChanged() is
    // emitted from it once the change is done (queued, one per turn of the
    // event loop), as QsciScintilla would have emitted it.
    SendScintilla(SCI_SETMODEVENTMASK,
                  static_cast<unsigned long>(SC_MOD_CHANGEFOLD | SC_MOD_BEFOREINSERT | SC_MOD_BEFOREDELETE));
    connect(this, &QsciScintillaBase::SCEN_CHANGE, this, [this] {
        scheduleValidation();
        if (changePending_)
            return;
        changePending_ = true;
        QMetaObject::invokeMethod(
            this,
            [this] {
                changePending_ = false;
                emit textChanged();
            },
            Qt::QueuedConnection);
    });
}

ProgramEditor::~ProgramEditor() { *alive_ = false; }

void ProgramEditor::setMachine(std::optional<profile::MachineProfile> machine, program::ProgramStore machinePrograms) {
    machine_ = std::move(machine);
    machinePrograms_ = std::move(machinePrograms);
    description_.reset();
    if (machine_) {
        try {
            description_ = std::make_shared<const plc::MachineDescription>(k528::machine::Simulation::descriptionFor(*machine_));
        } catch (const std::exception&) {
            // No M-codes of its own to complete; the machine is still checked.
        }
    }
    scheduleValidation();
}

QVariant ProgramEditor::inputMethodQuery(Qt::InputMethodQuery query) const {
    switch (query) {
    case Qt::ImCursorPosition:
    case Qt::ImAnchorPosition:
    case Qt::ImSurroundingText:
    case Qt::ImCurrentSelection:
    case Qt::ImTextBeforeCursor:
    case Qt::ImTextAfterCursor:
    case Qt::ImAbsolutePosition:
        break;
    default:
        return QsciScintilla::inputMethodQuery(query);
    }
    const long pos = static_cast<long>(SendScintilla(SCI_GETCURRENTPOS));
    const long anchor = static_cast<long>(SendScintilla(SCI_GETANCHOR));
    const int line = static_cast<int>(SendScintilla(SCI_LINEFROMPOSITION, pos));
    const long start = static_cast<long>(SendScintilla(SCI_POSITIONFROMLINE, line));
    const long end = static_cast<long>(SendScintilla(SCI_GETLINEENDPOSITION, line));
    QByteArray bytes(static_cast<qsizetype>(end - start), '\0');
    if (!bytes.isEmpty())
        SendScintilla(SCI_GETTEXTRANGE, start, end, bytes.data());
    // Byte offsets within the line -> UTF-16 offsets, as Qt counts.
    auto offset = [&](long p) {
        const long b = std::clamp(p, start, end) - start;
        return static_cast<int>(QString::fromUtf8(bytes.constData(), static_cast<qsizetype>(b)).size());
    };
    const QString text = QString::fromUtf8(bytes);
    const int cursor = offset(pos);
    switch (query) {
    case Qt::ImCursorPosition:
        return cursor;
    case Qt::ImAnchorPosition:
        return offset(anchor);
    case Qt::ImSurroundingText:
        return text;
    case Qt::ImCurrentSelection:
        return anchor >= start && anchor <= end ? text.mid(std::min(cursor, offset(anchor)), std::abs(cursor - offset(anchor)))
                                                : QString();
    case Qt::ImTextBeforeCursor:
        return text.left(cursor);
    case Qt::ImTextAfterCursor:
        return text.mid(cursor);
    default: // Qt::ImAbsolutePosition: the byte position (counting characters from the start would be the cost avoided here)
        return static_cast<int>(pos);
    }
}

void ProgramEditor::scheduleValidation() {
    ++generation_;
    debounce_.start();
}

void ProgramEditor::startValidation() {
    if (workerBusy_) {
        pendingAgain_ = true; // the newest text is validated when the worker is done
        return;
    }
    workerBusy_ = true;
    QByteArray text = documentBytes();
    const std::uint64_t gen = generation_;
    auto machine = machine_;
    auto programs = machinePrograms_;
    std::weak_ptr<bool> alive = alive_;
    QPointer<ProgramEditor> self(this);
    QThreadPool::globalInstance()->start([text = std::move(text), gen, machine, programs, self, alive]() mutable {
        auto r = std::make_shared<Result>();
        r->generation = gen;
        r->v = validateText(text, machine, programs);
        text = QByteArray(); // the editor's buffer is free for the next validation
        if (alive.expired())
            return;
        QMetaObject::invokeMethod(
            QCoreApplication::instance(), [self, r]() mutable {
                if (!self)
                    return;
                self->workerBusy_ = false;
                const bool current = r->generation == self->generation_;
                if (current)
                    self->apply(std::move(*r), false);
                else // outdated by a key typed meanwhile: freed on a worker (milliseconds for 99 x 999 frames)
                    QThreadPool::globalInstance()->start([old = std::move(r)]() mutable { old.reset(); });
                if (self->pendingAgain_ || !current) {
                    self->pendingAgain_ = false;
                    self->startValidation();
                }
            },
            Qt::QueuedConnection);
    });
}

void ProgramEditor::validateNow() {
    debounce_.stop();
    Result r;
    r.generation = generation_;
    r.v = validateText(documentBytes(), machine_, machinePrograms_);
    apply(std::move(r), true);
}

void ProgramEditor::setText(const QString& text) {
    QsciScintilla::setText(text);
    const long length = static_cast<long>(SendScintilla(SCI_GETLENGTH));
    SendScintilla(SCI_ALLOCATE, static_cast<unsigned long>(length + std::max<long>(kGrowthRoomMin, length / kGrowthRoomDivisor)));
}

QByteArray ProgramEditor::documentBytes() const {
    // The two parts of Scintilla's gap buffer, read where they lie
    // (SCI_GETCHARACTERPOINTER would first move the gap to the end, a move of
    // all the text after the caret, and the next key would move it back),
    // copied into the buffer of the last validation when its worker is done
    // with it: a new 2.9 MB buffer is 700 page faults on the GUI thread.
    const auto length = static_cast<qsizetype>(SendScintilla(SCI_GETLENGTH));
    const auto gap = static_cast<qsizetype>(SendScintilla(SCI_GETGAPPOSITION));
    const auto* before = reinterpret_cast<const char*>(SendScintilla(SCI_GETRANGEPOINTER, 0, static_cast<long>(gap)));
    const auto* after =
        reinterpret_cast<const char*>(SendScintilla(SCI_GETRANGEPOINTER, static_cast<unsigned long>(gap), static_cast<long>(length - gap)));
    if ((gap > 0 && !before) || (length > gap && !after))
        return text().toUtf8();
    if (!snapshot_.isDetached())
        snapshot_ = QByteArray();
    snapshot_.resize(length);
    char* out = snapshot_.data();
    if (gap > 0)
        std::memcpy(out, before, static_cast<std::size_t>(gap));
    if (length > gap)
        std::memcpy(out + gap, after, static_cast<std::size_t>(length - gap));
    return snapshot_;
}

std::pair<int, int> ProgramEditor::spanPositions(const program::Diagnostic& d) const {
    if (d.line < 1 || d.line > lines())
        return {0, 0};
    const long line = d.line - 1;
    const long lineStart = static_cast<long>(SendScintilla(SCI_POSITIONFROMLINE, line));
    const long lineEnd = static_cast<long>(SendScintilla(SCI_GETLINEENDPOSITION, line));
    // Columns are code points: Scintilla steps over whole characters (a
    // position beyond the line stops at the line's end).
    const int column = std::max(1, d.column);
    long begin = column <= 1 ? lineStart : static_cast<long>(SendScintilla(SCI_POSITIONRELATIVE, lineStart, column - 1));
    if (begin <= 0 && column > 1)
        begin = lineEnd; // past the end of the document
    begin = std::min(begin, lineEnd);
    long end = d.endColumn > column
                   ? static_cast<long>(SendScintilla(SCI_POSITIONRELATIVE, begin, d.endColumn - column))
                   : begin;
    if (end <= 0 || end > lineEnd)
        end = lineEnd;
    if (end <= begin) // a span at the end of the line: mark the last character
        end = std::min(lineEnd, begin + 1);
    return {static_cast<int>(begin), static_cast<int>(end)};
}

void ProgramEditor::apply(Result&& r, bool all) {
    ++validations_;
    ++applied_;
    // The old store (99 x 999 frames at most) and diagnostics are freed on a
    // worker: their destruction alone is milliseconds.
    struct Old {
        program::ProgramStore store;
        std::vector<program::Diagnostic> diagnostics;
    };
    auto old = std::make_shared<Old>(Old{std::move(store_), std::move(diagnostics_)});
    store_ = std::move(r.v.store);
    diagnostics_ = std::move(r.v.diagnostics);
    QThreadPool::globalInstance()->start([old]() mutable { old.reset(); });
    const int length = static_cast<int>(SendScintilla(SCI_GETLENGTH));
    for (int ind : {kErrorIndicator, kWarningIndicator}) {
        SendScintilla(SCI_SETINDICATORCURRENT, ind);
        SendScintilla(SCI_INDICATORCLEARRANGE, 0, length);
    }
    diagnosticPositions_.assign(diagnostics_.size(), {0, 0});
    squiggledTo_ = 0;
    if (all) {
        drawSquiggles(0, diagnostics_.size());
        squiggledTo_ = diagnostics_.size();
    } else {
        // The lines on screen first (diagnostics are sorted by line).
        const int first = static_cast<int>(SendScintilla(SCI_DOCLINEFROMVISIBLE, SendScintilla(SCI_GETFIRSTVISIBLELINE)));
        const int last = first + static_cast<int>(SendScintilla(SCI_LINESONSCREEN)) + 1;
        auto lo = std::lower_bound(diagnostics_.begin(), diagnostics_.end(), first + 1,
                                   [](const program::Diagnostic& d, int line) { return d.line < line; });
        auto hi = std::upper_bound(lo, diagnostics_.end(), last + 1,
                                   [](int line, const program::Diagnostic& d) { return line < d.line; });
        if (std::is_sorted(diagnostics_.begin(), diagnostics_.end(),
                           [](const program::Diagnostic& a, const program::Diagnostic& b) { return a.line < b.line; }))
            drawSquiggles(static_cast<std::size_t>(lo - diagnostics_.begin()),
                          static_cast<std::size_t>(hi - diagnostics_.begin()));
        drawNextSlice();
    }
    emit validated();
}

void ProgramEditor::drawSquiggles(std::size_t from, std::size_t to) {
    int current = -1;
    for (std::size_t i = from; i < to && i < diagnostics_.size(); ++i) {
        const program::Diagnostic& d = diagnostics_[i];
        const auto [b, e] = spanPositions(d);
        diagnosticPositions_[i] = {b, e};
        if (e <= b)
            continue;
        const int ind = d.isError() ? kErrorIndicator : kWarningIndicator;
        if (ind != current)
            SendScintilla(SCI_SETINDICATORCURRENT, current = ind);
        SendScintilla(SCI_INDICATORFILLRANGE, b, e - b);
    }
}

void ProgramEditor::drawNextSlice() {
    const std::size_t to = std::min(diagnostics_.size(), squiggledTo_ + kSquiggleSlice);
    drawSquiggles(squiggledTo_, to);
    squiggledTo_ = to;
    if (squiggledTo_ >= diagnostics_.size())
        return;
    const std::uint64_t applied = applied_;
    QTimer::singleShot(0, this, [this, applied] {
        // A newer result, or an edit since (the positions would be stale:
        // the next result draws them), stops this one.
        if (applied == applied_ && !debounce_.isActive() && !workerBusy_)
            drawNextSlice();
    });
}

void ProgramEditor::setProveoutFindings(const std::vector<proveout::Finding>& findings) {
    findings_.clear();
    SendScintilla(SCI_SETINDICATORCURRENT, kProveoutIndicator);
    SendScintilla(SCI_INDICATORCLEARRANGE, 0L, SendScintilla(SCI_GETLENGTH));
    for (const proveout::Finding& f : findings) {
        if (f.line < 1 || f.line > lines() || programAtLine(f.line - 1) != f.program)
            continue; // a program of the machine, not of the file
        findings_.push_back(f);
        const long start = SendScintilla(SCI_POSITIONFROMLINE, f.line - 1);
        const long end = SendScintilla(SCI_GETLINEENDPOSITION, f.line - 1);
        if (end > start)
            SendScintilla(SCI_INDICATORFILLRANGE, start, end - start);
    }
}

QString ProgramEditor::hoverText(int position) const {
    QStringList out;
    // The prove-out's findings of a boxed line (the box moves with an edit;
    // the findings' lines are new after the next proof).
    if (!findings_.empty() &&
        SendScintilla(SCI_INDICATORVALUEAT, kProveoutIndicator, static_cast<long>(position)) != 0) {
        const long line = SendScintilla(SCI_LINEFROMPOSITION, static_cast<unsigned long>(position));
        for (const proveout::Finding& f : findings_)
            if (f.line - 1 == line)
                out << QStringLiteral("N%1: ").arg(f.n) + findingText(f);
    }
    for (std::size_t i = 0; i < diagnostics_.size() && i < diagnosticPositions_.size(); ++i) {
        const auto [b, e] = diagnosticPositions_[i];
        if (position < b || position >= e)
            continue;
        out << diagnosticWithManual(diagnostics_[i]);
    }
    return out.join('\n');
}

void ProgramEditor::dwellStart(int position, int x, int y) {
    if (position < 0)
        return;
    const QString t = hoverText(position);
    if (!t.isEmpty())
        QToolTip::showText(viewport()->mapToGlobal(QPoint(x, y)), t, this);
}

int ProgramEditor::programAtLine(int line) const {
    int found = 0;
    for (const program::Program& p : store_.programs())
        if (p.headerLine > 0 && p.headerLine - 1 <= line)
            found = p.number;
    if (found == 0 && store_.size() == 1)
        found = store_.programs()[0].number;
    return found;
}

QList<int> ProgramEditor::breakpointLines() const {
    QList<int> out;
    int line = markerFindNext(0, 1 << kBreakpointMarker);
    while (line >= 0) {
        out << line;
        line = markerFindNext(line + 1, 1 << kBreakpointMarker);
    }
    return out;
}

void ProgramEditor::toggleBreakpoint(int line) {
    if (markersAtLine(line) & (1 << kBreakpointMarker))
        markerDelete(line, kBreakpointMarker);
    else
        markerAdd(line, kBreakpointMarker);
    emit breakpointsChanged();
}

void ProgramEditor::setExecutingLine(int line) {
    if (line == executingLine_)
        return;
    markerDeleteAll(kExecutingMarker);
    markerDeleteAll(kExecutingLineMarker);
    executingLine_ = line;
    if (line >= 0) {
        markerAdd(line, kExecutingMarker);
        markerAdd(line, kExecutingLineMarker);
        ensureLineVisible(line);
    }
}

void ProgramEditor::charAdded(int ch) {
    int line = 0, index = 0;
    getCursorPosition(&line, &index);
    const QString before = text(line).left(index);
    const QChar c = QChar(ch).toUpper();
    const QChar prev = before.size() >= 2 ? before.at(before.size() - 2) : QChar(' ');
    if (prev.isLetterOrNumber() && !(c == '#'))
        return;
    editing::CompletionContext ctx;
    ctx.store = &store_;
    ctx.currentProgram = programAtLine(line);
    ctx.machine = description_.get();
    editing::CompletionKind kind;
    int id = 0;
    if (c == 'G') {
        kind = editing::CompletionKind::G, id = kUserListG;
    } else if (c == 'M') {
        kind = editing::CompletionKind::M, id = kUserListM;
    } else if (c == 'R') {
        kind = editing::CompletionKind::R, id = kUserListR;
    } else if (c == 'L') {
        kind = editing::CompletionKind::Call, id = kUserListL;
    } else if (c == '#') {
        kind = editing::CompletionKind::Message, id = kUserListMessage;
    } else if (c == ' ' && before.trimmed().toUpper().endsWith("GOTO")) {
        kind = editing::CompletionKind::JumpTarget, id = kUserListTarget;
    } else {
        return;
    }
    QStringList items;
    for (const editing::CompletionItem& it : editing::complete(editing::completionCatalog(ctx), kind, ""))
        items << QString::fromStdString(it.word) + kDetailSeparator + completionDetail(it);
    if (!items.isEmpty())
        showUserList(id, items);
}

void ProgramEditor::completionChosen(int id, const QString& text) {
    const QString word = text.section(kDetailSeparator, 0, 0);
    int line = 0, index = 0;
    getCursorPosition(&line, &index);
    // The typed address letter (or '#') is replaced by the whole word.
    if (id != kUserListTarget && index > 0) {
        setSelection(line, index - 1, line, index);
        removeSelectedText();
    }
    insert(word);
    setCursorPosition(line, (id != kUserListTarget && index > 0 ? index - 1 : index) + static_cast<int>(word.size()));
    const QString detail = text.section(kDetailSeparator, 1);
    if (!detail.isEmpty()) {
        const QByteArray tip = (word + ": " + detail).toUtf8();
        SendScintilla(SCI_CALLTIPSHOW, static_cast<long>(SendScintilla(SCI_GETCURRENTPOS)), tip.constData());
    }
}

} // namespace k528::studio
