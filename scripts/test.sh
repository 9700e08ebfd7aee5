#!/usr/bin/env bash
# Installs the dependencies, builds Release with 2 cores and runs the whole
# test suite (GUI tests under xvfb-run); then the robustness checks: the core
# and CLI tests under AddressSanitizer + UBSan (preset asan, build/asan, no
# GUI) and a short libFuzzer run of the program parser (preset fuzz) over the
# corpus kept in core/program/fuzz/corpus. Ends with CTest's summary: the
# sanitizer suite's, then the main suite's closing lines once more.
# K528_FUZZ_SECONDS (default 90) sets the fuzz run's length; 0 skips the
# robustness checks.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel 2
mkdir -p build
xvfb-run -a -s "-noreset -screen 0 1280x800x24" ctest --preset release 2>&1 | tee build/ctest-release.log

fuzz_seconds="${K528_FUZZ_SECONDS:-90}"
[ "$fuzz_seconds" -gt 0 ] || exit 0

echo "== AddressSanitizer + UBSan build (core and CLI tests, no GUI)"
cmake --preset asan -DK528_BUILD_GUI=OFF -DK528_BUILD_BENCH=OFF
cmake --build --preset asan --parallel 2

echo "== libFuzzer: fuzz_program for ${fuzz_seconds} s"
cmake --preset fuzz
cmake --build --preset fuzz --parallel 2 --target fuzz_program
mkdir -p build/fuzz/corpus build/fuzz/artifacts
if ! build/fuzz/bin/fuzz_program -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=4096 \
        -print_final_stats=1 -artifact_prefix=build/fuzz/artifacts/ \
        build/fuzz/corpus core/program/fuzz/corpus > build/fuzz/fuzz.log 2>&1; then
    tail -n 60 build/fuzz/fuzz.log
    echo "fuzz_program found a failure: its input is in build/fuzz/artifacts/" >&2
    exit 1
fi
tail -n 12 build/fuzz/fuzz.log

echo "== The core and CLI tests under AddressSanitizer + UBSan"
ctest --preset asan -LE "gui|needs_x|packaging"

echo "== The main suite (build/release):"
grep -E "tests passed|Total Test time" build/ctest-release.log
