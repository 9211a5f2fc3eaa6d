#!/bin/sh
# Makes the motion data Thespis ships in resources/motion, from the CMU clips in
# ../shared/data/mocap/cmu (see resources/motion/README.md for the acknowledgement):
#
#   cmu_postures.pca   the posture PCA (whole body and upper body) of every CMU clip there:
#                      walks, a dance, jumps, waves, standing and waiting. The dependent-joint
#                      filter works in its upper body: people's common motions.
#   cmu_standing.idle  the idle motion database the demo's characters idle with, from 77_02
#                      "standing" (60 fps, as the CMU index gives) from 2 s on (after the T-pose
#                      and the settling) and 111_28 "Standing still" from 6 s on (before, its feet
#                      are together; then they step apart and stay). Left out: 113_21, whose
#                      performer stands with the head bowed (the idle would take it on), the
#                      crouched "ready" stances of 140_06/140_07 and the restless 141_20.
#
# Usage: scripts/make_motion_data.sh   (THESPIS_CLI and THESPIS_SHARED_DATA override the paths)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${THESPIS_CLI:-$root/build/app/cli/thespis-cli}
cmu=${THESPIS_SHARED_DATA:-$root/../shared/data}/mocap/cmu
out=$root/resources/motion
mkdir -p "$out"
"$cli" train-pca "$cmu"/0*.bvh "$cmu"/1*.bvh "$cmu/77_02.bvh@60" --skip 1 --out "$out/cmu_postures.pca"
"$cli" build-idle "$cmu/77_02.bvh@60" "$cmu/111_28.bvh+6" --skip 2 --out "$out/cmu_standing.idle"
