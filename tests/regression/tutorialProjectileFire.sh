#!/bin/bash
# Regression: tutorials/jwlIbFoam/projectileFire (quick mode: ideal-gas gun, free steel projectile): velocity against the exact simple-wave solution until the breech reflection (3 %), momentum budget of the closed barrel, gas mass; figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/projectileFire" .
cd projectileFire
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
