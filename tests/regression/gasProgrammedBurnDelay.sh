#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# Regression: programmed burn with a delayed initiation, a second explosive,
# the plan-view burn, restarts and bad setChargeDict input.
#  1. PETN, primer at the closed wall, initiationTime 4 us (1D, 600 cells):
#     the charge stays inert until t0 (max |p/p0 - 1| < 1e-6 at the writes
#     before t0), then detonates: detonation velocity, CJ pressure and
#     Taylor wave against the exact solution (programmedBurnData/check.py);
#     a restart from 8 us ends bitwise equal to the uninterrupted run, and
#     the run on 2 ranks equals the serial one.
#  2. TNT in plan view (no primer: the whole charge 0.02..0.06 m lit at
#     1 us): the charge's interior reaches the constant-volume explosion
#     pressure of the JWL set (the energy E0 released in place; 1e-5: the
#     trace air of alphaMin 1e-6 in the charge shifts it by O(1e-6)) while
#     the total energy stays constant to round-off.
#  4. Three materials (products water air): the same detonation with a
#     water layer beyond the charge, inert until t0, against the exact
#     solution, through its arrival at the water, restarted, on 2 ranks
#     (below, before 3).
#  3. Bad setChargeDict entries stop setCharge with a FatalIOError naming
#     the file and the entry, and write nothing.
set -e
cd "$JWLIBFOAM_TEST_DIR"
data="$JWLIBFOAM_PROJECT/tests/regression/programmedBurnData"
fail=0

prepare()   # prepare <case>: a copy of the planar case, mesh, 0/
{
    rm -rf $1 && cp -r "$data/planar" $1
    cp -r $1/0.orig $1/0
    blockMesh -case $1 > $1/log.blockMesh 2>&1
}

twoRanks()  # twoRanks <case>: decomposeParDict for 2 ranks, cut at x = 0.06
{
    cat > $1/system/decomposeParDict <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method simple;
coeffs { n (2 1 1); }
EOD
}

# 1. delayed PETN detonation, restart
prepare petn
sed -i 's/explosive TNT;/explosive PETN;/' petn/constant/thermophysicalProperties
foamDictionary -entry endTime -set 1.3e-5 petn/system/controlDict > /dev/null
sed -i 's/initiationTime 0;/initiationTime 4e-6;/' petn/system/setChargeDict
setCharge -case petn > petn/log.setCharge 2>&1
jwlIbFoam -case petn > petn/log.jwlIbFoam 2>&1
/usr/bin/python3 "$data/check.py" --t0 4e-6 --inert petn || fail=1

rm -rf petnRestart && mkdir petnRestart
cp -r petn/system petn/constant petn/8e-06 petnRestart/
foamDictionary -entry startFrom -set latestTime petnRestart/system/controlDict > /dev/null
jwlIbFoam -case petnRestart > petnRestart/log.jwlIbFoam 2>&1
same=1
for f in p rhoE rhoU alphaRho.products burnFraction
do
    cmp -s petn/1.3e-05/$f petnRestart/1.3e-05/$f || same=0
done
if [ $same = 1 ]; then
    echo ">> restart from 8e-06: fields at 1.3e-05 bitwise equal to the uninterrupted run"
else
    echo ">> restart from 8e-06: fields at 1.3e-05 differ  <-- FAIL"; fail=1
fi

# The same on 2 ranks (the charge, its lighting times and the front cross
# the processor boundary at x = 0.06)
prepare petnPar
cp petn/constant/thermophysicalProperties petnPar/constant/
cp petn/system/controlDict petn/system/setChargeDict petnPar/system/
twoRanks petnPar
(
    cd petnPar
    setCharge > log.setCharge 2>&1
    decomposePar > log.decomposePar 2>&1
    mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1
    reconstructPar -latestTime > log.reconstructPar 2>&1
)
/usr/bin/python3 - <<'EOD' || fail=1
import sys
sys.path.insert(0, "%s/tests/regression/programmedBurnData" % __import__("os").environ["JWLIBFOAM_PROJECT"])
from check import read_field
import numpy as np
a = read_field("petn", "1.3e-05", "p", 600)
b = read_field("petnPar", "1.3e-05", "p", 600)
d = np.abs(b - a).max()/np.abs(a).max()
ok = d < 1e-10
print(f">> 2 ranks vs serial: max |p_2 - p_1|/max p at 1.3e-05 = {d:.3g}, tolerance 1e-10" + ("" if ok else "  <-- FAIL"))
sys.exit(0 if ok else 1)
EOD

