#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 solvers at once)
# Regression: tutorials/jwlIbFoam/benchBlast -quick -water (0.1 ms): the
# charge decoupled by a water-filled gap (three materials: products water
# air, setCharge's water fill) in water/ beside the same charge with the air
# gap, one core each. Checked: both run to the end, the gas + solid energy
# of each within the tutorial's 1e-2 (checkSummary), and water transmits
# more: the peak hole-wall pressure of the water gap above the air gap's;
# printed beside the impedance-matching and Esen et al. estimates
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/benchBlast" .
cd benchBlast
./Allclean > /dev/null 2>&1 || true
start=$(date +%s)
./Allrun -quick -water
echo ">> ./Allrun -quick -water (air gap here, water gap in water/, concurrently): $(( $(date +%s) - start )) s wall"
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" water/summary.json
/usr/bin/python3 - <<'PY'
import json, sys
def figs(path):
    return {x["name"]: x["value"] for x in json.load(open(path))["figures"]}
f, w = figs("summary.json"), figs("water/summary.json")
def get(d, start):
    keys = [k for k in d if k.startswith(start)]
    if not keys:
        sys.exit(f">> no figure '{start}...'  <-- FAIL")
    return d[keys[0]]
pa = get(f, "water versus air: peak hole-wall pressure, air gap")
pw = get(f, "water versus air: peak hole-wall pressure, water gap")
ea = get(f, "water versus air: estimate, air gap")
ew = get(f, "water versus air: estimate, water gap")
print(f">> peak hole-wall pressure: air gap {pa:.4g} Pa (estimate, Esen et al. quasi-static {ea:.4g}),"
      f" water gap {pw:.4g} Pa (estimate, impedance matching {ew:.4g}); ratio water/air"
      f" {pw / pa:.3g} (estimate {ew / ea:.3g})")
ge, gw = get(f, "energy gained by gas + solid"), get(w, "energy gained by gas + solid")
print(f">> gas + solid energy change / initial gas energy: air gap {ge:.3g}, water gap {gw:.3g}"
      " (tolerance 1e-2)")
checks = [
    ("both at 0.1 ms", abs(get(f, "end time") - 1e-4) < 1e-12 and abs(get(w, "end time") - 1e-4) < 1e-12),
    ("water gap: three materials", get(w, "gap material") == 1 and get(f, "gap material") == 0),
    (f"water transmits more: peak hole-wall pressure water/air {pw / pa:.3g} > 1", pw > pa),
    (f"energy budgets within 1e-2 ({ge:.3g}, {gw:.3g})", abs(ge) <= 1e-2 and abs(gw) <= 1e-2),
]
for name, ok in checks:
    print(f">> {name}: {'yes' if ok else 'no  <-- FAIL'}")
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
