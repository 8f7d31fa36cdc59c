#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 solvers at once)
# Regression: tutorials/jwlIbFoam/benchBlast -quick -water (0.2 ms): the
# charge decoupled by a water-filled gap (three materials: products water
# air, setCharge's water fill) in water/ beside the same charge with the air
# gap, one core each. Checked: both run to the end (0.2 ms: the water drawn
# into the opening cracks cavitates, cut-off model; without it the water
# run stopped at 0.145 ms), the gas + solid energy of each within the
# tutorial's 1e-2 (checkSummary), and water transmits more: the peak
# hole-wall pressure of the water gap above the air gap's; printed beside
# the impedance-matching and Esen et al. estimates, and the water cells at
# the cavitation pressure at the end
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
# Cavitation (cut-off at the water's cavitationPressure, 2300 Pa): the
# cells at it at the end and the first step whose smallest pressure is it
import os, re
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_TUTORIALS"], "jwlIbFoam", "common"))
from blastPost import read_field, log_table
pCav = 2300.0
pEnd = read_field("water", "0.0002", "p")
aw = read_field("water", "0.0002", "alpha.water", len(pEnd))
ap = read_field("water", "0.0002", "alpha.products", len(pEnd))
cav = pEnd == pCav
steps = log_table("water/log.jwlIbFoam")
first = steps[steps[:, 6] == pCav, 0]
print(f">> water gap at 0.2 ms: {int(cav.sum())} cells at the cavitation pressure {pCav:g} Pa"
      f" ({int((aw[cav] > 0.5).sum())} mostly water, {int((ap[cav] > 0.5).sum())} mostly products);"
      f" first cut-off in the step to {first[0] if len(first) else float('nan'):.4g} s;"
      f" {len(first)} of {len(steps)} steps end with cells at it")
ge, gw = get(f, "energy gained by gas + solid"), get(w, "energy gained by gas + solid")
print(f">> gas + solid energy change / initial gas energy: air gap {ge:.3g}, water gap {gw:.3g}"
      " (tolerance 1e-2)")
checks = [
    ("both at 0.2 ms", abs(get(f, "end time") - 2e-4) < 1e-12 and abs(get(w, "end time") - 2e-4) < 1e-12),
    ("water gap: three materials", get(w, "gap material") == 1 and get(f, "gap material") == 0),
    (f"water transmits more: peak hole-wall pressure water/air {pw / pa:.3g} > 1", pw > pa),
    (f"energy budgets within 1e-2 ({ge:.3g}, {gw:.3g})", abs(ge) <= 1e-2 and abs(gw) <= 1e-2),
    ("water gap: no pressure below the cavitation pressure", pEnd.min() >= pCav),
]
for name, ok in checks:
    print(f">> {name}: {'yes' if ok else 'no  <-- FAIL'}")
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
