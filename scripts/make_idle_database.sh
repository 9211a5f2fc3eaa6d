#!/bin/sh
# Builds resources/idle/cmu_standing.idle, the idle motion database the product ships (the demo's
# characters idle with it), from two CMU standing recordings in ../shared/data/mocap/cmu:
#   77_02 "standing" (60 fps, as the CMU index gives) from 2 s on (after the T-pose and the
#   settling), and 111_28 "Standing still" from 6 s on (before, its feet are together; then they
#   step apart and stay).
# Left out: 113_21, whose performer stands with the head bowed (the idle would take it on), the
# crouched "ready" stances of 140_06/140_07 and the restless 141_20.
#
# Usage: scripts/make_idle_database.sh   (THESPIS_CLI and THESPIS_SHARED_DATA override the paths)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${THESPIS_CLI:-$root/build/app/cli/thespis-cli}
cmu=${THESPIS_SHARED_DATA:-$root/../shared/data}/mocap/cmu
mkdir -p "$root/resources/idle"
"$cli" build-idle "$cmu/77_02.bvh@60" "$cmu/111_28.bvh+6" --skip 2 \
    --out "$root/resources/idle/cmu_standing.idle"
