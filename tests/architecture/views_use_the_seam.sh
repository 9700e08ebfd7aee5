#!/bin/sh
# usage: views_use_the_seam.sh STUDIO_SOURCE_DIR
# The views of the studio reach a controller through the seam
# (controller/controller.h) only: simulation_session.h is included by the
# session itself, the simulated controller, the window that builds them
# (main.cpp, main_window.cpp) and the views that exist only for the
# simulated machine (its control panel, the debugger). A view that shows any
# controller — the K923, Program, messages, axes, backplot, oscilloscope,
# constants, R-parameters, history, the editor, the Controller dock — must
# not include it (else it would show the simulation while a real controller
# is viewed).
set -u
studio=$1
. "$(dirname "$0")/allowed_files.sh"
allowed='
session/simulation_session.cpp
session/program_loader.cpp
controller/simulated_controller.cpp
main.cpp
main_window.cpp
machine/machine_panel.cpp
editor/debug_panel.cpp
editor/debug_session.cpp
'
only_in "$studio" '#[[:space:]]*include[[:space:]]*"(session/)?simulation_session\.h"' "$allowed" \
    'includes simulation_session.h: a view reaches controllers through controller/controller.h'
n=$(echo "$found" | grep -c . || true)
[ $status -eq 0 ] && echo "views use the seam: simulation_session.h included by $n simulation-only files"
exit $status
