#!/bin/bash
# Helpers of the signal-stop tests (sourced by restartAdjustable.sh and
# parallelSignalStop.sh): cd to $JWLIBFOAM_TEST_DIR, set -u, and define
#   root fail          the project; 1 once a check failed
#   bad msg            print '>> msg  <-- FAIL', set fail
#   setEntry case k v  replace the line 'k ...;' of case/system/controlDict
#   header object      a FoamFile header line
#   smallBox dir       the coupled box of coupledData/closedBoxSolid on
#                      20x20 cells, 38 triangles (not meshed)
#   waitSteps log pid n  wait (<= 60 s) until log has n step lines or pid
#                      ended
set -u
cd "$JWLIBFOAM_TEST_DIR" || exit 1
root=$JWLIBFOAM_PROJECT
fail=0
bad() { echo ">> $*  <-- FAIL"; fail=1; }
setEntry() { sed -i "s/^$2 .*/$2 $3;/" "$1/system/controlDict"; }
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }
smallBox() {
    rm -rf "$1" && cp -r "$root/tests/regression/coupledData/closedBoxSolid" "$1"
    sed -i 's/(80 80 1)/(20 20 1)/' "$1/system/blockMeshDict"
    sed -i 's/^targetSize .*/targetSize 0.02;/; s/nSegments 48/nSegments 12/' "$1/system/femdemMeshDict"
}
waitSteps() {
    local k
    for ((k = 0; k < 3000; k++)); do
        [ "$(grep -c '^Time = ' "$1" 2> /dev/null)" -ge "$3" ] && return
        kill -0 "$2" 2> /dev/null || return
        sleep 0.02
    done
}
