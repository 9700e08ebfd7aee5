// A program that keeps both axes moving for about 90 s on the training
// lathe: twelve passes of feeds, counted down in R1 (an endless GOTO loop
// would make the backplot compute a preview of 100,000 frames first). The
// studio's quiet test runs it (a running program repaints at most at the
// frame rate) and bench/studio_cpu measures the CPU while it runs.
#pragma once

namespace k528::testrig {

inline constexpr const char* kLoopProgram = "%L1\n"
                                            "N1 G90 G0 X60 Z-5\n"
                                            "N2 R1=12\n"
                                            "N3 G1 X20 FX600 Z-60 FZ900\n"
                                            "N4 G1 X60 FX600 Z-5 FZ900\n"
                                            "N5 R1=R1-1\n"
                                            "N6 IF R1>0 GOTO 3\n"
                                            "N7 M30\n";

} // namespace k528::testrig
