#!/bin/sh
# usage: build_deb.sh CPACK BUILD_DIR OUT_DIR — builds the .deb into OUT_DIR.
set -eu
cpack=$1
build=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
cd "$build"
"$cpack" -G DEB -B "$out" --config "$build/CPackConfig.cmake"
ls "$out"/*.deb
