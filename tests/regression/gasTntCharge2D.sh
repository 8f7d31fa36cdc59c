#!/bin/bash
# Regression: tutorials/jwlIbFoam/tntCharge2D (Allrun -quick), figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/tntCharge2D" .
cd tntCharge2D
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
