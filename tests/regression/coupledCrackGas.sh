#!/bin/bash
# Regression (coupled): gas in cracks narrower than a cell (crackGas, issue
# 14). The crackVenting plate (1 MPa driver gas against 0.1 MPa air, the plate
# breaks at 46 us) with `crackGas { }`: the broken joints the gas view has not
# opened hold a crack network, fed through its mouths on the solid's outline
# from the cells there, its pressure on the crack faces every FEMDEM sub-step.
# Checks that gas goes into the cracks and that every kilogram and joule is
# accounted for: mesh gas + crack gas mass changes only by what the network
# created for isolated joints and what it could not hand back (both printed),
# and mesh + crack gas energy + the work on the solid likewise, to round-off.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData/crackVenting
rm -rf crackGas && cp -r "$data" crackGas && cd crackGas || exit 1
echo 'crackGas { }' >> constant/immersedBodyProperties
blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 && setFields > log.setFields 2>&1 || exit 1
jwlIbFoam > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; exit 1; }
# The crack gas is not written with the time directories yet: a restart (the
# solid has broken joints) must stop naming the entry, not start it again
# from nothing; a misspelt entry is refused
sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict
if jwlIbFoam > log.restart 2>&1 || ! grep -q "entry 'crackGas'" log.restart; then
    echo ">> restart with crackGas: not refused  <-- FAIL"; tail -5 log.restart; exit 1
fi
echo ">> restart with crackGas refused, naming the entry"
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict
sed -i 's/^crackGas { }/crackGas { minApertur 1e-6; }/' constant/immersedBodyProperties
if jwlIbFoam > log.typo 2>&1 || ! grep -q "unknown entry 'minApertur' in crackGas" log.typo; then
    echo ">> misspelt crackGas entry: not refused  <-- FAIL"; tail -5 log.typo; exit 1
fi
echo ">> misspelt crackGas entry refused, naming it"
/usr/bin/python3 - <<'PY'
import os, sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_PROJECT"], "tests", "regression", "coupledData"))
import budget as budgetFile

b = budgetFile.load("postProcessing/jwlIbFoam/0/budget.dat")
m = b["gasMass"] + b["crackGasMass"]
E = b["gasEnergy"] + b["crackGasEnergy"]
W = b["solidExternalWork"]
created, lost = b["crackGasCreatedMass"], b["crackGasLostMass"]
createdE, lostE = b["crackGasCreatedEnergy"], b["crackGasLostEnergy"]
res = []
res.append(("most crack gas held / gas mass", b["crackGasMass"].max() / m[0], 1e-5, ">="))
res.append(("crack gas at the end [kg/m]", b["crackGasMass"][-1], None, None))
res.append(("max |mesh + crack gas mass change - (created - lost)| / mass",
            np.abs(m - m[0] - (created - lost)).max() / m[0], 1e-12, "<="))
res.append(("max |mesh + crack gas energy change + work on the solid - (created - lost)| / energy",
            np.abs(E - E[0] + W - W[0] - (createdE - lostE)).max() / E[0], 1e-10, "<="))
res.append(("gas the network created for isolated joints / mass", created[-1] / m[0], 1e-5, "<="))
res.append(("gas the network could not hand back / mass", lost[-1] / m[0], 1e-5, "<="))
res.append(("energy it could not hand back / energy", lostE[-1] / E[0], 1e-4, "<="))
sys.exit(1 if budgetFile.report(res) else 0)
PY
