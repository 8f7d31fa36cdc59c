#!/bin/bash
# Pre-existing joints under tension: a 0.1 x 0.05 m rock block (intact
# tensile strength 5 MPa) meshed by femdemMesh with a joint set across it,
# pulled apart by velocity conditions on its left and right sides
# (femdemFoam, slow ramp, damped: quasi-static). Per case:
# - the first broken joints (crackEvents.dat, until the set has broken
#   through) all lie on the set, none elsewhere (a weaker set along the pull
#   does not break first);
# - the peak tensile stress F/H (right reaction over the height) against
#   the set's tensile strength (uniform stress: a joint normal to the pull
#   breaks at f_t): error printed, tolerance 5 %.
# Cases: A vertical joint crossing the block (clipped at top and bottom),
# f_t 1 MPa, with a weaker (0.5 MPa) set along the pull; B the joint from
# a DFN CSV file (columns in another order, an extra column, a
# tensileStrength column scaling the set's 3 MPa to 1.5 MPa), other mesh
# size and pull speed; C a joint at 30 degrees to the y axis (breaking
# in shear: Mohr-Coulomb criterion below f_t/n_x^2) from a CSV row whose
# frictionAngle (20) replaces the set's (40: the criterion would be
# 0.75 MPa), another size. Then a bad joint-set property in solidMesh.
set -eu
cd "$JWLIBFOAM_TEST_DIR"
ok=0
run_case()   # name size speed jointSetsEntry "ft c phi angle" [csv]
{
    local name=$1 size=$2 speed=$3 sets=$4 strength=$5
    rm -rf "$name"; mkdir -p "$name/system" "$name/constant"
    cat > "$name/system/femdemMeshDict" <<D
FoamFile { version 2.0; format ascii; class dictionary; object femdemMeshDict; }
targetSize $size;
minAngle   25;
solids { block { type rectangle; min (0 0); max (0.1 0.05); material rock;
                 patches (bottom right top left); } }
jointSets { $sets }
D
    cat > "$name/system/controlDict" <<D
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application femdemFoam; startFrom startTime; startTime 0; stopAt endTime;
endTime $(python3 -c "print(6e-6/$speed + 5e-5)"); deltaT 2e-6;
writeControl runTime; writeInterval 1; timePrecision 8;
D
    cat > "$name/constant/femdemProperties" <<D
FoamFile { version 2.0; format ascii; class dictionary; object femdemProperties; }
cohesiveLaw munjiza; contactLaw potential; gravity (0 0);
materials
{
    rock { E 20e9; nu 0.25; rho 2500; tensileStrength 5e6; cohesion 15e6;
           frictionAngle 30; GI 50; GII 500; dampingRatio 0.3;
           jointPenalty 4e11; }
}
boundaryConditions
{
    left  { type velocity; value (-$speed 0); components (x); rampTime 1e-4; }
    right { type velocity; value ( $speed 0); components (x); rampTime 1e-4; }
}
output { logInterval 2e-6; vtk false; reactions (right); }
D
    [ -n "${6:-}" ] && printf '%s\n' "$6" > "$name/constant/dfn.csv"
    start=$(date +%s.%N)
    femdemMesh -case "$name" > "$name/log.femdemMesh" 2>&1 || { tail -20 "$name/log.femdemMesh"; return 1; }
    femdemFoam -case "$name" > "$name/log.femdemFoam" 2>&1 || { tail -20 "$name/log.femdemFoam"; return 1; }
    echo ">> case $name: $(grep -m1 'Solid mesh:' "$name/log.femdemMesh"), $(grep -m1 'Joint sets:' "$name/log.femdemFoam"), run $(python3 -c "import time; print(f'{time.time() - $start:.1f}')") s"
    /usr/bin/python3 - "$name" $strength <<'PY'
import glob, math, sys
name = sys.argv[1]
ft, c, phi, angle = map(float, sys.argv[2:6])
# Joint through the centre at 'angle' from the y axis: normal (nx, ny);
# uniaxial sigma_xx breaks it at sigma nx^2 = f_t or, sliding, at
# sigma |nx ny| = c - sigma nx^2 tan(phi) (Mohr-Coulomb)
a = math.radians(angle)
nx, ny = math.cos(a), -math.sin(a)
crit = min(ft / nx**2, c / (abs(nx * ny) + nx**2 * math.tan(math.radians(phi))))
post = glob.glob(f"{name}/postProcessing/femdem/*/")[0]
def table(f):
    lines = open(post + f).read().splitlines()
    return [list(map(float, l.split())) for l in lines if l and not l.startswith("#")]
events = table("crackEvents.dat")
R = table("reactions.dat")
H = 0.05
dist = lambda x, y: abs((x - 0.05) * nx + (y - 0.025) * ny)
on_set = lambda e: dist(e[1], e[2]) < 1e-9 and dist(e[3], e[4]) < 1e-9
# Events until the set is broken through (every joint on x = x0 broken)
n_set = sum(on_set(e) for e in events)
first = []
for e in events:
    first.append(e)
    if sum(on_set(f) for f in first) == n_set:
        break
off = [e for e in first if not on_set(e)]
peak = max(r[1] for r in R)
err = abs(peak / H - crit) / crit
good = n_set > 0 and not off and err < 0.05
print(f">> case {name}: {len(events)} joints broken, {n_set} on the set (within 1e-9 m); of the first {len(first)}"
      f" (until the set broke through) {len(off)} off the set (tolerance 0);"
      f" first break at t = {events[0][0]:.3e} s" if events else f">> case {name}: no joint broke  <-- FAIL")
print(f">> case {name}: peak tensile stress F/H {peak / H / 1e6:.4f} MPa against the set's"
      f" criterion {crit / 1e6:.4f} MPa (f_t {ft / 1e6:g} MPa, joint at {angle:g} deg; intact f_t 5 MPa): error {100 * err:.2f} % (tolerance 5 %)"
      + ("" if good else "  <-- FAIL"))
sys.exit(0 if good else 1)
PY
}
run_case A 0.01 0.004 "across { type lines; segments (((0.05 -0.05) (0.05 0.1))); tensileStrength 1e6; cohesion 3e6; frictionAngle 30; GI 1; GII 10; }
           along  { type lines; segments (((0.01 0.025) (0.09 0.025))); tensileStrength 0.5e6; cohesion 3e6; GI 1; GII 10; }" "1e6 3e6 30 0" || ok=1
