#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 and 3 MPI ranks)
# femdemFoam in parallel (issue 15): 'mpirun -np N femdemFoam -parallel' on
# the undecomposed case partitions the solid (femdemPartition). A 0.2 m x
# 0.1 m plate meshed by femdemMesh, fractured with contact, run serial and
# in parallel; each case must give:
# - final node positions and velocities (femdemState entries x and v)
#   byte-identical to the serial run's (the acceptance asks 1e-8; the halo
#   gives every owned node the serial forces in the serial order);
# - fragments.dat and crackEvents.dat identical (fragments and cracks of the
#   state gathered on the master), reactions within 1e-9 of their scale;
# - the energy budget (each rank counts its owned nodes and joints, summed):
#   every column within 1e-9 of the input energy of the serial run's, the
#   budget residual below 1 % of the input (both runs);
# - the fracture it tests (broken joints, fragments >= 2) and, for the fast
#   loads, halo rebuilds (parts moving across the partition);
# - the crushed plate on 3 ranks: at least one load-balancing repartition
#   (maxImbalance 0.01: its imbalance stays under the default 10 %) with triangles migrating
#   to another rank, the figures above unchanged by it; the same case
#   stopped at half time and restarted on 3 ranks continues bitwise with
#   the owners it wrote (entry triangleOwner of the state).
# Restarts: a parallel run stopped at half time and restarted on 2 ranks,
# a serial run continued on 3 ranks and a 2-rank run continued serially all
# end with x and v byte-identical to the uninterrupted serial run (the
# state is one global femdemState in the case directory).
# The brazilianDisc tutorial with Allrun -quick -np 2 gives the serial
# summary.json. The memory line (local solid per rank, 1 -> 2 -> 3 ranks) is
# printed.
set -u
cd "$JWLIBFOAM_TEST_DIR" || exit 1
fail=0
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }

makeCase() {  # dir endTime bcs reactionPatches extraProperties
    local d=$1 endTime=$2 bcs=$3 reactions=$4 extra=$5
    rm -rf "$d" && mkdir -p "$d/system" "$d/constant"
    { header controlDict; cat <<D; } > "$d/system/controlDict"
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime $endTime; deltaT 1e-6; writeControl adjustableRunTime;
writeInterval $(python3 -c "print($endTime/2)");
D
    { header femdemMeshDict; cat <<'D'; } > "$d/system/femdemMeshDict"
targetSize 0.006; minAngle 25;
solids { plate { type rectangle; min (0 0); max (0.2 0.1); material rock;
                 patches (bottom right top left); } }
D
    { header femdemProperties; cat <<D; } > "$d/constant/femdemProperties"
cohesiveLaw munjiza; contactLaw potential; $extra
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6;
                   cohesion 8e6; frictionAngle 30; GI 20; GII 200; dampingRatio 0.2;
                   strengthDistribution { type Weibull; modulus 6; seed 77; } } }
boundaryConditions { $bcs }
output { vtk false; reactions ($reactions); logInterval 5e-6; }
D
    (cd "$d" && femdemMesh > log.femdemMesh 2>&1) || { echo ">> $d: femdemMesh failed  <-- FAIL"; fail=1; }
}

runCase() {  # dir np  (np 1: serial)
    local d=$1 np=$2
    if [ "$np" = 1 ]; then
        (cd "$d" && femdemFoam > log.femdemFoam 2>&1)
    else
        (cd "$d" && mpirun -np "$np" femdemFoam -parallel > log.femdemFoam 2>&1)
    fi || { tail -n 20 "$d/log.femdemFoam"; echo ">> $d: femdemFoam on $np rank(s) failed  <-- FAIL"; fail=1; return 1; }
}

# Entries x and v of a femdemState, one line each (the node lists)
nodes() { grep -E '^(x|v) ' "$1"; }

