#!/bin/bash
# Joint sets lie on mesh edges: femdemMesh and gmshToFemdem meshes conform
# to the joint traces. tests/bin/jointCoverage clips every segment to the
# solid independently and measures, per set, the length of it not covered
# by the set's edges and the largest distance of a set edge from the
# segments (tolerance 1e-9 m). Cases:
#   A rectangle with a hole: two crossing joints, one ending inside the
#     solid, two crossing the boundary (one also through the hole);
#   B a polygon with a steel inclusion (two materials), a 30-fracture DFN
#     from a CSV file (random, seeded: crossings, ends inside, in the
#     inclusion, across the outline), another size and angle, -renumber;
#   C the jointedBench tutorial's bench.geo meshed by gmsh -2 and read by
#     gmshToFemdem (physical curve "joints"), D its femdemMeshDict
#     (the same traces from constant/joints.csv) meshed by femdemMesh;
#   control: case A meshed without its jointSets must fail the check.
# Then bad input, each a FatalIOError naming the file and the entry: a
# segment outside the solid (from the dictionary, from a CSV file), a
# zero-length segment and fracture, an unreadable CSV, a
# missing column, a bad number, a jointSets curve missing from the gmsh
# file, a solidMesh joint-set edge that is no triangle edge.
set -u
cd "$JWLIBFOAM_TEST_DIR"
cov="$JWLIBFOAM_PROJECT/tests/bin/jointCoverage"
bench="$JWLIBFOAM_TUTORIALS/jwlIbFoam/jointedBench"
fail=0
/usr/bin/python3 - <<'PY'
import json, math, random
def circle(c, r, n):
    return [[c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n)] for i in range(n)]
def seg(s):
    return "((%r %r) (%r %r))" % tuple(s)
head = "FoamFile { version 2.0; format ascii; class dictionary; object femdemMeshDict; }\n"
# A
A = {"crossing": [[0.1, 0.1, 0.9, 0.4], [0.1, 0.4, 0.9, 0.1]],
     "inside": [[0.55, 0.05, 0.62, 0.31]],
     "through": [[-0.2, 0.33, 1.3, 0.37], [0.3, -0.1, 0.3, 0.6]]}
sets = "\n".join(f"    {k} {{ type lines; segments ({' '.join(seg(s) for s in v)}); }}" for k, v in A.items())
open("A.dict", "w").write(head + f"""targetSize 0.05; minAngle 20;
solids {{ block {{ type rectangle; min (0 0); max (1 0.5); material rock; }} }}
holes {{ borehole {{ type circle; centre (0.3 0.25); radius 0.03; nSegments 24; }} }}
jointSets
{{
{sets}
}}
""")
json.dump({"solids": [[[0, 0], [1, 0], [1, 0.5], [0, 0.5]]], "holes": [circle((0.3, 0.25), 0.03, 24)],
           "sets": A}, open("A.json", "w"))
# B: DFN, seeded
rng = random.Random(7)
rows, segs = ["name,length,y,x,orientation,aperture"], []
for i in range(30):
    x, y, L, o = rng.uniform(-0.1, 1.3), rng.uniform(-0.1, 0.9), rng.uniform(0.05, 0.5), rng.uniform(0, 180)
    h = (0.5 * L * math.cos(math.radians(o)), 0.5 * L * math.sin(math.radians(o)))
    s = [x - h[0], y - h[1], x + h[0], y + h[1]]
    poly = [[0, 0], [1.2, 0], [1.2, 0.6], [0.6, 0.8], [0, 0.6]]
    # keep only fractures with a part in the solid (others are bad input)
    if not any(0 < s[0] + t * (s[2] - s[0]) < 1.2 and 0 < s[1] + t * (s[3] - s[1]) < 0.6 for t in [k / 50 for k in range(51)]):
        continue
    rows.append(f"f{i},{L!r},{y!r},{x!r},{o!r},1e-4")
    segs.append(s)
open("dfn.csv", "w").write("# seeded DFN\n" + "\n".join(rows) + "\n")
open("B.dict", "w").write(head + """targetSize 0.04; minAngle 25;
solids {
    plate { type polygon; points ((0 0) (1.2 0) (1.2 0.6) (0.6 0.8) (0 0.6)); material rock; }
    inclusion { type circle; centre (0.8 0.3); radius 0.12; nSegments 32; material steel; }
}
jointSets { dfn { type file; file "dfn.csv"; tensileStrength 1e6; } }
""")
json.dump({"solids": [[[0, 0], [1.2, 0], [1.2, 0.6], [0.6, 0.8], [0, 0.6]], circle((0.8, 0.3), 0.12, 32)],
           "holes": [], "sets": {"dfn": segs}}, open("B.json", "w"))
