// The frame editor of РЕДАКТИРОВАНИЕ УП (2.6.7): one frame of a program on
// the whole LCD, in the layouts of the manual, edited field by field in the
// engine's program store (editablePrograms() + programsEdited()).
//
//   ISO                     computational     conditional      unconditional
//   /N12 G1  G90 G   #5     N12 R123          N202IF R1>0       N207GOTO 33
//    M3  M   M       L      =R1                   GOTO 301
//   X5.342     F=50.00      +12
//   Z-1234.678 F=1000.00
//
// Column 1 of line 1 is the skip flag «/» (`!` toggles it). The name of the
// field being edited blinks; typing replaces its value and the blinking moves
// to the input position. ▲▼◀► go to another field — the field left takes the
// value shown (a value out of range is «ОШИБКА ВВОДА» and stays); ESC gives
// the field its value back; DEL on N deletes the frame, elsewhere the
// field's value; SHIFT+▲▼ the previous / next frame; INS a new ISO frame
// after this one, ACK the menu of the other types; `%` types R.
//
// A frame goes into the store as soon as it is complete (an ISO frame with
// N or a word, R=a[op b], IF R>0 GOTO n, GOTO n) and after every change;
// until then the editor holds it, and a frame left incomplete is dropped
// (a new one) or keeps what the store has (one whose field was deleted).
// The store's frame is what the parser builds from the canonical text.
#pragma once

#include "panel/screen.h"
#include "program/model.h"

#include <array>
#include <optional>

namespace k528::panel {

// A frame as the editor holds it: every field may be empty.
struct FrameDraft {
    program::FrameKind kind = program::FrameKind::Iso;
    bool skip = false;
    std::optional<int> n;
    // ISO
    std::array<std::optional<int>, 3> g{}, m{};
    std::optional<int> message, call;
    std::optional<program::Value> x, fx, z, fz;
    // computational: R<target> = a [op b]
    std::optional<int> target;
    std::optional<program::Operand> a;
    program::ArithOp op = program::ArithOp::None;
    std::optional<program::Operand> b;
    // IF R<rTest> > 0 GOTO <jump>; GOTO <jump>
    std::optional<int> rTest, jump;

    static FrameDraft from(const program::Frame& f);
    // The model of the frame (as the parser builds it), or nullopt while incomplete.
    std::optional<program::Frame> toFrame() const;
};

class FrameEditor {
public:
    // The fields, in the order ◀► go through them.
    enum class Field {
        N,
        G1,
        G2,
        G3,
        Message,
        M1,
        M2,
        M3,
        Call,
        X,
        FX,
        Z,
        FZ,
        Target,
        A,
        B,
        RTest,
        Jump
    };

    // Opens program `number` (it exists) on its first frame.
    void open(int number, Context& ctx);
    void render(Canvas& c, const Context& ctx) const;
    void key(KeyPress k, Context& ctx);
    bool editing() const { return entry_.active(); }
    void cancelEdit() { entry_.stop(); }
    // ESC with nothing typed: closes the frame-type menu.
    void escape() { typeMenu_ = false; }
    // Leaving the editor: the field typed takes its value, an incomplete frame goes.
    void leave(Context& ctx);

    int program() const { return program_; }
    // Index of the frame shown in its program (for a new frame not yet in the
    // store: where it will go).
    int frameIndex() const { return index_; }
    bool typeMenu() const { return typeMenu_; }
    // The field chosen in the frame shown.
    Field field(const Context& ctx) const;
    FrameDraft draft(const Context& ctx) const;

private:
    const program::Program* prog(const Context& ctx) const;
    int frameCount(const Context& ctx) const;
    bool commitField(Context& ctx);
    bool apply(const FrameDraft& d, Context& ctx);
    void dropPending(Context& ctx);
    void gotoFrame(int delta, Context& ctx);
    void newFrame(program::FrameKind kind, Context& ctx);
    void deleteFrame(Context& ctx);
    void moveField(Key k, Context& ctx);
    void ensureFrame(Context& ctx);

    int program_ = 0;
    int index_ = 0;
    bool pendingNew_ = false;           // the frame shown is new, not yet in the store
    std::optional<FrameDraft> pending_; // the frame shown when it is not the store's
    int field_ = 0;                     // index into the layout of the frame's kind
    Entry entry_;
    bool typeMenu_ = false; // ACK: «Укажите тип кадра»
};

} // namespace k528::panel
