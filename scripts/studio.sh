#!/usr/bin/env bash
# The README's first command: installs what is missing, builds the studio (and the command
# line), and starts the studio on the built-in demo scenario. Extra arguments go to the studio
# (e.g. another scenario file). Without a display it still installs and builds, then explains
# how to get a display or use the command line (scripts/run-studio.sh).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${THESPIS_BUILD_DIR:-$root/build}"

"$root/scripts/install-deps.sh"

# Configure once; later runs only build what changed. Debian's python3 explicitly: the PATH may
# put another Python first, and the Python module must match the system's pybind11.
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3
fi
cmake --build "$build" --target thespis thespis-cli

THESPIS_BUILD_DIR="$build" exec "$root/scripts/run-studio.sh" "$@"