print(f">> case B: {len(segs)} DFN fractures with a part in the solid (seed 7)")
# C, D: the tutorial's traces (constant/joints.csv)
import csv, os
bench = os.path.join(os.environ["JWLIBFOAM_TUTORIALS"], "jwlIbFoam", "jointedBench")
tr = []
for r in csv.DictReader(l for l in open(os.path.join(bench, "constant", "joints.csv")) if not l.startswith("#")):
    x, y, o, L = (float(r[k]) for k in ("x", "y", "orientation", "length"))
    h = (0.5 * L * math.cos(math.radians(o)), 0.5 * L * math.sin(math.radians(o)))
    tr.append([x - h[0], y - h[1], x + h[0], y + h[1]])
json.dump({"solids": [[[-0.3, -0.4], [0.3, -0.4], [0.3, 0], [-0.3, 0]]], "holes": [circle((0, -0.15), 0.015, 24)],
           "sets": {"joints": tr}}, open("bench.json", "w"))
PY
mesh() {   # case dict [options]: femdemMesh the dictionary in a fresh case
    rm -rf "$1"; mkdir -p "$1/system"; cp "$2" "$1/system/femdemMeshDict"
    [ -f dfn.csv ] && cp dfn.csv "$1/"
    local c=$1; shift 2
    femdemMesh -case "$c" "$@" > "$c/log.femdemMesh" 2>&1
}
for c in A B; do
    opt=""; [ $c = B ] && opt=-renumber
    start=$(date +%s.%N)
    mesh $c $c.dict $opt || { tail -20 $c/log.femdemMesh; fail=1; continue; }
    echo ">> case $c: $(grep -m1 'Solid mesh:' $c/log.femdemMesh | sed 's/Solid mesh: //'), $(grep -m1 'joint sets' $c/log.femdemMesh | sed 's/.*boundary segments, //; s/, target.*//'), femdemMesh $(python3 -c "import time; print(f'{time.time() - $start:.2f}')") s"
    "$cov" $c $c.json || fail=1
    femdemMeshCheck -case $c > $c/log.femdemMeshCheck 2>&1 || { echo ">> case $c: femdemMeshCheck rejects the mesh  <-- FAIL"; fail=1; }
done
# C: gmsh route of the tutorial
rm -rf C; mkdir -p C/system C/constant; cp "$bench/system/gmshToFemdemDict" C/system/
gmsh -2 -format msh41 "$bench/bench.geo" -o C/bench.msh > C/log.gmsh 2>&1 \
    && gmshToFemdem -case C C/bench.msh > C/log.gmshToFemdem 2>&1 \
    || { tail -20 C/log.gmsh C/log.gmshToFemdem; fail=1; }
echo ">> case C (gmsh, jointedBench/bench.geo): $(grep -m1 'Solid mesh:' C/log.gmshToFemdem | sed 's/Solid mesh: //'), $(grep -m1 'joint set' C/log.gmshToFemdem | sed 's/^ *//')"
"$cov" C bench.json || fail=1
# D: femdemMesh route of the same traces
rm -rf D; mkdir -p D/system D/constant; cp "$bench/system/femdemMeshDict" D/system/
cp "$bench/constant/joints.csv" D/constant/
femdemMesh -case D > D/log.femdemMesh 2>&1 || { tail -20 D/log.femdemMesh; fail=1; }
echo ">> case D (femdemMesh, jointedBench/system/femdemMeshDict): $(grep -m1 'Solid mesh:' D/log.femdemMesh | sed 's/Solid mesh: //')"
"$cov" D bench.json || fail=1
# Control: the check fails on a mesh that ignores the joints
sed '/^jointSets/,$d' A.dict > A0.dict
mesh A0 A0.dict && /usr/bin/python3 - <<'PY' || fail=1
import json, subprocess, sys
out = subprocess.run([sys.argv[0] if False else __import__("os").environ["JWLIBFOAM_PROJECT"] + "/tests/bin/jointCoverage",
                      "A0", "A.json"], capture_output=True, text=True)
ok = out.returncode != 0 and "FAIL" in out.stdout
print(">> control (case A meshed without jointSets): the coverage check "
      + ("fails, as it must" if ok else "passes  <-- FAIL"))
sys.exit(0 if ok else 1)
PY

