// The prove-out's example: facing a Ø40 bar, then the return. The handbook's
// third error is the return rapid (N4, line 6 with the blank's line) straight
// through the blank; made safe, it goes back along the face, then up. The
// prove-out's rules, its command line and its pane in the studio share them.
#pragma once

#include <string>

namespace k528::testrig {

// A Ø40 bar, 80 mm out of the part zero (the face at Z0): the file's NC-200 blank.
inline constexpr const char* kBar = "; UCG,2,Z-80Z0,X40X0,S0S0,0,-5\n";

inline const std::string kBadFacing = std::string(kBar) + "%L1 (FACE)\n"
                                                          "N1 G90 G0 M3 X44 Z2\n"
                                                          "N2 Z-1\n"
                                                          "N3 G1 X-1 FX150\n"
                                                          "N4 G0 X44 Z-20\n"
                                                          "N5 M30\n";

inline const std::string kSafeFacing = std::string(kBar) + "%L1 (FACE)\n"
                                                           "N1 G90 G0 M3 X44 Z2\n"
                                                           "N2 Z-1\n"
                                                           "N3 G1 X-1 FX150\n"
                                                           "N4 G0 Z2\n"
                                                           "N5 X44\n"
                                                           "N6 M30\n";

} // namespace k528::testrig
