#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# Regression (coupled, cut cells: immersedBodyProperties method cutCell):
# exact moving-boundary finite volumes on the periodic box with a free rock
# disc (80 x 80 cells, the disc's polygon crosses cell faces everywhere).
#  - Galilean invariance: gas and disc moving together at 100 m/s along x
#    and at 30 degrees, the disc pre-stressed to the gas pressure (so that
#    the exact solution is a uniform translation), 200 steps, at 1e5 Pa
#    (1.2 kg/m3) and at 20 MPa (160 kg/m3, where a wall force spread
#    unlike the wall made the elastic disc ring: 7.5e-5):
#    max |p/p0 - 1| < 1e-6; gas + solid energy, momentum, mass to round-off;
#  - free disc thrown at (20, 5) m/s through air at rest, 1000 steps:
#    gas + solid energy conserved to 1e-8 relative, momentum to 1e-10;
#    pressure noise in the cut cells;
#  - piston at constant speed (a heavy, stiff block across a closed
#    channel, its faces inside cells, and once on face lines at the start)
#    pushed into the gas on one side and
#    withdrawn from it on the other, air and TNT products: the pressure
#    plateaus against the exact Riemann solutions (exactRiemann with the
#    mirror states, 1 %), gas energy change against the work of the gas
#    forces on the piston (1e-10);
#  - restart bitwise; 2 ranks (METIS) = serial within 1e-8 over 50 and 500
#    steps;
#  - fracturing tube (the blastingCylinder tutorial at 0.8 mm cells, TNT in
#    copper, 8 us): cracks open to the gas (gasView), the gas pays exactly
#    the work the solid received (gas energy + solid external work
#    conserved to 1e-10), the solid's own budget residual printed, restart
#    bitwise, a restart without <time>/uniform/openJoints refused.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData
compare=$data/compareCases.py
export PYTHONPATH=$data
fail=0

newCase()   # name: the closed box (cut cells)
{
    rm -rf "$1" && cp -r "$data/closedBoxSolid" "$1"
    (cd "$1" && blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1) \
        || { echo ">> $1: meshing failed <-- FAIL"; exit 1; }
}

check()     # name value tolerance
{
    local ok
    ok=$(/usr/bin/python3 -c "print(int($2 <= $3))")
    echo ">> $1 = $2 (tolerance $3)$([ "$ok" = 1 ] || echo '  <-- FAIL')"
    [ "$ok" = 1 ] || fail=1
}

# Galilean invariance at 0 and 30 degrees, 1e5 Pa and 20 MPa
for state in "0 1e5 1.2" "30 1e5 1.2" "0 20e6 160" "30 20e6 160"; do
    read angle p0 rho0 <<< "$state"
    c=galilean$angle
    [ $p0 = 1e5 ] || c=${c}_20MPa
    newCase $c
    sed -i "s/^internalField.*/internalField uniform $p0;/" $c/0/p
    sed -i "s/^internalField.*/internalField uniform $rho0;/" $c/0/rho
    read ux uy < <(/usr/bin/python3 -c "import math; a=math.radians($angle); print(f'{100*math.cos(a):.17g} {100*math.sin(a):.17g}')")
    sed -i "s/^initialVelocity.*/initialVelocity ($ux $uy);/; s/dampingRatio 0.1;/dampingRatio 0; initialStress (-$p0 0 -$p0);/" \
        $c/constant/femdemProperties
    sed -i "s/^internalField.*/internalField uniform ($ux $uy 0);/" $c/0/U
    sed -i 's/^endTime .*/endTime 2e-4;/; s/^deltaT .*/deltaT 1e-6;/; s/^writeInterval .*/writeInterval 200;/' \
        $c/system/controlDict
    (cd $c && jwlIbFoam > log.jwlIbFoam 2>&1) || { tail -n 5 $c/log.jwlIbFoam; echo ">> $c run failed <-- FAIL"; exit 1; }
    read dp dE dP dm < <(cd $c && /usr/bin/python3 - $p0 <<'PY'
import sys, numpy as np, budget
from budget import internal
p0 = float(sys.argv[1])
p, phi = internal("0.0002/p"), internal("0.0002/fluidFraction")
dE, dP, dm = budget.drifts(budget.load())
print(np.abs(p[phi > 0] / p0 - 1).max(), dE, dP, dm)
PY
)
    check "$c: max |p/p0 - 1| after 200 steps (disc at 100 m/s, $angle deg, $p0 Pa)" $dp 1e-6
    check "$c: gas + solid energy drift (relative)" $dE 1e-10
    check "$c: momentum drift (relative)" $dP 1e-12
    check "$c: gas mass drift (relative)" $dm 1e-12
done

