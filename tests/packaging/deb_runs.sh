#!/bin/sh
# usage: deb_runs.sh PACKAGE_DIR VERSION PROGRAM — unpacks the .deb and runs it
# (PROGRAM: a program file that `k528 plot` accepts).
set -eu
dir=$1
version=$2
program=$3
deb=$(ls "$dir"/*.deb | head -n 1)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dpkg-deb -x "$deb" "$tmp/root"
fail() { echo "FAIL: $*"; exit 1; }
for f in usr/bin/k528 usr/bin/k528studio \
         usr/lib/k528studio/k528-link usr/lib/k528studio/k528-plot usr/lib/k528studio/k528-sheet \
         usr/lib/k528studio/plugins/k528_modbus_rtu.so usr/lib/k528studio/plugins/k528_modbus_tcp.so \
         usr/share/applications/k528studio.desktop \
         usr/share/icons/hicolor/scalable/apps/k528studio.svg \
         usr/share/metainfo/io.github.k528studio.K528Studio.metainfo.xml \
         usr/share/doc/k528studio/copyright usr/share/doc/k528studio/changelog.Debian.gz \
         usr/share/man/man1/k528.1.gz usr/share/man/man1/k528studio.1.gz \
         usr/share/man/ru/man1/k528.1.gz usr/share/man/ru/man1/k528studio.1.gz; do
    [ -e "$tmp/root/$f" ] || fail "$f missing from $deb"
done
# Only the commands on the PATH: the helpers live in /usr/lib/k528studio.
commands=$(ls "$tmp/root/usr/bin" | tr '\n' ' ')
[ "$commands" = "k528 k528studio " ] || fail "usr/bin holds '$commands', not just k528 and k528studio"
# Each man page renders, in its language.
man -l "$tmp/root/usr/share/man/ru/man1/k528.1.gz" 2>/dev/null | grep -q "КОМАНДЫ" ||
    fail "the Russian k528(1) does not render"
man -l "$tmp/root/usr/share/man/man1/k528studio.1.gz" 2>/dev/null | grep -q -- "--list-plugins" ||
    fail "k528studio(1) does not render"
out=$("$tmp/root/usr/bin/k528" --version) || fail "k528 --version exited $?"
[ "$out" = "k528 $version (K528 Studio)" ] || fail "unexpected version output: $out"
# No display at all (a build server, ssh): these only print.
nodisplay="env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM"
studio=$($nodisplay "$tmp/root/usr/bin/k528studio" --version) || fail "k528studio --version failed"
echo "$studio" | grep -q "$version" || fail "unexpected k528studio version output: $studio"
# The controller-link plugin in its installed place, found by k528 and the studio.
plugins=$(env -u K528_PLUGIN_PATH "$tmp/root/usr/bin/k528" link --list) || fail "k528 link --list exited $?"
echo "$plugins" | grep -q "^plugin modbus-rtu .*($tmp/root/usr/lib/k528studio/plugins/k528_modbus_rtu.so)" ||
    fail "k528 link --list does not find the installed plugin: $plugins"
splugins=$($nodisplay -u K528_PLUGIN_PATH "$tmp/root/usr/bin/k528studio" --list-plugins) ||
    fail "k528studio --list-plugins exited $?"
echo "$splugins" | grep -q "^plugin modbus-rtu .*($tmp/root/usr/lib/k528studio/plugins/k528_modbus_rtu.so)" ||
    fail "k528studio does not find the installed plugin: $splugins"
# k528 plot finds its renderer in the helper folder (it may then fail for
# want of an X server, but not for want of k528-plot).
plot=$($nodisplay "$tmp/root/usr/bin/k528" plot --lang en --out "$tmp/p.png" "$program" 2>&1) || true
case $plot in *"needs the renderer"*) fail "k528 plot does not find the installed k528-plot: $plot" ;; esac
depends=$(dpkg-deb -f "$deb" Depends)
echo "$depends" | grep -q libqt6serialbus6 || fail "Depends lacks Qt SerialBus (the link plugin): $depends"
echo "$depends" | grep -q libqt6widgets6 || fail "Depends lacks Qt: $depends"
echo "$depends" | grep -q libsqlite3 || fail "Depends lacks SQLite (core/db links it): $depends"
db=$(K528_DB="$tmp/k528.db" "$tmp/root/usr/bin/k528" db init --lang en) || fail "k528 db init exited $?"
echo "$db" | grep -q "schema    version" || fail "unexpected k528 db init output: $db"
# k528 setup-sheet writes its PDF through the installed k528-sheet, without a display.
sheet=$($nodisplay K528_DB="$tmp/k528.db" "$tmp/root/usr/bin/k528" setup-sheet --out "$tmp/sheet.pdf" "$program" 2>&1) ||
    fail "k528 setup-sheet from the package: $sheet"
[ -s "$tmp/sheet.pdf" ] || fail "k528 setup-sheet wrote no PDF: $sheet"
echo "ok: $(basename "$deb") unpacks; $out; Depends: $depends"
