#!/bin/bash
# Regression: tutorials/jwlIbFoam/jointedBench -quick (75 us of the bench
# blast in jointed rock, the mesh from bench.geo by gmsh -2 and
# gmshToFemdem): benchBlast's checks (positivity, gas mass, fragment
# partition, fits) from its summary.json, the joint set in the mesh and
# breaking more than its share of the joint length; fragment count and x50
# printed beside benchBlast's quick run when its test has run before
# (tests/results/tutorialBenchBlast; not a check: another mesh).
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/jointedBench" .
cd jointedBench
./Allclean > /dev/null 2>&1 || true
start=$(date +%s)
./Allrun -quick
echo ">> Allrun -quick: $(( $(date +%s) - start )) s wall; $(cat log.runTime)"
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
/usr/bin/python3 - "$JWLIBFOAM_PROJECT/tests/results/tutorialBenchBlast/benchBlast/summary.json" <<'PY'
import json, os, sys
f = {x["name"]: x["value"] for x in json.load(open("summary.json"))["figures"]}
get = lambda v, s: next((v[k] for k in v if k.startswith(s)), None)
n = get(f, "joint-set joints")
ok = n is not None and n > 0 and get(f, "joint set breaks more than its share") is not None
print(f">> joint set in the mesh: {n} joints; its share of the broken length"
      f" {get(f, 'joint-set share of the broken') or 0:.3f} against its length share"
      f" {get(f, 'joint-set share of the joint length') or 0:.3f}" + ("" if ok else "  <-- FAIL"))
ref = sys.argv[1]
if os.path.exists(ref):
    b = {x["name"]: x["value"] for x in json.load(open(ref))["figures"]}
    print(f">> beside benchBlast -quick -crackGas (no joints, its own mesh, 0.2 ms against 75 us): fragments {get(f, 'fragments (loose'):.0f}"
          f" vs {get(b, 'fragments (loose'):.0f}, x50 {get(f, 'x50 measured'):.4f} m vs"
          f" {get(b, 'x50 measured'):.4f} m, broken joints {get(f, 'broken joints'):.0f}"
          f" vs {get(b, 'broken joints'):.0f}")
else:
    print(">> benchBlast -quick not run before in tests/results: no side-by-side figures")
sys.exit(0 if ok else 1)
PY
