#!/bin/bash
# Regression: tutorials/jwlIbFoam/benchBlast -quick (0.1 ms of the bench
# blast): positivity, gas mass, fragment partition, fragment count and
# fragments in flight, Rosin-Rammler fit against the measured x50/x80;
# figures from its summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/benchBlast" .
cd benchBlast
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
