#!/bin/bash
# Regression: tutorials/jwlIbFoam/immersedWall (Mach 2 reflection by an immersed and a body-fitted wall), figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/immersedWall" .
cd immersedWall
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
