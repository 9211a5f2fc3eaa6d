#!/usr/bin/env bash
# Starts the studio window on a scenario (default: the built-in demo). It does not build: run
# scripts/studio.sh for install + build + run. Without a display it explains how to get one,
# or how to use the command line instead, and exits with status 3.
#
#   scripts/run-studio.sh [SCENARIO.thespis]
#   THESPIS_BUILD_DIR=build-debug scripts/run-studio.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${THESPIS_BUILD_DIR:-$root/build}"
scenario="${1:-$root/resources/demo.thespis}"
studio="$build/app/studio/thespis"
cli="$build/app/cli/thespis-cli"

if [ ! -x "$studio" ]; then
  echo "run-studio: $studio is not built yet. Build it with: scripts/studio.sh" >&2
  exit 1
fi

if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ] && [ -z "${QT_QPA_PLATFORM:-}" ]; then
  # A real character name makes the bake-motion example runnable as printed.
  character="$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["characters"][0]["name"])' \
               "$scenario" 2>/dev/null || echo NAME)"
  cat >&2 <<MESSAGE
run-studio: cannot open the studio window: no display (neither DISPLAY nor WAYLAND_DISPLAY is set).

To get a display:
  - run it on a virtual X server:  xvfb-run -a scripts/studio.sh
                                   (xvfb-run comes with the xvfb package that install-deps.sh installs)
  - log in with X forwarding:      ssh -X user@this-machine, then scripts/studio.sh
  - or set DISPLAY / WAYLAND_DISPLAY to a running display, or QT_QPA_PLATFORM to a Qt platform
    (QT_QPA_PLATFORM=offscreen runs without showing anything, for tests).

Or use the engine without a window, from the command line:
  $cli validate $scenario
  $cli info $scenario
  $cli bake-motion $scenario --character "$character" --fps 30 --out motion.bvh
  (info lists the characters, clips and actions; open motion.bvh in Blender)
MESSAGE
  exit 3
fi

exec "$studio" "$scenario"
