// The backplot scene rendered offscreen to a PNG (`k528 plot`, tests).
// Debian's VTK is built for X/GLX only: it needs an X server even offscreen
// (run under `xvfb-run -a -s "-screen 0 1280x800x24"`); without DISPLAY this
// refuses with a message instead of letting VTK abort.
#pragma once

#include "backplot/backplot_scene.h"

#include <string>
#include <vector>

namespace k528::backplot {

// Renders `scene` fitted to w × h; the RGB pixels (row 0 at the bottom) in
// `rgb` if given, the PNG at `pngPath` if not empty. False with `error` set.
bool renderOffscreen(BackplotScene& scene, int w, int h, const std::string& pngPath,
                     std::vector<unsigned char>* rgb, std::string& error);

} // namespace k528::backplot
