#!/bin/bash
# Regression: tutorials/jwlIbFoam/delayedRound -quick (three holes, programmed
# burn; the delayed round with 20 us delays against the same round fired at
# once, 50 us, solid 20 mm / 10 mm at the holes): every charge fires at its
# initiation time (in the delay order), stays inert before it (pressure at its
# centre within 1e-6, burnFraction 0 in its cells at the writes before),
# no products of another hole in its air gap before it fires, gas + solid
# energy (cut cells) within 1e-3; figures from summary.json
set -e
cd "$JWLIBFOAM_TEST_DIR" && rm -rf delayedRound
cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/delayedRound" . && cd delayedRound
start=$(date +%s)
./Allrun -quick             # (cleans the copy first)
echo ">> delayedRound -quick: $(( $(date +%s) - start )) s wall ($(cat log.runTime))"
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
/usr/bin/python3 - <<'PY'
import json, sys
f = {x["name"]: x for x in json.load(open("summary.json"))["figures"]}
def hole(rnd, k, what):
    keys = [n for n in f if n.startswith(f"{rnd}: hole {k} ") and what in n]
    if len(keys) != 1:
        sys.exit(f">> summary.json: no unique '{rnd}: hole {k} ... {what}'  <-- FAIL")
    return f[keys[0]]
checks = []
fired = [hole("delayed", k, "fired at")["value"] for k in (1, 2, 3)]
t0 = [hole("delayed", k, "fired at")["reference"] for k in (1, 2, 3)]
checks.append(("delayed: three distinct initiation times", t0[0] < t0[1] < t0[2]))
checks.append(("delayed: fired in the delay order", fired[0] < fired[1] < fired[2]))
inst = [hole("instantaneous", k, "fired at")["value"] for k in (1, 2, 3)]
checks.append(("instantaneous: all fired within 3 us of 0", max(inst) < 3e-6))
checks.append(("delayed holes 2, 3: inertness checked at >= 1 write",
               all("writes before" in n and "at the 0 writes" not in n
                   for n in (hole("delayed", k, "burnFraction")["name"] for k in (2, 3)))))
for name, ok in checks:
    print(f">> {name}: {'yes' if ok else 'no  <-- FAIL'}")
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
