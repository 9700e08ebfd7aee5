#!/usr/bin/env bash
# Installs the Debian 12 packages K528 Studio needs to build, test and run.
# Idempotent: when every package is present it changes nothing. Otherwise it
# runs `apt-get update` first, then installs what is missing (as root, or
# through sudo).
set -euo pipefail

packages=(
    build-essential cmake ninja-build ccache pkg-config  # compilers and build tools
    qt6-base-dev libqt6opengl6-dev qt6-serialport-dev     # Qt 6 Widgets, OpenGL, serial ports
    qt6-serialbus-dev qt6-tools-dev qt6-l10n-tools        # Modbus, Qt Test/Linguist tools
    libqt6sql6-sqlite libqt6svg6 qt6-qpa-plugins          # run-time plugins
    qt6-translations-l10n                                 # Qt's own texts in Russian (qtbase_ru.qm)
    libvtk9-dev libsqlite3-dev                            # VTK 9.1, SQLite
    libpq-dev postgresql postgresql-common                # PostgreSQL's client library; a throwaway server for tests (pg_virtualenv)
    nlohmann-json3-dev libboost-dev                       # JSON, Boost.Geometry (header-only)
    libqscintilla2-qt6-dev qt6-charts-dev                 # program editor, oscilloscope
    libgl1-mesa-dri xvfb xauth                            # OpenGL in software, X server for GUI tests
    socat mbpoll                                          # serial-link test peers
    libmosquitto-dev mosquitto mosquitto-clients          # MQTT: k528 shop publish; its test broker and subscriber
    python3-pymodbus python3-serial python3-serial-asyncio # a foreign Modbus RTU controller in tests
    dpkg-dev file                                         # packaging (dpkg-shlibdeps) and its tests
    scdoc lintian appstream man-db                        # man pages (docs/man); the package's checks
    clang libclang-rt-14-dev                              # libFuzzer targets (optional preset)
    fonts-dejavu-core                                     # a font with Cyrillic for offscreen rendering
    poppler-utils                                         # pdftotext: tests read the PDFs back (class report)
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages are installed; nothing to do."
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    as_root=()
elif command -v sudo >/dev/null; then
    as_root=(sudo)
else
    echo "install-deps: ${#missing[@]} packages are missing (${missing[*]})" >&2
    echo "install-deps: run this script as root, or install sudo." >&2
    exit 2
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
echo "install-deps: apt-get update"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
echo "install-deps: apt-get install"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "install-deps: done."
