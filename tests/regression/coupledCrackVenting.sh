#!/bin/bash
# Regression (coupled): crack venting. A notched rock plate (ft = 8 MPa),
# clamped at both ends, holds 1 MPa of driver gas against air at 0.1 MPa in a
# closed channel. The gas pressure breaks it; the driver gas (traced as its
# own material) flows through the cracks and the pressure behind the plate
# rises (cut cells: the cracks open to the gas from crackOpening cells wide);
# gas + solid energy conserved. Control: the same plate made unbreakable must
# not leak.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData/crackVenting
run()
{
    rm -rf $1 && cp -r "$data" $1 && cd $1 || exit 1
    [ "$1" = intact ] && sed -i 's/tensileStrength 8e6; cohesion 15e6/tensileStrength 1e12; cohesion 1e12/' constant/femdemProperties
    blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 && setFields > log.setFields 2>&1 || exit 1
    jwlIbFoam > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; exit 1; }
    cd ..
}
run venting
run intact
/usr/bin/python3 - <<'PY'
import re, sys
import numpy as np
import os
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_TUTORIALS"], "jwlIbFoam", "common"))
import blastPost as bp
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_PROJECT"], "tests", "regression", "coupledData"))
import budget as budgetFile

nx, ny, dx, depth = 80, 40, 0.0025, 0.01
x = (np.arange(nx * ny) % nx + 0.5) * dx


def solid_xmax(case, t):
    s = open(f"{case}/{t}/uniform/femdemState").read()
    body = re.search(r"\nx\s+\d+\s*\((.*?)\n\)\s*;", s, re.S).group(1)
    return np.array(re.findall(r"\(([-\d.e+]+) [-\d.e+]+\)", body), float).max()


def driver_beyond_solid(case, t):
    """Driver gas beyond the farthest point of the solid / all driver gas"""
    m = bp.read_field(case, t, "alphaRho.driver") * bp.read_field(case, t, "fluidFraction")
    return m[x > solid_xmax(case, t) + dx].sum() / m.sum()


def budget(case):
    """budget.dat columns by name (tests/regression/coupledData/budget.py)"""
    return budgetFile.load(f"{case}/postProcessing/jwlIbFoam/0/budget.dat")


def probe_behind(case):
    d = np.loadtxt(f"{case}/postProcessing/probes/0/p")
    return d[-1, 2]          # (0.15 0.05): 4 cm behind the plate


res = []
bv, bi = budget("venting"), budget("intact")
broken = bv["brokenJoints"]
t_break = bv["time"][np.argmax(broken > 0)] if broken.max() > 0 else np.inf
res.append(("venting: first broken joint at t [s]", t_break, None, None))
res.append(("venting: broken joints at 1 ms", broken[-1], 1, ">="))
fv, fi = driver_beyond_solid("venting", "0.001"), driver_beyond_solid("intact", "0.001")
res.append(("venting: driver gas beyond the farthest fragment / driver gas", fv, 1e-4, ">="))
res.append(("intact plate: driver gas beyond the plate / driver gas (leak)", fi, 1e-6, "<="))
pv, pi = probe_behind("venting"), probe_behind("intact")
res.append(("venting: pressure 4 cm behind the plate at 1 ms [Pa]", pv, 1.1e5, ">="))
res.append(("intact plate: pressure 4 cm behind the plate at 1 ms [Pa]", pi, 1.02e5, "<="))
for name, b in (("venting", bv), ("intact", bi)):
    m = b["gasMass"]
    res.append((f"{name}: gas mass drift", np.abs(m - m[0]).max() / m[0], 1e-12, "<="))
solid = budgetFile.solidEnergy(bv)
G, W = bv["gasEnergy"], bv["solidExternalWork"]
E = G + solid
gain = solid[-1] - solid[0]
# Closed channel, cut cells: the gas pays exactly the work the solid
# receives (the coupling's account, exact: 1e-10 of the total energy as in
# coupledCutCells' fracturing tube); what the solid does with it is
# FEMDEM's own budget (fracture: its joint forces are not the exact
# gradient of the stored joint energy; 1e-3 of the total, as the tube)
res.append(("venting: max |gas energy + solid external work - initial| / total energy (the coupling's account)",
            np.abs(G + W - G[0] - W[0]).max() / abs(E[0]), 1e-10, "<="))
res.append(("venting: max |solid energy - external work - initial| / total energy (FEMDEM's own budget)",
            np.abs(solid - W - solid[0] + W[0]).max() / abs(E[0]), 1e-3, "<="))
res.append(("venting: (gas + solid energy change) / solid energy gained", (E[-1] - E[0]) / gain, 0.08, "<="))
sys.exit(1 if budgetFile.report(res) else 0)
PY