# 2. plan view: whole charge lit at 1 us
prepare plan
foamDictionary -entry endTime -set 1.5e-6 plan/system/controlDict > /dev/null
foamDictionary -entry writeInterval -set 5e-7 plan/system/controlDict > /dev/null
cat > plan/system/setChargeDict <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object setChargeDict; }
charges ( box { min (0.02 -1 -1); max (0.06 1 1); initiationTime 1e-6; } );
EOD
setCharge -case plan > plan/log.setCharge 2>&1
jwlIbFoam -case plan > plan/log.jwlIbFoam 2>&1
/usr/bin/python3 - plan <<'EOD' || fail=1
import re, sys, numpy as np
sys.path.insert(0, "%s" % __import__("os").environ["JWLIBFOAM_PROJECT"] + "/tests/regression/programmedBurnData")
from check import jwl_from_log, read_field
case = sys.argv[1]
j = jwl_from_log(case)
w = j["omega"]
pCV = (w*j["E0"] + j["A"]*(1 - w/j["R1"])*np.exp(-j["R1"])
       + j["B"]*(1 - w/j["R2"])*np.exp(-j["R2"]))
n = 600
x = (np.arange(n) + 0.5)*0.12/n
core = (x > 0.035) & (x < 0.045)
charge = (x > 0.02) & (x < 0.06)
fail = 0
dev = np.abs(read_field(case, "1e-06", "p", n)[charge]/101325 - 1).max()
ok = dev < 1e-6; fail += not ok
print(f">> plan view: charge pressure change until t0 = 1e-06 s (max |p/p0 - 1|) = {dev:.3g}, tolerance 1e-06" + ("" if ok else "  <-- FAIL"))
p = read_field(case, "1.5e-06", "p", n)[core]
err = np.abs(p/pCV - 1).max()
ok = err < 1e-5; fail += not ok
print(f">> plan view: pressure in the charge's core at 1.5e-06 s = {p.mean():.9g} Pa, reference constant-volume explosion (JWL at rho0, E0/rho0) {pCV:.9g}, error {err:.3g}, tolerance 1e-05 (the trace air, alphaMin 1e-6, shifts it by O(alphaMin))" + ("" if ok else "  <-- FAIL"))
E = [float(v) for v in re.findall(r"energy = (\S+)", open(case + "/log.jwlIbFoam").read())]
err = abs(E[-1]/E[0] - 1)
ok = err < 1e-12; fail += not ok
print(f">> plan view: total energy change while the charge burns = {err:.3g} (relative, {len(E)} steps), tolerance 1e-12" + ("" if ok else "  <-- FAIL"))
sys.exit(1 if fail else 0)
EOD

# 4. Three materials (products water air): the TNT charge 0..0.1 m lit at
# 3 us from the closed wall, water (stiffened gas) in 0.1..0.115 m, air
# beyond. To 16 us: inert until t0 and the detonation against the exact
# solution as in 1 (the trace water in the charge: alphaMin); then a
# restart from 16 us to 20 us, through the detonation's arrival at the
# water (17.4 us): the transmitted shock in the water, every material's
# mass and the total energy kept (the right boundary is still at rest), and
# the same on 2 ranks (the cut at x = 0.06: the front crosses it)
prepare water3
cat > water3/constant/thermophysicalProperties <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object thermophysicalProperties; }
materials (products water air);
products { equationOfState JWL; explosive TNT; }
water    { equationOfState stiffenedGas; gamma 4.4; pInf 6e8; }
air      { equationOfState idealGas; gamma 1.4; Cv 718; }
alphaMin 1e-6;
EOD
waterFields()  # waterFields <case>: 0/alpha.water, 0/rho.water (a trace) from the products'
{
    for f in alpha rho; do sed "s/$f.products/$f.water/" $1/0/$f.products > $1/0/$f.water; done
}
waterFields water3
cat > water3/system/setChargeDict <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object setChargeDict; }
nSample     8;
burnWidth   2;
charges ( box { min (0 -1 -1); max (0.1 1 1); explosive products; initiationTime 3e-6; primer (0 0 0); } );
fills   ( box { min (0.1 -1 -1); max (0.11 1 1); material water; rho 1000; } );
EOD
foamDictionary -entry endTime -set 1.6e-5 water3/system/controlDict > /dev/null
setCharge -case water3 > water3/log.setCharge 2>&1
twoRanks water3
rm -rf water3Par water3Pert && cp -r water3 water3Par && cp -r water3 water3Pert
jwlIbFoam -case water3 > water3/log.jwlIbFoam 2>&1
/usr/bin/python3 "$data/check.py" --t0 3e-6 --inert water3 || fail=1
mv water3/log.jwlIbFoam water3/log.jwlIbFoam.1
foamDictionary -entry startFrom -set latestTime water3/system/controlDict > /dev/null
foamDictionary -entry endTime -set 2e-5 water3/system/controlDict > /dev/null
jwlIbFoam -case water3 > water3/log.jwlIbFoam 2>&1
foamDictionary -entry endTime -set 2e-5 water3Par/system/controlDict > /dev/null
(
    cd water3Par
    decomposePar > log.decomposePar 2>&1
    mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1
    reconstructPar > log.reconstructPar 2>&1
)
# The serial run's own sensitivity: the water density 1000 -> 1000 + 1e-13
# (one unit in the last place) from the start
(
    cd water3Pert
    rm -rf 0 && cp -r 0.orig 0
    waterFields .
    sed -i 's/rho 1000;/rho 1000.0000000000001;/' system/setChargeDict
    foamDictionary -entry endTime -set 2e-5 system/controlDict > /dev/null
    setCharge > log.setCharge 2>&1 && jwlIbFoam > log.jwlIbFoam 2>&1
)
/usr/bin/python3 - <<'EOD' || fail=1
import os, re, sys
import numpy as np
sys.path.insert(0, os.environ["JWLIBFOAM_PROJECT"] + "/tests/regression/programmedBurnData")
from check import read_field
n, L = 600, 0.12
x = (np.arange(n) + 0.5)*L/n
V = (L/n)*1e-3*1e-3
fail = 0
def row(name, v, tol, ok):
    global fail
    fail += not ok
    print(f">> three materials: {name} = {v:.4g}, tolerance {tol}" + ("" if ok else "  <-- FAIL"))
