#include "engine/debug_gate.h"

#include "engine/positioner.h"

namespace k528::engine {

void DebugGate::started() {
    fresh_ = true;
    holding_ = false;
    pass_.reset();
}

void DebugGate::resumed() {
    if (!holding_)
        return;
    holding_ = false;
    if (lastStop_)
        pass_ = std::make_pair(lastStop_->program, lastStop_->frameIndex);
}

bool DebugGate::beforeFrame(int program, int frameIndex, int line) {
    if (pass_ && pass_->first == program && pass_->second == frameIndex) {
        pass_.reset();
        fresh_ = false;
        return false;
    }
    pass_.reset();
    std::optional<Reason> why;
    if (runTo_ && runTo_->first == program && runTo_->second == line) {
        why = Reason::RunTo;
        runTo_.reset();
    } else if (hasBreakpoint(program, line)) {
        why = Reason::Breakpoint;
    } else if (singleFrame_ && !fresh_) {
        why = Reason::SingleFrame;
    }
    fresh_ = false;
    if (!why)
        return false;
    holding_ = true;
    lastStop_ = Stop{*why, program, frameIndex, line};
    ++stops_;
    return true;
}

std::vector<CallLevel> callStack(const Positioner& controller) {
    std::vector<CallLevel> out;
    if (!programActive(controller.state()))
        return out;
    const Interpreter& in = controller.interpreter();
    const auto level = [](int depth, const program::Program* p, int index) {
        CallLevel l;
        l.level = depth;
        l.program = p ? p->number : 0;
        l.frameIndex = index;
        if (p && index >= 0 && index < static_cast<int>(p->frames.size())) {
            const program::Frame& f = p->frames[static_cast<std::size_t>(index)];
            l.frameNumber = f.number();
            l.line = f.span.line;
        }
        return l;
    };
    for (int d = 0; d < in.level(); ++d)
        out.push_back(level(d, in.callerProgram(d), in.callerReturnIndex(d) - 1)); // the L frame
    out.push_back(level(in.level(), in.currentProgram(), in.frameIndex()));
    return out;
}

} // namespace k528::engine
