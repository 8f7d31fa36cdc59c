#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# The tutorials' -np N -method NAME options (tutorials/jwlIbFoam/common/
# parallelFunctions), on a copy of benchBlast: a wrong -np, an unknown method
# and -method without -np are refused before any mesh is made, with the
# option named, and leave the tracked files as they are; then
# './Allrun -quick -noLined -np 2 -method ptscotch' (decomposed by
# redistributePar; without the lined copy, which has nothing to do with the
# decomposition; the flagship's default, the crack gas, on 2 ranks: 130 s)
# and '-method scotch -noCrackGas' (decomposePar; the mesh venting only, 35 s)
# run, their logs show the method, their figures pass checkSummary, and the
# fragment count and x50 are printed beside the serial quick run of test
# tutorialBenchBlast (with the crack gas) when it has run before (not a
# check: the gas reductions differ in the last bits between decompositions,
# and fracture amplifies them). On the ptscotch case, the crack network's
# nodes read from the halo against gathered (crackNodes below).
set -eu
cd "$JWLIBFOAM_TEST_DIR" && rm -rf benchBlast
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/benchBlast" . && cd benchBlast
fail=0

refused() {  # expected-message options...: refused, before meshing, nothing tracked changed
    local want=$1; shift
    touch "$JWLIBFOAM_TEST_DIR/stamp"; sleep 1
    if ./Allrun "$@" > ../log.refused 2>&1; then
        echo ">> Allrun $*: ran  <-- FAIL"; fail=1; return
    fi
    local changed
    changed=$(find 0.orig constant system -type f -newer "$JWLIBFOAM_TEST_DIR/stamp" | tr '\n' ' ')
    if ! grep -q -- "$want" ../log.refused || [ -e log.blockMesh ] || [ -n "$changed" ]; then
        tail -3 ../log.refused
        echo ">> Allrun $*: not refused with '$want' before meshing, or files changed ($changed)  <-- FAIL"; fail=1
    else
        echo ">> Allrun $*: refused: $(grep -m1 -- "$want" ../log.refused)"
    fi
}
refused "-np 'x': expected an integer" -quick -np x
refused "-method 'kahip' is not a decomposition method here" -quick -np 2 -method kahip
refused "-method scotch needs -np N with N > 1" -quick -method scotch

ref=$JWLIBFOAM_PROJECT/tests/results/tutorialBenchBlast/benchBlast/summary.json

# The crack network's nodes on the partitioned solid are read from the local
# solid (owned or halo: the halo exchange carries their work displacement);
# the fallback for a rank reading a node outside its halo gathers the nodes
# a rank does not own from their owners twice per sub-step. Forced by
# 'DebugSwitches { crackGasCoupling 1; }' on the decomposed case to 20 us,
# it must exchange nodes (the default none) and give budget.dat byte for byte
crackNodes() {
    local mode n
    for mode in halo gather; do
        rm -rf "../nodes.$mode" && mkdir "../nodes.$mode"
        cp -r system constant processor* "../nodes.$mode/"
        (
            cd "../nodes.$mode" || exit 1
            rm -rf processor*/[1-9]* processor*/0.[0-9]* system/controlDict.mode
            sed -i 's/^endTime .*/endTime 2e-5;/; s/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime 0;/' system/controlDict
            [ $mode = gather ] && printf 'DebugSwitches { crackGasCoupling 1; }\n' >> system/controlDict
            timeout 300 mpirun -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1
        ) || { tail -5 "../nodes.$mode/log.jwlIbFoam"; echo ">> crack nodes ($mode): jwlIbFoam to 20 us failed  <-- FAIL"; return 1; }
    done
    local nHalo nGather
    nHalo=$(grep -o 'nodes exchanged per sub-step at most [0-9]*' ../nodes.halo/log.jwlIbFoam | awk '{print $NF}')
    nGather=$(grep -o 'nodes exchanged per sub-step at most [0-9]*' ../nodes.gather/log.jwlIbFoam | awk '{print $NF}')
    n=$(grep -c '^Time = ' ../nodes.halo/log.jwlIbFoam)
    echo ">> crack nodes, 2 ranks to 20 us ($n steps): exchanged per sub-step ${nHalo:-?} (read from the halo, default), ${nGather:-?} (gather forced)"
    if [ "${nHalo:-1}" != 0 ] || [ "${nGather:-0}" -lt 1 ]; then
        echo ">> expected none exchanged by default and some with the gather forced  <-- FAIL"; return 1
    fi
    if cmp -s ../nodes.halo/postProcessing/jwlIbFoam/0/budget.dat ../nodes.gather/postProcessing/jwlIbFoam/0/budget.dat; then
        echo ">> crack nodes gathered: budget.dat equal to the default run's, byte for byte ($(wc -l < ../nodes.halo/postProcessing/jwlIbFoam/0/budget.dat) lines)"
    else
        echo ">> crack nodes gathered: budget.dat differs from the default run's  <-- FAIL"; return 1
    fi
}
for method in ptscotch scotch; do
    start=$(date +%s)
    gas=$([ $method = scotch ] && echo -noCrackGas || true)
    ./Allrun -quick -noLined $gas -np 2 -method $method > ../log.Allrun.$method 2>&1 \
        || { tail -20 ../log.Allrun.$method; echo ">> Allrun -quick -noLined $gas -np 2 -method $method failed  <-- FAIL"; exit 1; }
    log=$([ $method = ptscotch ] && echo log.redistributePar || echo log.decomposePar)
    if grep -q "^Selecting decompositionMethod $method \[2\]" $log; then
        echo ">> -method $method: $log: $(grep -m1 '^Selecting decompositionMethod' $log); $(grep -m1 'Max number of cells' $log | sed 's/^ *//'); $(( $(date +%s) - start )) s wall"
    else
        echo ">> -method $method: $log does not select $method  <-- FAIL"; fail=1
    fi
    "$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json || fail=1
    [ $method = ptscotch ] && { crackNodes || fail=1; }
    /usr/bin/python3 - "$method" "$ref" <<'PY'
import json, os, sys
method, ref = sys.argv[1], sys.argv[2]
get = lambda f, s: next(x["value"] for x in json.load(open(f))["figures"] if x["name"].startswith(s))
line = (f">> -np 2 -method {method}{' -noCrackGas' if method == 'scotch' else ' (crack gas)'}: fragments {get('summary.json', 'fragments (loose'):.0f},"
        f" x50 {get('summary.json', 'x50 measured'):.4f} m, broken joints {get('summary.json', 'broken joints'):.0f}")
if os.path.exists(ref):
    line += (f"; serial with the crack gas (tutorialBenchBlast): {get(ref, 'fragments (loose'):.0f},"
             f" {get(ref, 'x50 measured'):.4f} m, {get(ref, 'broken joints'):.0f}")
print(line)
PY
done
exit $fail
