#!/usr/bin/env bash
# Installs the dependencies, builds Release with 2 cores and runs the whole
# test suite (GUI tests under xvfb-run), ending with CTest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel 2
xvfb-run -a -s "-screen 0 1280x800x24" ctest --preset release
