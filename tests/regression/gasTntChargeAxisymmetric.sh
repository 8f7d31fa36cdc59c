#!/bin/bash
# Regression: tutorials/jwlIbFoam/tntChargeAxisymmetric (Allrun -quick), figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/tntChargeAxisymmetric" .
cd tntChargeAxisymmetric
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
