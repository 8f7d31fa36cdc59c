#!/bin/bash
# Regression: tutorials/jwlIbFoam/benchBlast -quick (0.1 ms of the bench
# blast): positivity, gas mass, fragment partition, fragment count and
# fragments in flight, Rosin-Rammler and Swebrec fits against the measured
# x50/x80; figures from its summary.json, and the engineering figures
# (KCO, zones, PPV, throw, animation) present and sane
set -e
cd "$JWLIBFOAM_TEST_DIR"
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/benchBlast" .
cd benchBlast
./Allclean > /dev/null 2>&1 || true
./Allrun -quick
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
/usr/bin/python3 - <<'PY'
import json, math, os, sys
f = {x["name"]: x["value"] for x in json.load(open("summary.json"))["figures"]}
def get(start):
    keys = [k for k in f if k.startswith(start)]
    if not keys:
        sys.exit(f">> summary.json has no figure '{start}...'  <-- FAIL")
    return [f[k] for k in keys]
ppv = get("PPV at gauge")
checks = [
    ("KCO x50, n, b positive", all(v[0] > 0 for v in (get("KCO x50"), get("KCO uniformity"), get("KCO Swebrec b")))),
    ("Swebrec xmax above the Swebrec x50", get("Swebrec xmax")[0] > get("Swebrec x50")[0]),
    ("hole radius < crushed <= cracked <= crack reach",
     0.015 < get("crushed zone radius")[0] <= get("cracked zone radius")[0] <= get("crack reach")[0]),
    ("Esen estimate finite and positive", 0 < get("Esen et al. crushed zone radius")[0] < math.inf),
    (f"{len(ppv)} gauges, every PPV positive and finite", len(ppv) >= 3 and all(0 < v < 1e3 for v in ppv)),
    ("PPV damage threshold 0.62 m/s", abs(get("PPV damage threshold")[0] - 0.623) < 0.01),
    ("max throw > 0, >= mean throw; fragments thrown", get("max throw")[0] > 0
     and get("max throw")[0] >= get("mean throw")[0] and get("fragments thrown")[0] >= 1),
    ("blast.gif written", os.path.getsize("blast.gif") > 1000),
]
for name, ok in checks:
    print(f">> {name}: {'yes' if ok else 'no  <-- FAIL'}")
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