# Pistons: name, thermophysicalProperties material lines, rho, p, speed,
# end time, plateau length[, the piston's x range at the start: by default
# 0.3013-0.4487, its faces inside cells of 2.5 mm]
piston()
{
    local c=$1 mat=$2 rho=$3 p=$4 u=$5 tEnd=$6 len=$7 x0=${8:-0.3013} x1=${9:-0.4487}
    rm -rf $c && cp -r "$data/piston" $c
    sed -i "s/min (0.3013 0); max (0.4487 0.01)/min ($x0 0); max ($x1 0.01)/" $c/system/femdemMeshDict
    printf 'materials (%s);\n%s\n' "${mat%% *}" "$mat" >> $c/constant/thermophysicalProperties
    sed -i "s/^internalField.*/internalField uniform $rho;/" $c/0/rho
    sed -i "s/^internalField.*/internalField uniform $p;/" $c/0/p
    sed -i "s/^initialVelocity.*/initialVelocity (-$u 0);/; s/initialStress.*/initialStress (-$p 0 -$p);/" \
        $c/constant/femdemProperties
    sed -i "s/^endTime .*/endTime $tEnd;/; s/^writeInterval .*/writeInterval $tEnd;/" $c/system/controlDict
    m=${mat%% *}
    riemann()   # u left, u right, log: the piston problem as mirror states
    {
        cat > system/exactRiemannDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object exactRiemannDict; }
x0 0.5; direction (1 0 0);
left  { material $m; rho $rho; u $1; p $p; }
right { material $m; rho $rho; u $2; p $p; }
DICT
        exactRiemann -latestTime > $3 2>&1
    }
    (cd $c && blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 \
        && jwlIbFoam > log.jwlIbFoam 2>&1 && riemann $u -$u log.compression \
        && riemann -$u $u log.expansion) \
        || { tail -n 5 $c/log.*; echo ">> $c failed <-- FAIL"; fail=1; return; }
    local pc pe
    pc=$(sed -n 's/.*p\* = \(\S*\).*/\1/p' $c/log.compression)
    pe=$(sed -n 's/.*p\* = \(\S*\).*/\1/p' $c/log.expansion)
    read ec ee dW < <(cd $c && /usr/bin/python3 - $tEnd $u $len $pc $pe $x0 $x1 <<'PY'
import sys, os, numpy as np, budget
u, L, pc, pe, x0, x1 = map(float, sys.argv[2:])
t = max((d for d in os.listdir(".") if d.replace(".", "").replace("e-", "").isdigit()), key=float)
p, phi = budget.internal(f"{t}/p"), budget.internal(f"{t}/fluidFraction")
x = (np.arange(p.size) % 400 + 0.5) * 0.0025
front, back = x0 - u * float(t), x1 - u * float(t)
ahead = (phi >= 1) & (x > front - L) & (x < front - 0.01)
behind = (phi >= 1) & (x > back + 0.005) & (x < back + L)
b = budget.load()
dGas = b["gasEnergy"][-1] - b["gasEnergy"][0]
work = b["solidExternalWork"][-1] - b["solidExternalWork"][0]
print(abs(np.median(p[ahead]) / pc - 1), abs(np.median(p[behind]) / pe - 1),
      abs(dGas + work) / abs(dGas))
PY
)
    echo ">> $c: exact piston pressures (exactRiemann) $pc Pa pushed, $pe Pa withdrawn"
    check "$c: pushed-piston plateau vs exact (relative)" $ec 0.01
    check "$c: withdrawn-piston plateau vs exact (relative)" $ee 0.01
    check "$c: |gas energy change + work on the piston| / gas energy change" $dW 1e-10
}
piston pistonAir "air { equationOfState idealGas; gamma 1.4; Cv 718; }" 1.2 1e5 50 5e-4 0.1
piston pistonTNT "products { equationOfState JWL; explosive TNT; }" 100 1e8 200 1.5e-4 0.07
# The same with the piston's faces on face lines at the start (0.3, 0.45)
piston pistonAirOnFace "air { equationOfState idealGas; gamma 1.4; Cv 718; }" 1.2 1e5 50 5e-4 0.1 0.3 0.45
piston pistonTNTOnFace "products { equationOfState JWL; explosive TNT; }" 100 1e8 200 1.5e-4 0.07 0.3 0.45

# Free disc through air at rest: 1000 steps (2 ms), written at 1 ms
newCase serial
(cd serial && jwlIbFoam > log.jwlIbFoam 2>&1) || { tail -5 serial/log.jwlIbFoam; echo ">> free disc run failed <-- FAIL"; exit 1; }
read dE dP dm noise < <(cd serial && /usr/bin/python3 - <<'PY'
import numpy as np, budget
from budget import internal
p, phi = internal("0.002/p"), internal("0.002/fluidFraction")
cut = (phi > 0) & (phi < 1)
dE, dP, dm = budget.drifts(budget.load())
print(dE, dP, dm, np.percentile(np.abs(p[cut] / 1e5 - 1), 95))
PY
)
check "free disc: gas + solid energy drift over 1000 steps (relative)" $dE 1e-8
check "free disc: momentum drift (relative)" $dP 1e-10
check "free disc: gas mass drift (relative)" $dm 1e-12
check "free disc: 95th percentile |p/p0 - 1| in cut cells (disc at Mach 0.06)" $noise 0.05

