#include "program/refactor.h"

#include <array>
#include <vector>

namespace k528::program {
namespace {

constexpr std::array kTexts = {
    util::CatalogText{"refactor.no-program",
                      "программы L%1 нет",
                      "there is no program L%1"},
    util::CatalogText{"refactor.program-number",
                      "номер программы 1..99, а не %1",
                      "a program number is 1..99, not %1"},
    util::CatalogText{"refactor.program-exists",
                      "программа L%1 уже есть",
                      "program L%1 exists already"},
    util::CatalogText{"refactor.start-step",
                      "начало и шаг нумерации должны быть не меньше 1",
                      "the start and step of numbering must be at least 1"},
    util::CatalogText{"refactor.past-999",
                      "последний номер кадра превысил бы 999 (%1 кадров)",
                      "the last frame number would exceed 999 (%1 frames)"},
};

RefactorResult fail(std::string id, std::vector<std::string> args = {}) {
    return {false, std::move(id), std::move(args)};
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
        return fail("refactor.no-program", {std::to_string(from)});
    if (to < 1 || to > kMaxPrograms)
        return fail("refactor.program-number", {std::to_string(to)});
    if (store.contains(to))
        return fail("refactor.program-exists", {std::to_string(to)});
    return {};
}

} // namespace

util::TextCatalog refactorTexts() { return util::TextCatalog(kTexts); }

std::string RefactorResult::text(bool russian) const { return refactorTexts().render(textId, args, russian); }

RefactorResult renumber(Program& program, int start, int step) {
    if (start < 1 || step < 1)
        return fail("refactor.start-step");
    const long long count = static_cast<long long>(program.frames.size());
    if (count > 0 && start + (count - 1) * step > kMaxFrameNumber)
        return fail("refactor.past-999", {std::to_string(count)});
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