mass = lambda t, m: (read_field("water3", t, "alphaRho." + m, n)*V).sum()
mass0 = lambda m: (read_field("water3", "0", "alpha." + m, n)*read_field("water3", "0", "rho." + m, n)*V).sum()
for m in ("products", "water"):
    a, b = mass0(m), mass("2e-05", m)
    row(f"{m} mass change 0 -> 20 us (relative)", abs(b/a - 1), "1e-12", abs(b/a - 1) < 1e-12)
E = [float(v) for f in ("log.jwlIbFoam.1", "log.jwlIbFoam")
     for v in re.findall(r"energy = (\S+)", open("water3/" + f).read())]
row(f"total energy change 0 -> 20 us (relative, {len(E)} steps, both runs)", abs(E[-1]/E[0] - 1), "1e-12",
    abs(E[-1]/E[0] - 1) < 1e-12)
p = read_field("water3", "2e-05", "p", n)
aw = read_field("water3", "2e-05", "alpha.water", n)
pw = p[aw > 0.5].max()
print(f">> three materials: the detonation reached the water at {3e-6 + 0.1/6930:.3g} s; highest water pressure at 20 us {pw:.4g} Pa")
row("highest water pressure at 20 us / 1 GPa (the transmitted shock)", pw/1e9, ">= 1", pw > 1e9)
# 2 ranks against serial (restarted at 16 us): to round-off until the
# detonation meets the water; after it within the serial run's own
# sensitivity (the trace phases' densities, (rho - m1 - m2)/alpha3 with
# alpha3 ~ alphaMin, carry the last bits of the inputs 1e6-fold, and the
# products/water contact under the detonation amplifies them further)
for t, tol in (("1.7e-05", 1e-10), ("2e-05", 1e-2)):
    a = read_field("water3", t, "p", n)
    b = read_field("water3Par", t, "p", n)
    d = np.abs(b - a).max()/np.abs(a).max()
    row(f"2 ranks vs serial: max |p_2 - p_1|/max p at {float(t)*1e6:g} us", d, f"{tol:g}", d < tol)
c = read_field("water3Pert", "2e-05", "p", n)
print(f">> three materials: the serial run with the water density 1 ulp higher: max |p - p_1|/max p at 20 us = {np.abs(c - p).max()/np.abs(p).max():.3g} (its sensitivity; not checked)")
sys.exit(1 if fail else 0)
EOD

# 3. bad input: setCharge stops naming file and entry, writes nothing
prepare bad
md5=$(md5sum bad/0/p | cut -d' ' -f1)
badCase()   # badCase <label> <entry the message must name> <charge entries>
{
    cat > bad/system/setChargeDict <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object setChargeDict; }
$4
charges ( box { min (0 -1 -1); max (0.1 1 1); $3 } );
EOD
    if setCharge -case bad > bad/log.$1 2>&1; then
        echo ">> $1: accepted  <-- FAIL"; fail=1
    elif grep -q "setChargeDict" bad/log.$1 && grep -q "$2" bad/log.$1 \
      && [ ! -e bad/0/lightingTime ] && [ "$(md5sum bad/0/p | cut -d' ' -f1)" = $md5 ]; then
        echo ">> $1: rejected, nothing written ($(grep -m1 "$2" bad/log.$1 | sed 's/^ *//' | cut -c1-90))"
    else
        echo ">> $1: no FatalIOError naming setChargeDict and $2, or fields written  <-- FAIL"; fail=1
    fi
}
badCase primerWithoutInitiation "'primer'" "primer (0 0 0);"
badCase misspeltInitiationTime "initationTime" "initationTime 0;"
badCase negativeDetonationVelocity "'detonationVelocity'" "initiationTime 0; detonationVelocity -6930;"
badCase primerOutside "'primer'" "initiationTime 0; primer (0.2 0 0);"
badCase initiationBeforeStart "'initiationTime'" "initiationTime -1e-6;"
badCase wrongExplosive "'explosive'" "explosive TNT; initiationTime 0;"
badCase zeroBurnWidth "'burnWidth'" "initiationTime 0;" "burnWidth 0;"
exit $fail
