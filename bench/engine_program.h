// The engine benchmark's program (bench/engine_bench.cpp), also the main part
// of the tick's profile training (bench/pgo_train.cpp): moves of both axes at
// cutting feeds and rapids, with computations and a loop of `passes` passes,
// as a day's batch of parts does.
#pragma once

#include <string>

namespace k528::bench {

inline std::string engineProgram(int passes) {
    return "%L1 (engine benchmark)\n"
           "N1 G90 G54 G0 M61 M3 M8 X80 Z2\n"
           "N2 R1=" + std::to_string(passes) + "\n"
           "N3 G1 X60 FX3000 Z-90 FZ2500\n"
           "N4 G1 X40 FX1500 Z-20 FZ3000\n"
           "N5 G0 X80 Z2\n"
           "N6 R2=R2+1\n"
           "N7 R1=R1-1\n"
           "N8 IF R1>0 GOTO 3\n"
           "N9 M5 M9\n"
           "N10 M30\n";
}

} // namespace k528::bench
