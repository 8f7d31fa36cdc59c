#!/bin/bash
# Base cases of the bad-input tests (sourced by badInputTable.sh and
# hostileInput.sh from $JWLIBFOAM_TEST_DIR): bases/<name>, each prepared once
# (mesh, fields) and checked to run (one '>> base' line each):
#   sod         Sod tube, one material (ideal gas), 20 cells, two steps
#   restart     sod run to 0.02 (written 0.01, 0.02), set to restart to 0.04
#   tnt         TNT products + air, 10x10 cells, fields before setCharge
#   tntCharged  tnt after setCharge (2e-06 removed)
#   box         coupled gas + free FEMDEM disc on 20x20 cells, 38 triangles
#   boxRestart  box run to 4e-6 (written 2e-6, 4e-6), restarts to 8e-6
#   bar         FEMDEM rectangle (femdemMesh done), two steps
#   barRun      bar run by femdemFoam (written 2e-6, 4e-6)
#   square      a unit square in gmsh 2.2 format, two triangles
#   squareRun   square after gmshToFemdem
# Defines top, header, setEntry; exits 1 if a base does not run.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
rm -rf bases cases
mkdir bases cases
top=$(pwd)
tutorials=$JWLIBFOAM_TUTORIALS
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }
setEntry() {  # file key value: replace the line 'key ...;'
    sed -i "s/^$2 .*/$2 $3;/" "$1"
}
baseFail=0
baseline() {  # name command...: a base case must run cleanly
    local name=$1; shift
    if (cd "bases/$name" && "$@" > "log.baseline.$1" 2>&1); then
        echo ">> base $name: $* runs"
    else
        echo ">> base $name: $* fails on the unbroken input  <-- FAIL"
        tail -20 "bases/$name/log.baseline.$1"
        baseFail=1
    fi
}

# ----------------------------------------------------------------- bases
# sod: one material (ideal gas), 20 cells, two steps
cp -r "$tutorials/jwlIbFoam/sodShockTube" bases/sod
(
    cd bases/sod && ./Allclean > /dev/null 2>&1
    rm -rf mesh* && cp -r 0.orig 0
    setEntry system/blockMeshDict nx 20
    setEntry system/controlDict endTime 0.02
    setEntry system/controlDict writeInterval 0.01
    blockMesh > log.blockMesh 2>&1 && setFields > log.setFields 2>&1
) || { echo ">> base sod: blockMesh/setFields failed  <-- FAIL"; exit 1; }
# restart: sod run to 0.02 (written 0.01, 0.02), restarted from latestTime
cp -r bases/sod bases/restart
baseline restart jwlIbFoam
setEntry bases/restart/system/controlDict startFrom latestTime
setEntry bases/restart/system/controlDict endTime 0.04

# tnt: TNT products + air, 10x10 cells, fields before setCharge
cp -r "$tutorials/jwlIbFoam/tntCharge2D" bases/tnt
(
    cd bases/tnt && ./Allclean > /dev/null 2>&1
    rm -rf parallel VTK && find . -maxdepth 1 -name "[0-9]*" ! -name 0.orig -exec rm -rf {} + && cp -r 0.orig 0
    setEntry system/blockMeshDict n 10
    setEntry system/controlDict endTime 2e-6
    setEntry system/controlDict writeInterval 2e-6
    blockMesh > log.blockMesh 2>&1
) || { echo ">> base tnt: blockMesh failed  <-- FAIL"; exit 1; }
cp -r bases/tnt bases/tntCharged
baseline tntCharged setCharge
baseline tntCharged jwlIbFoam
rm -rf bases/tntCharged/2e-06

# box: coupled gas + free FEMDEM disc (tests/regression/coupledData/
# closedBoxSolid on 20x20 cells, 38 triangles), two steps of 2e-6 s
cp -r "$JWLIBFOAM_PROJECT/tests/regression/coupledData/closedBoxSolid" bases/box
(
    cd bases/box
    sed -i 's/(80 80 1)/(20 20 1)/' system/blockMeshDict
    setEntry system/femdemMeshDict targetSize 0.02
    sed -i 's/nSegments 48/nSegments 12/' system/femdemMeshDict
    setEntry system/controlDict endTime 4e-6
    setEntry system/controlDict writeInterval 1
    blockMesh > log.blockMesh 2>&1
) || { echo ">> base box: blockMesh failed  <-- FAIL"; exit 1; }
baseline box femdemMesh
# boxRestart: box run to 4e-6 (written 2e-6, 4e-6), restarted from latestTime
cp -r bases/box bases/boxRestart
baseline boxRestart jwlIbFoam
setEntry bases/boxRestart/system/controlDict endTime 8e-6

# bar: FEMDEM rectangle, a few triangles, two steps
mkdir -p bases/bar/system bases/bar/constant
{ header controlDict; cat <<'D'; } > bases/bar/system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 4e-6; deltaT 2e-6; writeControl runTime; writeInterval 2e-6;
D
{ header femdemMeshDict; cat <<'D'; } > bases/bar/system/femdemMeshDict
targetSize 0.01;
minAngle 20;
solids { bar { type rectangle; min (0 0); max (0.03 0.02); material rock;
               patches (bottom right top left); } }
D
{ header femdemProperties; cat <<'D'; } > bases/bar/constant/femdemProperties
cohesiveLaw munjiza;
contactLaw potential;
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6;
                   cohesion 8e6; frictionAngle 30; GI 20; GII 200; dampingRatio 0.1; } }
boundaryConditions { left { type fixed; } right { type velocity; value (3 0.5); } }
output { vtk false; reactions (left right); }
D
baseline bar femdemMesh
cp -r bases/bar bases/barRun
baseline barRun femdemFoam
baseline barRun femdemMeshCheck

# square: a unit square in gmsh 2.2 format, two triangles, one material
mkdir -p bases/square/constant
cat > bases/square/square.msh <<'D'
$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "walls"
2 2 "rock"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
6
1 1 2 1 1 1 2
2 1 2 1 1 2 3
3 1 2 1 1 3 4
4 1 2 1 1 4 1
5 2 2 2 1 1 2 3
6 2 2 2 1 1 3 4
$EndElements
D
cp -r bases/square bases/squareRun
baseline squareRun gmshToFemdem square.msh
[ $baseFail = 0 ] || { echo ">> base cases do not run: no table"; exit 1; }
