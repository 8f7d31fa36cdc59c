#!/bin/bash
# Regression (coupled gas + solid): a free rock disc thrown at (20, 5) m/s
# through air at rest in a periodic box (80 x 80 cells, 1000 fluid steps).
#  - total momentum of gas + solid conserved (1e-8 relative), gas mass
#    conserved (1e-12), gas mass in cells covered by the solid (< 1 %),
#    no gas piling up in the cut cells, energy budget;
#  - restart: 0 -> 2 ms in one run equals 0 -> 1 ms, stop, restart -> 2 ms
#    (gas fields and solid state, 1e-12 relative);
#  - 2 ranks (decomposePar with METIS, reconstructPar) against serial (1e-8),
#    and a 2-rank restart against the 2-rank run (1e-12).
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData
compare=$data/compareCases.py
rm -rf serial && cp -r "$data/closedBoxSolid" serial && cd serial
blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 || exit 1
jwlIbFoam > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; exit 1; }
fail=0
/usr/bin/python3 - <<'PY' || fail=1
import numpy as np, re, sys, os
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_PROJECT"], "tests", "regression", "coupledData"))
import budget
b = budget.load()
steps = len(b["time"])
P = np.stack([b["gasMomentumX"] + b["solidMomentumX"], b["gasMomentumY"] + b["solidMomentumY"]], axis=1)
P0 = P[0]
dP = np.abs(P - P0).max() / np.linalg.norm(P0)
m = b["gasMass"]
dm = np.abs(m - m[0]).max() / m[0]
E = b["gasEnergy"] + budget.solidEnergy(b)
KE0 = b["solidKinetic"][0]
dE = abs(E[-1] - E[0]) / KE0

def field(name):
    t = open(f"0.002/{name}").read()
    body = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\((.*?)\)\s*;", t, re.S).group(1)
    return np.array(body.split(), float)
alpha, rho, phi = field("alpha.solid"), field("rho"), field("fluidFraction")
gas = phi * rho
covered = alpha > 0.99
cut = (phi > 0) & (phi < 1)
pile = rho[cut].max() / 1.2
p = field("p")
open_ = phi >= 1
pNoiseOpen = np.abs(p[open_] / 1e5 - 1).max()
pNoiseCut95 = np.percentile(np.abs(p[cut] / 1e5 - 1), 95)
res = [("steps", steps, None),
       ("total momentum drift |P - P0|/|P0|", dP, 1e-8),
       ("gas mass drift", dm, 1e-12),
       ("gas mass in covered cells / total gas mass", gas[covered].sum() / gas.sum(), 0.01),
       ("max gas density in cut cells / ambient", pile, 1.5),
       ("max |p/p0 - 1| in uncovered cells (body at Mach 0.06)", pNoiseOpen, 0.08),
       ("95th percentile |p/p0 - 1| in cut cells", pNoiseCut95, 0.3),
       ("energy drift (gas + solid) / initial solid kinetic energy", dE, 0.02)]
bad = 0
for name, v, tol in res:
    ok = tol is None or v <= tol
    bad += not ok
    print(f">> {name} = {v:.3g}" + ("" if tol is None else f" (tolerance {tol:g})") + ("" if ok else "  <-- FAIL"))
sys.exit(1 if bad else 0)
PY

# Restart: stop at 1 ms and go on
cd .. && rm -rf restart && mkdir restart
cp -r serial/{0,constant,system,0.001} restart/
(cd restart && jwlIbFoam > log.jwlIbFoam 2>&1) || { echo ">> restart run failed <-- FAIL"; exit 1; }
d=$(/usr/bin/python3 $compare serial/0.002 restart/0.002 | tail -1 | awk '{print $2}')
ok=$(/usr/bin/python3 -c "print(int($d <= 1e-12))")
echo ">> serial restart at 1 ms vs one run, at 2 ms: max relative difference $d (tolerance 1e-12)$([ $ok = 1 ] || echo '  <-- FAIL')"
[ $ok = 1 ] || fail=1

# Two ranks to 1 ms (written every 0.5 ms), reconstructed, against serial
rm -rf parallel && mkdir parallel && cp -r serial/{0,constant,system} parallel/
cd parallel
sed -i 's/^endTime .*/endTime         1e-3;/; s/^writeInterval .*/writeInterval   250;/' system/controlDict
decomposePar > log.decomposePar 2>&1 || { echo ">> decomposePar failed <-- FAIL"; exit 1; }
mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; echo ">> parallel run failed <-- FAIL"; exit 1; }
reconstructPar -latestTime > log.reconstructPar 2>&1 || { echo ">> reconstructPar failed <-- FAIL"; exit 1; }
cd ..
if [ ! -f parallel/0.001/uniform/femdemState ]; then
    echo ">> reconstructPar did not bring the solid state <-- FAIL"; fail=1
else
    d=$(/usr/bin/python3 $compare serial/0.001 parallel/0.001 | tail -1 | awk '{print $2}')
    ok=$(/usr/bin/python3 -c "print(int($d <= 1e-8))")
    echo ">> 2 ranks (METIS) vs serial at 1 ms, reconstructed: max relative difference $d (tolerance 1e-8)$([ $ok = 1 ] || echo '  <-- FAIL')"
    [ $ok = 1 ] || fail=1
fi

# Two-rank restart from 0.5 ms
rm -rf parallelRestart && mkdir parallelRestart && cp -r parallel/{0,constant,system} parallelRestart/
for p in 0 1; do
    mkdir -p parallelRestart/processor$p
    cp -r parallel/processor$p/{constant,0,0.0005} parallelRestart/processor$p/
done
(cd parallelRestart && mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1) || { echo ">> parallel restart failed <-- FAIL"; exit 1; }
worst=0
for p in 0 1; do
    d=$(/usr/bin/python3 $compare parallel/processor$p/0.001 parallelRestart/processor$p/0.001 | tail -1 | awk '{print $2}')
    worst=$(/usr/bin/python3 -c "print(max($worst, $d))")
done
ok=$(/usr/bin/python3 -c "print(int($worst <= 1e-12))")
echo ">> 2-rank restart at 0.5 ms vs 2-rank run, at 1 ms: max relative difference $worst (tolerance 1e-12)$([ $ok = 1 ] || echo '  <-- FAIL')"
[ $ok = 1 ] || fail=1
exit $fail
