#!/bin/bash
# Regression: tutorials/jwlIbFoam/blastingCylinder at full resolution (0.2 mm
# cells, 240 x 240, 4610 triangles, 24 us; TNT; the tutorial's own ./Allrun,
# about 5 min on one core): the run reaches its end time (a fragmenting wall
# whose triangles nearly all become fragments: cut cells down to slivers,
# crushed pockets, cells opening and closing every step), the terminal wall
# velocity is within 5 % of Gurney and gas + solid energy within the
# tutorial's tolerance until gas leaves the domain; figures from its
# summary.json and the solver's last lines (steps in parts, pockets vented,
# cells mixed)
set -e -o pipefail
cd "$JWLIBFOAM_TEST_DIR"
rm -rf full && cp -r "$JWLIBFOAM_TUTORIALS/jwlIbFoam/blastingCylinder" full
cd full
./Allclean > /dev/null 2>&1 || true
./Allrun > log.Allrun 2>&1 || { tail -20 log.Allrun; echo ">> ./Allrun failed  <-- FAIL"; exit 1; }
end=$(foamDictionary -entry endTime -value system/controlDict)
last=$(grep '^Time = ' log.jwlIbFoam | tail -1 | awk '{print $3}')
echo ">> last step $last s of endTime $end s"
grep -q '^End' log.jwlIbFoam || { echo ">> the solver did not end  <-- FAIL"; exit 1; }
python3 - "$last" "$end" <<'PYEOF' || exit 1
import sys
last, end = float(sys.argv[1]), float(sys.argv[2])
if last < end*(1 - 1e-6):
    print(f">> the run stopped at {last} s before endTime {end} s  <-- FAIL")
    sys.exit(1)
PYEOF
grep -E '^Coupled steps taken in parts' log.jwlIbFoam | sed 's/^/>> /'
"$JWLIBFOAM_PROJECT/tests/bin/checkSummary" summary.json
