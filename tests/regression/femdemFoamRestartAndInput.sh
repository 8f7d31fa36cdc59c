#!/bin/bash
# femdemFoam: (1) a run restarted from a written femdemState ends bit-identical
# to an uninterrupted run (state written at full precision); (2) bad input in
# constant/femdemProperties stops with a FatalIOError naming the file and the
# entry (misspelt entry, non-positive E, unknown material, unknown law).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$JWLIBFOAM_TEST_DIR"
mkdir -p base/system base/constant
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }
{ header controlDict; cat <<'D'; } > base/system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 4e-5; deltaT 2e-6; writeControl runTime; writeInterval 2e-5;
D
{ header femdemMeshDict; cat <<'D'; } > base/system/femdemMeshDict
targetSize 0.004; minAngle 20;
solids { bar { type rectangle; min (0 0); max (0.06 0.02); material rock;
               patches (bottom right top left); } }
D
{ header femdemProperties; cat <<'D'; } > base/constant/femdemProperties
cohesiveLaw munjiza; contactLaw potential;
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6;
                   cohesion 8e6; frictionAngle 30; GI 20; GII 200; dampingRatio 0.1; } }
boundaryConditions { left { type fixed; } right { type velocity; value (3 0.5); } }
output { vtk false; reactions (left right); }
D
(cd base && femdemMesh > log.femdemMesh 2>&1)

cp -r base full && (cd full && femdemFoam > log.femdemFoam 2>&1)
cp -r base split
(cd split && sed -i 's/endTime 4e-5;/endTime 2e-5;/' system/controlDict \
    && femdemFoam > log.femdemFoam1 2>&1 \
    && sed -i 's/endTime 2e-5;/endTime 4e-5;/' system/controlDict \
    && femdemFoam > log.femdemFoam2 2>&1)
grep -q "Restarted from" split/log.femdemFoam2
broken=$(grep -o 'broken joints [0-9]*' full/log.femdemFoam | tail -1 | awk '{print $3}')
if cmp -s full/4e-05/femdemState split/4e-05/femdemState; then same=yes; else same=no; fi
echo ">> restart at 2e-5 s: final femdemState identical to the uninterrupted run: $same (broken joints: $broken)"
[ "$same" = yes ] && [ "${broken:-0}" -gt 0 ]

bad() {  # name, sed expression, words the message must contain
    local name=$1 expr=$2; shift 2
    rm -rf "bad_$name" && cp -r base "bad_$name" && cd "bad_$name"
    sed -i "$expr" constant/femdemProperties
    if femdemFoam > log.femdemFoam 2>&1; then echo ">> $name: accepted  <-- FAIL"; cd ..; return 1; fi
    for w in "$@"; do
        grep -q -- "$w" log.femdemFoam || { echo ">> $name: message lacks '$w'  <-- FAIL"; tail -12 log.femdemFoam; cd ..; return 1; }
    done
    echo ">> $name: rejected, message names: $*"
    cd ..
}
bad misspeltEntry 's/tensileStrength/tensileStrenght/' femdemProperties tensileStrength
bad zeroE 's/E 10e9/E 0/' femdemProperties "'E'"
bad negativeRho 's/rho 2500/rho -1/' femdemProperties "'rho'"
bad unknownMaterial 's/materials { rock/materials { granite/' femdemProperties rock
bad unknownLaw 's/cohesiveLaw munjiza/cohesiveLaw munjitza/' femdemProperties munjitza

# A deltaT that needs more sub-steps than a label holds (4e9 here) used to
# wrap the count to one sub-step of the whole deltaT and blow the solid up
rm -rf bad_hugeDeltaT && cp -r base bad_hugeDeltaT && cd bad_hugeDeltaT
sed -i 's/endTime 4e-5; deltaT 2e-6;/endTime 4e3; deltaT 1e3;/; s/writeInterval 2e-5;/writeInterval 1e3;/' system/controlDict
if femdemFoam > log.femdemFoam 2>&1; then echo ">> hugeDeltaT: accepted  <-- FAIL"; exit 1; fi
grep -q "'deltaT'" log.femdemFoam && grep -q "system/controlDict" log.femdemFoam \
    || { echo ">> hugeDeltaT: message lacks 'deltaT' / system/controlDict  <-- FAIL"; tail -12 log.femdemFoam; exit 1; }
if grep -q "Signal\|sigFpe\|Segmentation" log.femdemFoam; then echo ">> hugeDeltaT: crashed  <-- FAIL"; exit 1; fi
echo ">> hugeDeltaT (deltaT 1e3 s, $(grep -o 'more than 1e8 sub-steps' log.femdemFoam | head -1)): rejected, message names 'deltaT' and system/controlDict"
cd ..