# Restart at 1 ms
rm -rf restart && mkdir restart && cp -r serial/{0,constant,system,0.001} restart/
(cd restart && jwlIbFoam > log.jwlIbFoam 2>&1) || { echo ">> restart run failed <-- FAIL"; exit 1; }
d=$(/usr/bin/python3 $compare serial/0.002 restart/0.002 | tail -1 | awk '{print $2}')
check "restart at 1 ms vs one run, at 2 ms: max relative difference" $d 1e-12

# Two ranks against serial: 0.1 ms (50 steps, written every 25) and 1 ms
# within 1e-8 (the round-off of the different summation orders stays
# round-off: see doc/theory-coupling.md, "Parallel")
rm -rf parallel && mkdir parallel && cp -r serial/{0,constant,system} parallel/
cd parallel
sed -i 's/^endTime .*/endTime         1e-3;/; s/^writeInterval .*/writeInterval   25;/' system/controlDict
decomposePar > log.decomposePar 2>&1 || { echo ">> decomposePar failed <-- FAIL"; exit 1; }
mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; echo ">> parallel run failed <-- FAIL"; exit 1; }
reconstructPar -time '0.0001,0.001' > log.reconstructPar 2>&1 || { echo ">> reconstructPar failed <-- FAIL"; exit 1; }
cd ..
rm -rf serial100 && mkdir serial100 && cp -r serial/{0,constant,system} serial100/
sed -i 's/^endTime .*/endTime         1e-4;/; s/^writeInterval .*/writeInterval   25;/' serial100/system/controlDict
(cd serial100 && jwlIbFoam > log.jwlIbFoam 2>&1) || { echo ">> serial 0.1 ms run failed <-- FAIL"; exit 1; }
d=$(/usr/bin/python3 $compare serial100/0.0001 parallel/0.0001 | tail -1 | awk '{print $2}')
check "2 ranks (METIS) vs serial at 0.1 ms (50 steps): max relative difference" $d 1e-8
d=$(/usr/bin/python3 - <<'PY'
import numpy as np, budget
# Gas content per cell (intrinsic state times fluid fraction): the state of
# a sliver cell may differ much, its content not
def content(t, f):
    return budget.internal(f"{t}/{f}") * budget.internal(f"{t}/fluidFraction")
print(max(np.abs(content("serial/0.001", f) - content("parallel/0.001", f)).max()
          / np.abs(content("serial/0.001", f)).max() for f in ("rho", "rhoE")))
PY
)
check "2 ranks (METIS) vs serial at 1 ms (500 steps): max difference of the cell gas contents (mass, energy) / largest" $d 1e-8

# Fracturing tube: the blasting cylinder, coarse, with cut cells
rm -rf tube && cp -r "$JWLIBFOAM_PROJECT/tutorials/jwlIbFoam/blastingCylinder" tube
cd tube
rm -rf 0 && cp -r 0.orig 0
sed -i 's/^n .*/n 60;/' system/blockMeshDict
sed -i 's/^targetSize .*/targetSize 0.001;/' system/femdemMeshDict
sed -i 's/^endTime .*/endTime 8e-6;/; s/^writeControl .*/writeControl timeStep;/; s/^writeInterval .*/writeInterval 50;/; s/^writePrecision .*/writePrecision 17;/' \
    system/controlDict
printf 'FoamFile { version 2.0; format ascii; class dictionary; object immersedBodyProperties; }\nmethod cutCell;\n' \
    > constant/immersedBodyProperties
for app in blockMesh femdemMesh setCharge jwlIbFoam; do
    $app > log.$app 2>&1 || { tail -5 log.$app; echo ">> tube: $app failed <-- FAIL"; exit 1; }
done
read tLast tMid <<< "$(ls -d [1-9]* | sort -g | tail -2 | tac | tr '\n' ' ')"
read dGas dSolid spread broken nOpen < <(/usr/bin/python3 - "$tLast" <<'PY'
import sys, glob, numpy as np, budget
b = budget.load(sorted(glob.glob("postProcessing/jwlIbFoam/*/budget.dat"))[0])
S, W, G = budget.solidEnergy(b), b["solidExternalWork"], b["gasEnergy"]
E0 = G[0] + S[0]
gas = np.abs(G + W - G[0] - W[0]).max() / E0     # the coupling's account
solid = np.abs(S - W - S[0] + W[0]).max() / E0   # FEMDEM's own budget
text = open(sys.argv[1] + "/uniform/openJoints").read()
n = int(text[text.index("}") + 1:].split("(")[0].split()[-1])
print(gas, solid, abs(b["gasSpreadEnergy"][-1]) / E0, int(b["brokenJoints"][-1]), n)
PY
)
cd ..
echo ">> tube: broken joints $broken, joints open to the gas $nOpen (cutCell, 8 us)"
check "tube: cracks open to the gas (open joints > 0, as 1/count)" \
    "$(/usr/bin/python3 -c "print(1/max($nOpen, 1e-300))")" 1
