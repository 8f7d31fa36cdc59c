#!/bin/bash
# Regression: tutorials/jwlIbFoam/blastingCylinder (copper cylinder test, quick mode, cut-cell coupling) with each JWL preset (TNT, Composition B, PETN, HMX): terminal wall velocity against each explosive's Gurney velocity (5 %), wall position from two measures, gas + solid energy; figures from its summary.json
set -e -o pipefail
cd "$JWLIBFOAM_TEST_DIR"
for explosive in TNT CompB PETN HMX
do
    rm -rf $explosive && cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/blastingCylinder" $explosive
    (
        cd $explosive
        ./Allclean > /dev/null 2>&1 || true
        ./Allrun -quick -explosive $explosive | sed "s/^/$explosive: /"
        "$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json | sed "s/^>> />> $explosive: /"
    )
done
