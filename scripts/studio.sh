#!/usr/bin/env bash
# Installs the dependencies, builds Release and starts the K528 Studio
# workstation on the training lathe with its sample programs (later: the
# machine chosen last in File > Machine).
# Extra arguments go to k528studio (e.g. --lang en).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target k528studio k528
binary="$PWD/build/release/bin/k528studio"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    echo
    echo "k528studio is built, but this session has no display (neither DISPLAY nor WAYLAND_DISPLAY is set)."
    echo "Start it on a virtual X server and save a screenshot instead:"
    echo "  xvfb-run -a -s '-screen 0 1280x800x24' $binary --screenshot k528studio.png"
    exit 1
fi
exec "$binary" "$@"
