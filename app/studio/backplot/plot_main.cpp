// k528-plot: the renderer behind `k528 plot` (app/cli/cmd_plot.cpp). It reads
// a path stream (toolpath/path_io.h) on standard input and renders the
// backplot scene offscreen to a PNG:
//   k528-plot --out FILE.png [--size WxH] [--view xz|3d]
// Kept apart from `k528` so that the command line never loads VTK. Needs an
// X server (Debian's VTK): xvfb-run -a -s "-screen 0 1280x800x24".
#include "backplot/offscreen.h"
#include "toolpath/path_io.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

int main(int argc, char** argv) {
    std::string out, view = "xz";
    int w = 1280, h = 800;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (a == "--view" && i + 1 < argc)
            view = argv[++i];
        else if (a == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 8192 ||
                h > 8192) {
                std::fprintf(stderr, "k528-plot: --size is WxH, 16..8192 each\n");
                return 2;
            }
        } else {
            std::fprintf(stderr, "k528-plot: unknown argument %s\n", a.c_str());
            return 2;
        }
    }
    if (out.empty() || (view != "xz" && view != "3d")) {
        std::fprintf(stderr, "usage: k528-plot --out FILE.png [--size WxH] [--view xz|3d] < path stream\n");
        return 2;
    }
    k528::toolpath::ProgrammedPath path;
    std::string ucg, error;
    if (!k528::toolpath::readPath(stdin, path, ucg, error)) {
        std::fprintf(stderr, "k528-plot: %s\n", error.c_str());
        return 2;
    }
    k528::backplot::BackplotScene scene;
    scene.setPath(std::move(path));
    if (!ucg.empty())
        scene.setStock(k528::stock::parseUcg(ucg));
    scene.setViewMode(view == "3d" ? k528::backplot::ViewMode::Solid3D : k528::backplot::ViewMode::XZ);
    if (!k528::backplot::renderOffscreen(scene, w, h, out, nullptr, error)) {
        std::fprintf(stderr, "k528-plot: %s\n", error.c_str());
        return 2;
    }
    return 0;
}
