#!/bin/bash
# Regression: tutorials/jwlIbFoam/waterShockTubes (Allrun -quick): water/air
# and TNT/water shock tubes against the exact Riemann solution, the
# three-material contact (p, u uniform, masses kept), the cavitating water
# expansion (cut-off model) against its exact solution and the same run
# without the cut-off stopping; figures from summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/waterShockTubes" .
cd waterShockTubes
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
