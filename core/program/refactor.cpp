#include "program/refactor.h"

#include <vector>

namespace k528::program {
namespace {

RefactorResult fail(std::string ru, std::string en) {
    return {false, std::move(ru), std::move(en)};
}

void retargetCalls(Program& p, int from, int to) {
    for (Frame& f : p.frames)
        if (f.body.callTarget() == from) {
            IsoFrame iso = f.body.isoFrame();
            iso.call->number = to;
            f.body = iso;
        }
}

RefactorResult checkNumbers(const ProgramStore& store, int from, int to) {
    if (!store.contains(from))
        return fail("программы L" + std::to_string(from) + " нет",
                    "there is no program L" + std::to_string(from));
    if (to < 1 || to > kMaxPrograms)
        return fail("номер программы 1..99, а не " + std::to_string(to),
                    "a program number is 1..99, not " + std::to_string(to));
    if (store.contains(to))
        return fail("программа L" + std::to_string(to) + " уже есть",
                    "program L" + std::to_string(to) + " exists already");
    return {};
}

} // namespace

RefactorResult renumber(Program& program, int start, int step) {
    if (start < 1 || step < 1)
        return fail("начало и шаг нумерации должны быть не меньше 1",
                    "the start and step of numbering must be at least 1");
    const long long count = static_cast<long long>(program.frames.size());
    if (count > 0 && start + (count - 1) * step > kMaxFrameNumber)
        return fail("последний номер кадра превысил бы 999 (" + std::to_string(count) + " кадров)",
                    "the last frame number would exceed 999 (" + std::to_string(count) + " frames)");
    program.reindex();
    // New number of the frame each old N names (the first frame with that N).
    std::vector<int> newOf(kMaxFrameNumber + 1, 0);
    for (int n = 1; n <= kMaxFrameNumber; ++n)
        if (const int i = program.indexOfN(n); i >= 0)
            newOf[static_cast<std::size_t>(n)] = start + i * step;
    auto retarget = [&](Word& target) {
        if (target.number >= 1 && target.number <= kMaxFrameNumber)
            if (const int m = newOf[static_cast<std::size_t>(target.number)]; m != 0)
                target.number = m;
    };
    for (std::size_t i = 0; i < program.frames.size(); ++i) {
        Frame& f = program.frames[i];
        if (f.kind() == FrameKind::IfGoto) {
            IfGotoFrame j = f.body.ifGotoFrame();
            retarget(j.target);
            f.body = j;
        } else if (f.kind() == FrameKind::Goto) {
            GotoFrame g = f.body.gotoFrame();
            retarget(g.target);
            f.body = g;
        }
        Word n;
        if (f.n)
            n = *f.n;
        n.number = start + static_cast<int>(i) * step;
        f.n = n;
    }
    program.reindex();
    return {};
}

RefactorResult moveProgram(ProgramStore& store, int from, int to) {
    if (RefactorResult r = checkNumbers(store, from, to); !r.ok)
        return r;
    Program moved = *store.find(from);
    store.remove(from);
    moved.number = to;
    for (Program& p : store.programs())
        retargetCalls(p, from, to);
    retargetCalls(moved, from, to);
    store.insert(std::move(moved));
    if (store.headerless)
        store.headerless = false; // the number must now be written
    return {};
}

RefactorResult copyProgram(ProgramStore& store, int from, int to) {
    if (RefactorResult r = checkNumbers(store, from, to); !r.ok)
        return r;
    Program copy = *store.find(from);
    copy.number = to;
    retargetCalls(copy, from, to);
    store.insert(std::move(copy));
    store.headerless = false;
    return {};
}

} // namespace k528::program
