#!/bin/bash
# Regression: programmed burn (setCharge initiationTime + primer), planar TNT
# detonation from the closed wall x = 0 of a 1D tube (explosive 0..0.1 m,
# air to 0.12 m), 600 and 1200 cells, 10 us. Against the exact solution
# computed from the JWL coefficients (programmedBurnData/check.py): the
# detonation velocity of the pressure front (1 %), the peak pressure against
# the CJ pressure of the JWL set (10 %, error falling with refinement), the
# Taylor-wave plateau pressure and extent (3 %), the L1 error of the profile
# (falling with refinement).
set -e
cd "$JWLIBFOAM_TEST_DIR"
data="$JWLIBFOAM_PROJECT/tests/regression/programmedBurnData"
for n in 600 1200
do
    c=tnt$n
    rm -rf $c && cp -r "$data/planar" $c
    sed -i "s/^nx .*/nx $n;/" $c/system/blockMeshDict
    cp -r $c/0.orig $c/0
    blockMesh -case $c > $c/log.blockMesh 2>&1
    setCharge -case $c > $c/log.setCharge 2>&1
    jwlIbFoam -case $c > $c/log.jwlIbFoam 2>&1
done
/usr/bin/python3 "$data/check.py" tnt600 tnt1200
