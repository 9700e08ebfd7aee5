// Memory of the program parser: the peak heap growth while
// parse() reads a large program file — the full store, 99 programs x 999
// frames (about 3 MB, the most a controller holds) — against the size of its
// text. Target: <= 5x the text. Counted by a replacement of the global
// operator new/delete with the allocator's usable sizes (what the heap really
// gives), so the figure includes the allocator's rounding.
#include <cstdio>
#include <cstdlib>
#include <malloc.h>
#include <new>
#include <string>

#include "program/formatter.h"
#include "program/parser.h"
#include "random_program.h"
#include "report.h"

namespace {
std::size_t gLive = 0, gPeak = 0;

void* allocate(std::size_t n) {
    void* p = std::malloc(n ? n : 1);
    if (!p)
        throw std::bad_alloc();
    gLive += malloc_usable_size(p);
    if (gLive > gPeak)
        gPeak = gLive;
    return p;
}
void release(void* p) noexcept {
    if (!p)
        return;
    gLive -= malloc_usable_size(p);
    std::free(p);
}
} // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }

using namespace k528;
using namespace k528::program;

int main() {
    std::string text;
    {
        testing::GeneratorOptions go;
        go.validOnly = true;
        testing::ProgramGenerator gen(528, go);
        text = format(gen.store(kMaxPrograms, kMaxFrames));
    }
    const std::size_t before = gLive;
    gPeak = gLive;
    std::size_t frames = 0, held = 0;
    {
        const ParseResult parsed = parse(text);
        held = gLive - before;
        for (const Program& p : parsed.store.programs())
            frames += p.frames.size();
    }
    const std::size_t peak = gPeak - before;
    const double mb = static_cast<double>(text.size()) / 1e6;
    std::printf("# %.2f MB of text, %zu frames: peak %.1f MB, %.1f MB held by the result (%.0f bytes a frame)\n",
                mb, frames, static_cast<double>(peak) / 1e6, static_cast<double>(held) / 1e6,
                frames ? static_cast<double>(held) / static_cast<double>(frames) : 0.0);
    bench::Report r;
    r.figure("program.parse_memory (99x999, peak / text)",
             static_cast<double>(peak) / static_cast<double>(text.size()), "x", 5, bench::Better::Lower);
    return r.exitCode();
}