run_case B 0.008 0.006 "dfn { type file; file \"constant/dfn.csv\"; tensileStrength 3e6; cohesion 6e6; GI 2; GII 10; }" "1.5e6 3e6 30 0" \
"# one fracture across the block
id,length,orientation,y,x,tensileStrength
1,0.05,90,0.025,0.05,1.5e6" || ok=1
run_case C 0.008 0.005 "inclined { type file; file \"constant/dfn.csv\"; tensileStrength 1e6; cohesion 0.8e6; frictionAngle 40; GI 1; GII 5; }" "1e6 0.8e6 20 30" \
"x,y,orientation,length,frictionAngle
0.05,0.025,60,0.2,20" || ok=1
# Bad joint-set property in constant/solidMesh: femdemFoam must stop
# naming the file and the entry (and write nothing)
rm -rf bad; cp -r A bad; rm -rf bad/postProcessing
sed -i '0,/tensileStrength 1000000;/s//tensileStrength -1;/' bad/constant/solidMesh
rc=0; femdemFoam -case bad > bad/log 2>&1 || rc=$?
if [ $rc -ne 0 ] && [ $rc -lt 128 ] && grep -q "FOAM FATAL IO ERROR" bad/log && grep -q "solidMesh.jointSets.across" bad/log \
   && grep -q "entry 'tensileStrength' must be positive" bad/log && [ ! -d bad/postProcessing ]; then
    echo ">> bad input: joint set tensileStrength -1 in constant/solidMesh: FatalIOError naming solidMesh, the set and 'tensileStrength'"
else
    echo ">> bad input: joint set tensileStrength -1: exit $rc  <-- FAIL"; tail -8 bad/log; ok=1
fi
exit $ok
