#!/bin/bash
# Regression: programmed burn (setCharge initiationTime + primer), planar TNT
# detonation from the closed wall x = 0 of a 1D tube (explosive 0..0.1 m,
# air to 0.12 m), 600 and 1200 cells, 10 us. Against the exact solution
# computed from the JWL coefficients (programmedBurnData/check.py): the
# detonation velocity of the pressure front (1 %), the peak pressure against
# the CJ pressure of the JWL set (10 %, error falling with refinement), the
# Taylor-wave plateau pressure and extent (3 %), the L1 error of the profile
# (falling with refinement). The same at 600 cells for CompB, and for HMX,
# whose preset D (9110 m/s) exceeds the CJ velocity of its JWL set (8995):
# the burn drives a weak detonation, whose front pressure (the lower
# intersection of the Rayleigh line with the Hugoniot, 32.9 GPa, not p_CJ
# 40.0 GPa) is then the reference.
set -e
cd "$JWLIBFOAM_TEST_DIR"
data="$JWLIBFOAM_PROJECT/tests/regression/programmedBurnData"
run()   # run <case> <explosive> <cells>
{
    rm -rf $1 && cp -r "$data/planar" $1
    sed -i "s/^nx .*/nx $3;/" $1/system/blockMeshDict
    sed -i "s/explosive TNT;/explosive $2;/" $1/constant/thermophysicalProperties
    cp -r $1/0.orig $1/0
    blockMesh -case $1 > $1/log.blockMesh 2>&1
    setCharge -case $1 > $1/log.setCharge 2>&1
    jwlIbFoam -case $1 > $1/log.jwlIbFoam 2>&1
}
run tnt600 TNT 600
run tnt1200 TNT 1200
run compB600 CompB 600
run hmx600 HMX 600
fail=0
/usr/bin/python3 "$data/check.py" --refinement tnt600 tnt1200 || fail=1
/usr/bin/python3 "$data/check.py" compB600 hmx600 || fail=1
exit $fail