# ------------------------------------------------------------ bad input
bad() {   # name file entry dict-edit-command: femdemMesh must refuse
    local name=$1 file=$2 entry=$3 dict=$4
    mesh bad_$name "$dict"
    local rc=$? log=bad_$name/log.femdemMesh
    local msg=$(awk '/FOAM FATAL/ { f = 1; next } f && NF { print; exit }' $log | sed 's/^ *//' | cut -c1-110)
    if [ $rc -ne 0 ] && [ $rc -lt 128 ] && grep -q "FOAM FATAL IO ERROR" $log \
       && sed -n '/FOAM FATAL/,$p' $log | grep -qF -- "$file" \
       && sed -n '/FOAM FATAL/,$p' $log | grep -qF -- "$entry" && [ ! -e bad_$name/constant/solidMesh ]
    then
        echo ">> bad input $name: FatalIOError naming $file and '$entry' ($msg)"
    else
        echo ">> bad input $name: exit $rc, not a FatalIOError naming $file and '$entry'  <-- FAIL"
        tail -8 $log; fail=1
    fi
}
base() { sed '/^jointSets/,$d' A.dict; }
{ base; echo 'jointSets { js { type lines; segments (((2 2) (3 3))); } }'; } > d1
bad outsideSegment femdemMeshDict "entry 'segments': segment 0" d1
{ base; echo 'jointSets { js { type lines; segments (((0.2 0.2) (0.2 0.2))); } }'; } > d2
bad zeroLength femdemMeshDict "segments" d2
{ base; echo 'jointSets { js { type file; file "missing.csv"; } }'; } > d3
bad unreadableCsv missing.csv "file" d3
badCsv() {   # name csv-content entry: a joint set from that CSV file must be refused
    printf "$2" > $1.csv
    { base; echo "jointSets { js { type file; file \"$PWD/$1.csv\"; } }"; } > d_$1
    bad $1 $1.csv "$3" d_$1
}
badCsv missingColumn 'x,y,length\n0.5,0.2,0.1\n' "orientation"
badCsv badNumber 'x,y,orientation,length\n0.5,0.2,abc,0.1\n' "column 'orientation'"
badCsv zeroLengthFracture 'x,y,orientation,length\n0.5,0.2,30,0.1\n0.5,0.3,30,0\n' "line 3, column 'length'"
badCsv outsideFracture 'x,y,orientation,length\n0.5,0.2,30,0.1\n5,5,0,0.1\n' "line 3"
# gmshToFemdem: a joint set naming no interior curve
rm -rf bad_gmsh; mkdir -p bad_gmsh/system
printf 'FoamFile { version 2.0; format ascii; class dictionary; object gmshToFemdemDict; }\njointSets { faults { tensileStrength 1e6; } }\n' \
    > bad_gmsh/system/gmshToFemdemDict
gmshToFemdem -case bad_gmsh C/bench.msh > bad_gmsh/log 2>&1; rc=$?
if [ $rc -ne 0 ] && [ $rc -lt 128 ] && grep -q "FOAM FATAL IO ERROR" bad_gmsh/log && grep -q "gmshToFemdemDict" bad_gmsh/log \
   && grep -q "faults" bad_gmsh/log && [ ! -e bad_gmsh/constant/solidMesh ]; then
    echo ">> bad input gmshJointSetName: FatalIOError naming gmshToFemdemDict and 'faults'"
else
    echo ">> bad input gmshJointSetName: exit $rc  <-- FAIL"; tail -8 bad_gmsh/log; fail=1
fi
# A solidMesh whose joint-set edge is no triangle edge
cp -r A bad_mesh
/usr/bin/python3 -c "
import re; p='bad_mesh/constant/solidMesh'; s=open(p).read()
s=re.sub(r'(crossing\s*\{[^}]*?edges\s+\d+\s*\(\s*)\(\s*\d+\s+\d+\s*\)', r'\1( 0 1000000 )', s, count=1)
open(p,'w').write(s)"
femdemMeshCheck -case bad_mesh > bad_mesh/log 2>&1; rc=$?
if [ $rc -ne 0 ] && [ $rc -lt 128 ] && grep -q "FOAM FATAL IO ERROR" bad_mesh/log && grep -q "solidMesh" bad_mesh/log \
   && grep -q "jointSets/crossing/edges" bad_mesh/log; then
    echo ">> bad input meshJointEdge: FatalIOError naming solidMesh and 'jointSets/crossing/edges'"
else
    echo ">> bad input meshJointEdge: exit $rc  <-- FAIL"; tail -8 bad_mesh/log; fail=1
fi
exit $fail
