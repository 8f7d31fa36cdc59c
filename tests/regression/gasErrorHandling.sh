#!/bin/bash
# Regression: jwlIbFoam stops cleanly on bad input and on a non-physical state.
#  1. misspelt entry in constant/thermophysicalProperties -> FatalIOError
#     naming the file and the entry
#  2. omega <= 0 for JWL -> rejected
#  3. unstable run (maxCo 3) -> stops naming time and cell, exit != 0, and
#     writes no time directory for the failed step
cd "$JWLIBFOAM_TEST_DIR" || exit 1
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/sodShockTube" base
cd base
./Allclean > /dev/null 2>&1
cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 && setFields > log.setFields 2>&1 || exit 1
fail=0

cp -r . ../misspelt
sed -i 's/equationOfState idealGas/equationOfStat idealGas/' ../misspelt/constant/thermophysicalProperties
if jwlIbFoam -case ../misspelt > ../misspelt.log 2>&1; then
    echo ">> misspelt entry: solver did not stop  <-- FAIL"; fail=1
elif grep -q "equationOfState" ../misspelt.log && grep -q "thermophysicalProperties" ../misspelt.log; then
    echo ">> misspelt entry: FatalIOError names file and entry: $(grep -m1 -o "Entry '[^']*' not found" ../misspelt.log)"
else
    echo ">> misspelt entry: message lacks file/entry  <-- FAIL"; fail=1
fi

cp -r . ../badOmega
cat > ../badOmega/constant/thermophysicalProperties <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object thermophysicalProperties; }
materials (air);
air { equationOfState JWL; explosive TNT; omega -0.3; }
EOD
if jwlIbFoam -case ../badOmega > ../badOmega.log 2>&1; then
    echo ">> omega <= 0: accepted  <-- FAIL"; fail=1
elif grep -q "omega" ../badOmega.log; then
    echo ">> omega <= 0: rejected ($(grep -m1 "omega" ../badOmega.log | sed 's/^ *//'))"
else
    echo ">> omega <= 0: no clear message  <-- FAIL"; fail=1
fi

sed -i 's/^maxCo .*/maxCo           3;/; s/^writeInterval .*/writeInterval   0.01;/' system/controlDict
if jwlIbFoam > log.unstable 2>&1; then
    echo ">> unstable run: did not stop  <-- FAIL"; fail=1
else
    msg=$(grep -m1 "non-physical state at time" log.unstable)
    t=$(echo "$msg" | sed -n 's/.*at time \([^ ]*\) in cell.*/\1/p')
    if [ -n "$t" ] && [ ! -d "$t" ]; then
        echo ">> unstable run stopped: ${msg:0:90}"
        echo ">> no time directory written for the failed time $t"
    else
        echo ">> unstable run: message or time directory wrong  <-- FAIL"; fail=1
    fi
fi
exit $fail
