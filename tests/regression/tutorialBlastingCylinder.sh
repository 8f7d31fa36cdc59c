#!/bin/bash
# Regression: tutorials/jwlIbFoam/blastingCylinder (copper cylinder test with TNT, quick mode): terminal wall velocity against Gurney, wall position from two measures; figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/blastingCylinder" .
cd blastingCylinder
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
