#!/bin/sh
# usage: deb_lintian.sh PACKAGE_DIR — lintian on the built .deb: any error or
# warning fails (overrides, each with its reason, are in
# packaging/lintian-overrides when there are any).
set -eu
deb=$(ls "$1"/*.deb | head -n 1)
# Root gets a notice from lintian on stderr, not a tag: keep it out of the log.
out=$(lintian --fail-on error,warning --display-level ">=warning" "$deb" 2>&1) && rc=0 || rc=$?
printf '%s\n' "$out" | grep -v "^running with root privileges" || true
[ "$rc" -eq 0 ] || { echo "FAIL: lintian reports errors or warnings on $(basename "$deb")"; exit 1; }
echo "ok: lintian finds no error or warning on $(basename "$deb")"