compare() {  # name serialDir parDir np minBroken minRebuilds [minRepartitions]
    local name=$1 s=$2 p=$3 np=$4 minBroken=$5 minRebuilds=$6 minRepart=${7:-0}
    local last; last=$(ls -d "$s"/[0-9]* | sort -t/ -k2 -g | tail -1); last=${last##*/}
    local sameNodes=no
    if [ -f "$p/$last/femdemState" ] && cmp -s <(nodes "$s/$last/femdemState") <(nodes "$p/$last/femdemState"); then sameNodes=yes; fi
    local pp=postProcessing/femdem/0
    local sameFrag=no sameCracks=no
    cmp -s "$s/$pp/fragments.dat" "$p/$pp/fragments.dat" && sameFrag=yes
    cmp -s "$s/$pp/crackEvents.dat" "$p/$pp/crackEvents.dat" && sameCracks=yes
    local rebuilds; rebuilds=$(grep -o 'Halo rebuilds [0-9]*' "$p/log.femdemFoam" | awk '{print $3}')
    local repart migrated
    read -r repart migrated <<< "$(sed -n 's/^Load-balancing repartitions \([0-9]*\) (\([0-9]*\) triangles migrated).*/\1 \2/p' "$p/log.femdemFoam")"
    local fig
    fig=$(python3 - "$s/$pp" "$p/$pp" <<'PY'
import sys
def table(path):
    rows = [l.split() for l in open(path)]
    head = rows[0][1:]
    return head, [[float(v) for v in r] for r in rows[1:]]
hs, es = table(sys.argv[1] + '/energy.dat')
hp, ep = table(sys.argv[2] + '/energy.dat')
c = {n: i for i, n in enumerate(hs)}
scale = max(abs(r[c['initial']] + r[c['external']] + r[c['gravity']]) for r in es)
dE = max(abs(a - b) for ra, rb in zip(es, ep) for a, b in zip(ra[1:], rb[1:])) / scale
res = max(max(abs(r[c['residual']]) for r in es), max(abs(r[c['residual']]) for r in ep)) / scale
hs, rs = table(sys.argv[1] + '/reactions.dat')
hp, rp = table(sys.argv[2] + '/reactions.dat')
rscale = max(abs(v) for r in rs for v in r[1:])
dR = max(abs(a - b) for ra, rb in zip(rs, rp) for a, b in zip(ra[1:], rb[1:])) / rscale
hs, fs = table(sys.argv[1] + '/fragments.dat')
cf = {n: i for i, n in enumerate(hs)}
print(f"{len(es)} {len(ep)} {dE:.3e} {res:.3e} {dR:.3e} {int(fs[-1][cf['nBrokenJoints']])} {int(fs[-1][cf['nFragments']])} {scale:.4g}")
PY
)
    read -r ns npar dE res dR broken frags input <<< "$fig"
    echo ">> $name ($np ranks): t = $last s, broken joints $broken, fragments $frags, halo rebuilds $rebuilds," \
         "load-balancing repartitions ${repart:-?} (${migrated:-?} triangles migrated);" \
         "x, v identical to serial: $sameNodes; fragments.dat identical: $sameFrag; crackEvents.dat identical: $sameCracks;" \
         "energy columns max |difference| / input $dE (input $input J/m, $ns/$npar rows), residual / input $res, reactions max difference / scale $dR"
    [ "$sameNodes" = yes ] || { echo ">> $name: node positions/velocities differ from serial  <-- FAIL"; fail=1; }
    [ "$sameFrag" = yes ] && [ "$sameCracks" = yes ] || { echo ">> $name: fragments or cracks differ from serial  <-- FAIL"; fail=1; }
    [ "$ns" = "$npar" ] || { echo ">> $name: energy.dat rows $ns serial, $npar parallel  <-- FAIL"; fail=1; }
    python3 -c "import sys; sys.exit(0 if $dE < 1e-9 and $res < 1e-2 and $dR < 1e-9 else 1)" \
        || { echo ">> $name: energy budget or reactions differ from serial (or residual >= 1 %)  <-- FAIL"; fail=1; }
    [ "${broken:-0}" -ge "$minBroken" ] && [ "${frags:-0}" -ge 2 ] \
        || { echo ">> $name: $broken broken joints / $frags fragments, the case needs >= $minBroken and >= 2  <-- FAIL"; fail=1; }
    [ "${rebuilds:-0}" -ge "$minRebuilds" ] \
        || { echo ">> $name: $rebuilds halo rebuilds, fewer than $minRebuilds  <-- FAIL"; fail=1; }
    [ -n "${repart:-}" ] && [ "$repart" -ge "$minRepart" ] && { [ "$minRepart" = 0 ] || [ "${migrated:-0}" -gt 0 ]; } \
        || { echo ">> $name: ${repart:-no} load-balancing repartitions (${migrated:-no} triangles migrated), the case needs >= $minRepart  <-- FAIL"; fail=1; }
}

# 1. Torn apart fast: the right part flies off across the partition, 2 ranks
pull='left { type fixed; } right { type velocity; value (30 5); rampTime 2e-6; }'
makeCase pullSerial 8e-5 "$pull" "left right" "partition { haloWidth 0.004; }"
cp -r pullSerial pull2 && cp -r pullSerial pullSplit && cp -r pullSerial pullToSerial
runCase pullSerial 1 && runCase pull2 2 && compare pull pullSerial pull2 2 40 1

# 2. A fast platen crushing the plate, St Venant-Kirchhoff, 3 ranks
impact='bottom { type fixed; } top { type velocity; value (5 -40); rampTime 2e-6; }'
makeCase impactSerial 8e-5 "$impact" "top bottom" "elasticLaw StVenantKirchhoff; partition { haloWidth 0.008; maxImbalance 0.01; }"
cp -r impactSerial impact3 && cp -r impactSerial impactSerialTo3 && cp -r impactSerial impactSplit3
runCase impactSerial 1 && runCase impact3 3 && compare impact impactSerial impact3 3 300 1 1

# 3. Restarts
half=4e-05
same() {  # name serialDir dir
    local last=8e-05
    if cmp -s <(nodes "$2/$last/femdemState") <(nodes "$3/$last/femdemState"); then
        echo ">> $1: x, v at $last s identical to the uninterrupted serial run: yes ($(grep -m1 -o 'Restarted from.*' "$3/log.femdemFoam"))"
    else
        echo ">> $1: x, v at $last s differ from the uninterrupted serial run  <-- FAIL"; fail=1
    fi
}
setEnd() { sed -i "s/endTime [^;]*;/endTime $2;/" "$1/system/controlDict"; }
# 3a. parallel, stopped at half time, restarted on 2 ranks (latestTime)
setEnd pullSplit $half && runCase pullSplit 2 && setEnd pullSplit 8e-5 && runCase pullSplit 2 \
    && same "restart 2 ranks -> 2 ranks" pullSerial pullSplit
# 3a'. the crushed plate on 3 ranks, stopped at half time (after its first
#     repartition), restarted on 3 ranks: the owners come from the state
setEnd impactSplit3 $half && runCase impactSplit3 3 && setEnd impactSplit3 8e-5 && runCase impactSplit3 3 \
    && same "restart 3 ranks -> 3 ranks, owners rebalanced ($(grep -o 'Load-balancing repartitions.*' impactSplit3/log.femdemFoam))" impactSerial impactSplit3
grep -q '^triangleOwner' impactSplit3/$half/femdemState \
    || { echo ">> impactSplit3: no entry triangleOwner in the state at $half  <-- FAIL"; fail=1; }
# 3b. 2 ranks, continued serially
setEnd pullToSerial $half && runCase pullToSerial 2 && setEnd pullToSerial 8e-5 && runCase pullToSerial 1 \
    && same "restart 2 ranks -> serial" pullSerial pullToSerial
# 3c. serial, continued on 3 ranks (no processor directories: startTime)
setEnd impactSerialTo3 $half && runCase impactSerialTo3 1 && setEnd impactSerialTo3 8e-5 \
    && sed -i "s/startFrom latestTime;/startFrom startTime;/; s/startTime 0;/startTime $half;/" impactSerialTo3/system/controlDict \
    && runCase impactSerialTo3 3 && same "restart serial -> 3 ranks" impactSerial impactSerialTo3

# 4. The brazilianDisc tutorial, Allrun -quick and Allrun -quick -np 2: the
#    same figures (summary.json) and the same final positions
root=$(cd "$(dirname "$0")/../.." && pwd)
for d in discSerial disc2; do
    rm -rf "$d" && cp -r "$root/tutorials/femdemFoam/brazilianDisc" "$d"
done
(cd discSerial && ./Allrun -quick > log.Allrun 2>&1) && (cd disc2 && ./Allrun -quick -np 2 > log.Allrun 2>&1) \
    || { echo ">> brazilianDisc: Allrun -quick [-np 2] failed  <-- FAIL"; fail=1; }
if [ -f disc2/summary.json ]; then
    lastDisc=$(ls -d discSerial/[0-9]* | sort -t/ -k2 -g | tail -1); lastDisc=${lastDisc##*/}
    same=no; cmp -s <(nodes "discSerial/$lastDisc/femdemState") <(nodes "disc2/$lastDisc/femdemState") && same=yes
    diffs=$(python3 - discSerial/summary.json disc2/summary.json <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
def flat(x, p=''):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from flat(v, p + '/' + k)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from flat(v, f'{p}[{i}]')
    else:
        yield p, x
fa, fb = dict(flat(a)), dict(flat(b))
bad = [k for k in fa if fa[k] != fb.get(k)]
print(len(fa), len(bad), ' '.join(bad[:5]))
PY
)
    read -r nFig nBad badKeys <<< "$diffs"
    echo ">> brazilianDisc tutorial, Allrun -quick -np 2 vs serial: $nFig summary.json entries, $nBad different ${badKeys:-}; x, v at $lastDisc s identical: $same"
    [ "$nBad" = 0 ] && [ "$same" = yes ] || { echo ">> brazilianDisc on 2 ranks differs from serial  <-- FAIL"; fail=1; }
fi

# Memory of the solid per rank, 1 -> 2 -> 3 ranks (same mesh, femdemMesh)
echo ">> memory, serial: $(grep -m1 'Solid memory:' pullSerial/log.femdemFoam)"
for d in pull2 impact3; do
    echo ">> memory, $d: $(grep -m1 'Solid memory per rank' "$d/log.femdemFoam"); $(grep -m1 "master's gathered copy" "$d/log.femdemFoam")"
done
exit $fail
