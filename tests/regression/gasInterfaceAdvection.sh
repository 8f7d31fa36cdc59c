#!/bin/bash
# Regression: tutorials/jwlIbFoam/interfaceAdvection (Allrun -quick), figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/interfaceAdvection" .
cd interfaceAdvection
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
