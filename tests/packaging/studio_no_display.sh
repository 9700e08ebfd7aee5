#!/bin/sh
# usage: studio_no_display.sh K528STUDIO VERSION — --help, --version and
# --list-plugins print and exit 0 where there is no display at all.
set -eu
studio=$1
version=$2
fail() { echo "FAIL: $*"; exit 1; }
run() { env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$studio" "$@"; }
out=$(run --version 2>&1) || fail "k528studio --version exited $?: $out"
[ "$out" = "k528studio $version" ] || fail "unexpected --version output: $out"
out=$(run --help 2>&1) || fail "k528studio --help exited $?: $out"
echo "$out" | grep -q -- "--list-plugins" || fail "--help does not list the options: $out"
out=$(run --list-plugins 2>&1) || fail "k528studio --list-plugins exited $?: $out"
echo "$out" | grep -q "^searched: " || fail "unexpected --list-plugins output: $out"
# The checks above mean something only where there really is no display:
# the window itself must fail to start here.
if run --lang en >/dev/null 2>&1; then fail "k528studio started a window without a display"; fi
echo "ok: k528studio --help, --version, --list-plugins without a display"