check "tube: |gas energy + solid external work - initial| / total energy (the coupling's account)" $dGas 1e-10
check "tube: |solid energy - external work - initial| / total energy (FEMDEM's own budget, fracture)" $dSolid 1e-3
check "tube: energy the gas spread over all gas / total energy" $spread 1e-3
rm -rf tubeRestart && mkdir tubeRestart && cp -r tube/{0,constant,system,$tMid} tubeRestart/
sed -i 's/^startFrom .*/startFrom latestTime;/' tubeRestart/system/controlDict
(cd tubeRestart && jwlIbFoam > log.jwlIbFoam 2>&1) || { tail -5 tubeRestart/log.jwlIbFoam; echo ">> tube restart failed <-- FAIL"; exit 1; }
# (the restarted time starts from the written name, so the last digit of
# the time names may differ: compare the last writes)
tLastR=$(cd tubeRestart && ls -d [1-9]* | sort -g | tail -1)
d=$(/usr/bin/python3 $compare tube/$tLast tubeRestart/$tLastR | tail -1 | awk '{print $2}')
check "tube: restart at $tMid vs one run, at $tLast: max relative difference" $d 1e-12
rm -rf tubeNoOpen && mkdir tubeNoOpen && cp -r tube/{0,constant,system,$tMid} tubeNoOpen/
sed -i 's/^startFrom .*/startFrom latestTime;/' tubeNoOpen/system/controlDict
rm tubeNoOpen/$tMid/uniform/openJoints
if (cd tubeNoOpen && jwlIbFoam > log.jwlIbFoam 2>&1); then
    echo ">> tube: restart without uniform/openJoints ran <-- FAIL"; fail=1
elif grep -q 'openJoints" is missing' tubeNoOpen/log.jwlIbFoam; then
    echo ">> tube: restart without uniform/openJoints refused, naming the file"
else
    tail -5 tubeNoOpen/log.jwlIbFoam; echo ">> tube: wrong message without openJoints <-- FAIL"; fail=1
fi
# Lined: crackVenting false keeps the gas out of the cracks (no joint opens
# to it) while the tube still breaks; the coupling's account stays exact and
# the gas, which no longer vents, drives the wall at least as hard
rm -rf tubeLined && mkdir tubeLined && cp -r tube/{0.orig,constant,system} tubeLined/
(cd tubeLined && cp -r 0.orig 0 && echo 'crackVenting false;' >> constant/immersedBodyProperties \
    && for app in blockMesh femdemMesh setCharge jwlIbFoam; do $app > log.$app 2>&1 || exit 1; done) \
    || { tail -5 tubeLined/log.jwlIbFoam; echo ">> tubeLined failed <-- FAIL"; exit 1; }
read brokenL nOpenL dGasL keL keU < <(cd tubeLined && /usr/bin/python3 - <<'PY'
import glob, numpy as np, budget
def last(case):
    return budget.load(sorted(glob.glob(case + "/postProcessing/jwlIbFoam/*/budget.dat"))[0])
b, u = last("."), last("../tube")
S, W, G = budget.solidEnergy(b), b["solidExternalWork"], b["gasEnergy"]
gas = np.abs(G + W - G[0] - W[0]).max() / (G[0] + S[0])
t = sorted(glob.glob("[1-9]*"), key=float)[-1]
text = open(t + "/uniform/openJoints").read()
n = int(text[text.index("}") + 1:].split("(")[0].split()[-1])
print(int(b["brokenJoints"][-1]), n, gas, b["solidKinetic"][-1], u["solidKinetic"][-1])
PY
)
echo ">> tubeLined: broken joints $brokenL, joint lists of openings $nOpenL; solid kinetic energy at 8 us lined $keL J/m, unlined $keU J/m"
[ "$brokenL" -gt 0 ] || { echo ">> tubeLined: no joint broke <-- FAIL"; fail=1; }
check "tubeLined: joints open to the gas (crackVenting false)" $nOpenL 0
check "tubeLined: |gas energy + solid external work - initial| / total energy" $dGasL 1e-10
check "tubeLined: unlined over lined solid kinetic energy - 1 (venting drives less)" \
    "$(/usr/bin/python3 -c "print(max($keU/$keL - 1, 0))")" 1e-2
exit $fail
