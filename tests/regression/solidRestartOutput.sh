#!/bin/bash
# Restarts continue the solid's output (issue 17):
#  - femdemFoam (a bar of 30 triangles, written every 2e-6 s to 8e-6 s),
#    restarted from 4e-6 after the later time directories were removed:
#    VTK/femdem.vtu.series, femdem.pvd and cracks.vtp.series list every
#    write time once, in order, with the indices continuing from the
#    restart; the frames up to the restart are not rewritten (md5); the
#    crack lines carry the array initialJointLength;
#  - jwlIbFoam (the coupled box of badInputTable, 20x20 cells, 38
#    triangles), restarted from 4e-6 without alpha.solid: the projection
#    check compares the deformed solid area and accepts it; the series
#    continues the same way.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
rm -rf bar box
fail=0
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }
checkSeries() {  # dir expected-times-csv: series files against the times
    /usr/bin/python3 - "$@" <<'PY'
import json, re, sys, os
d, expected = sys.argv[1], [float(t) for t in sys.argv[2].split(",")]
bad = 0
for series, stem in (("femdem.vtu.series", "femdem"), ("cracks.vtp.series", "cracks")):
    files = json.load(open(os.path.join(d, series)))["files"]
    times = [f["time"] for f in files]
    idx = [int(re.match(stem + r"_(\d+)\.", f["name"]).group(1)) for f in files]
    ok = len(times) == len(expected) and all(abs(a - b) <= 1e-12 * max(1, abs(b)) for a, b in zip(times, expected)) \
        and idx == list(range(len(expected))) and all(os.path.isfile(os.path.join(d, f["name"])) for f in files)
    bad += not ok
    print(f">> {d}/{series}: times {times} indices {idx}" + ("" if ok else f"  <-- FAIL (expected {expected}, 0..{len(expected) - 1})"))
pvd = re.findall(r"timestep='([^']*)' file='([^']*)'", open(os.path.join(d, "femdem.pvd")).read())
ok = [float(t) for t, _ in pvd] == [f["time"] for f in json.load(open(os.path.join(d, "femdem.vtu.series")))["files"]]
bad += not ok
print(f">> {d}/femdem.pvd: {len(pvd)} data sets" + ("" if ok else "  <-- FAIL (differs from the .vtu.series)"))
sys.exit(1 if bad else 0)
PY
}

# ---- femdemFoam
mkdir -p bar/system bar/constant && cd bar
{ header controlDict; cat <<'D'; } > system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 8e-6; deltaT 2e-6; writeControl runTime; writeInterval 2e-6;
D
{ header femdemMeshDict; cat <<'D'; } > system/femdemMeshDict
targetSize 0.01; minAngle 20;
solids { bar { type rectangle; min (0 0); max (0.03 0.02); material rock; patches (bottom right top left); } }
D
{ header femdemProperties; cat <<'D'; } > constant/femdemProperties
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6; cohesion 8e6; frictionAngle 30; GI 20; GII 200; } }
boundaryConditions { left { type fixed; } right { type velocity; value (300 0); } }
output { vtk true; }
D
femdemMesh > log.femdemMesh 2>&1 && femdemFoam > log.femdemFoam 2>&1 || { tail log.femdemFoam; exit 1; }
before=$(md5sum VTK/femdem_[012].vtu VTK/cracks_[012].vtp | md5sum)
nLines=$(grep -o "NumberOfLines=.[0-9]*" VTK/cracks_4.vtp | grep -o '[0-9]*')
grep -q "Name=.initialJointLength." VTK/cracks_4.vtp \
    && echo ">> bar: cracks_4.vtp: $nLines broken joints, CellData array initialJointLength" \
    || { echo '>> bar: cracks_4.vtp lacks the array initialJointLength  <-- FAIL'; fail=1; }
rm -rf 6e-06 8e-06
femdemFoam > log.restart 2>&1 || { tail log.restart; exit 1; }
grep -q 'Restarted from' log.restart || { echo '>> bar: the restart did not read 4e-06/femdemState  <-- FAIL'; fail=1; }
checkSeries VTK 0,2e-6,4e-6,6e-6,8e-6 || fail=1
after=$(md5sum VTK/femdem_[012].vtu VTK/cracks_[012].vtp | md5sum)
[ "$before" = "$after" ] && echo '>> bar: frames 0-2 (t <= restart time) unchanged by the restart' \
    || { echo '>> bar: frames 0-2 changed by the restart  <-- FAIL'; fail=1; }
cd ..

# ---- jwlIbFoam, coupled box
cp -r "$JWLIBFOAM_PROJECT/tests/regression/coupledData/closedBoxSolid" box && cd box
sed -i 's/(80 80 1)/(20 20 1)/' system/blockMeshDict
sed -i 's/^targetSize .*/targetSize 0.02;/; s/nSegments 48/nSegments 12/' system/femdemMeshDict
sed -i 's/^endTime .*/endTime 4e-6;/; s/^writeInterval .*/writeInterval 1;/' system/controlDict
blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 && jwlIbFoam > log.jwlIbFoam 2>&1 || { tail log.jwlIbFoam; exit 1; }
sed -i 's/^endTime .*/endTime 8e-6;/' system/controlDict
rm 4e-06/alpha.solid
if jwlIbFoam > log.restart 2>&1; then
    echo '>> box: restart from 4e-06 without alpha.solid runs (solid inside the fluid mesh)'
else
    echo ">> box: restart without alpha.solid refused  <-- FAIL"; grep -A2 FATAL log.restart; fail=1
fi
checkSeries VTK 0,2e-6,4e-6,6e-6,8e-6 || fail=1
exit $fail
