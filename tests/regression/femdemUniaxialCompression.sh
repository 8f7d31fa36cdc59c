#!/bin/bash
# femdemFoam tutorial uniaxialCompression, quick mode: copies the case to the scratch folder,
# runs Allrun -quick and checks the figures of its summary.json.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
cp -r "$root/tutorials/femdemFoam/uniaxialCompression" "$JWLIBFOAM_TEST_DIR/case"
cd "$JWLIBFOAM_TEST_DIR/case"
./Allrun -quick
"$root/tests/bin/checkSummary" summary.json
