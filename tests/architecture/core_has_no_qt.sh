#!/bin/sh
# usage: core_has_no_qt.sh PROBE_BINARY CORE_SOURCE_DIR
set -u
probe=$1
core=$2
status=0
if ! "$probe" >/dev/null; then
    echo "FAIL: $probe does not run"
    status=1
fi
qtlibs=$(ldd "$probe" | grep -i 'libQt' || true)
if [ -n "$qtlibs" ]; then
    echo "FAIL: core links Qt libraries:"
    echo "$qtlibs"
    status=1
fi
qtincludes=$(grep -rnE '#\s*include\s*[<"](Q[A-Za-z]+|Qt[A-Za-z]*/)' "$core" || true)
if [ -n "$qtincludes" ]; then
    echo "FAIL: core sources include Qt headers:"
    echo "$qtincludes"
    status=1
fi
[ $status -eq 0 ] && echo "core: no Qt headers, no Qt libraries ($(ldd "$probe" | wc -l) shared libraries)"
exit $status
