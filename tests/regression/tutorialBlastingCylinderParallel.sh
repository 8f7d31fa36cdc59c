#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# Regression: tutorials/jwlIbFoam/blastingCylinder in quick mode (TNT) on 2
# ranks (decomposePar with METIS, mpirun -np 2 jwlIbFoam -parallel, the
# solid partitioned, reconstructPar): the run reaches its end time, the
# terminal wall velocity is within 5 % of Gurney and gas + solid energy
# within the tutorial's tolerance (its plot.py on the reconstructed case),
# and crushed pockets were vented (the venting is rank-local: a pocket
# vented on one rank only once had that rank alone exchange the fluid
# fraction's processor values, and the other rank's next reduction
# received them: MPI_ERR_TRUNCATE at 11.3 us here, at 4.6 us at full
# resolution)
set -e -o pipefail
cd "$JWLIBFOAM_TEST_DIR"
rm -rf np2 && cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/blastingCylinder" np2
cd np2
./Allclean > /dev/null 2>&1 || true
rm -rf 0 && cp -r 0.orig 0    # (what the tutorial's restore0Dir does)
# The quick mode's generated entries (as ./Allrun -quick writes them)
m='#inputMode merge'
printf '%s\n%s\n' "$m" 'n 120;' > system/blockMeshDict.mode
printf '%s\n%s\n' "$m" 'targetSize 0.0005;' > system/femdemMeshDict.mode
printf '%s\n%s\n' "$m" 'endTime 2e-5;' > system/controlDict.mode
printf '%s\n' 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }' \
    'numberOfSubdomains 2;' 'method metis;' > system/decomposeParDict
for app in blockMesh femdemMesh setCharge decomposePar; do
    $app > log.$app 2>&1 || { tail -5 log.$app; echo ">> $app failed  <-- FAIL"; exit 1; }
done
mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1 \
    || { tail -8 log.jwlIbFoam; echo ">> mpirun -np 2 jwlIbFoam failed  <-- FAIL"; exit 1; }
reconstructPar > log.reconstructPar 2>&1 || { echo ">> reconstructPar failed  <-- FAIL"; exit 1; }
end=$(foamDictionary -entry endTime -value system/controlDict)
last=$(grep '^Time = ' log.jwlIbFoam | tail -1 | awk '{print $3}')
echo ">> 2 ranks: last step $last s of endTime $end s"
grep -q '^End' log.jwlIbFoam || { echo ">> the solver did not end  <-- FAIL"; exit 1; }
line=$(grep -E '^Coupled steps taken in parts' log.jwlIbFoam)
echo ">> $line"
vented=$(echo "$line" | sed -n 's/.*crushed pockets vented: \([0-9]*\).*/\1/p')
[ "${vented:-0}" -gt 0 ] || { echo ">> no pocket vented: the test does not exercise the venting  <-- FAIL"; exit 1; }
/usr/bin/python3 plot.py > log.plot 2>&1 || { tail -5 log.plot; echo ">> plot.py failed  <-- FAIL"; exit 1; }
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
