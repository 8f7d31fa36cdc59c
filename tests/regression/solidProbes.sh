#!/bin/bash
# The solidProbes function object (src/femdem/solidProbes) in femdemFoam:
# (1) a free block in rigid translation (initialVelocity): every probe reads
#     the exact velocity at every step; header and columns by name;
# (2) a pulled bar run in one go and restarted at 2e-5 s: the restart writes
#     postProcessing/gauges/2e-05/velocity.dat beside the untouched first
#     file, and the joined series equals the uninterrupted run's bit for bit;
#     a rerun from the same start time writes velocity_1.dat and leaves
#     velocity.dat unchanged;
# (3) a probe outside the solid: FatalIOError naming the entry 'points'.
set -eu
cd "$JWLIBFOAM_TEST_DIR"
rm -rf base translation full split bad
mkdir -p base/system base/constant
header() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n' "$1"; }
{ header controlDict; cat <<'D'; } > base/system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 4e-5; deltaT 2e-6; writeControl runTime; writeInterval 2e-5;
functions { gauges { type solidProbes; points ((0.01 0.01) (0.03 0.0051) (0.055 0.017)); } }
D
{ header femdemMeshDict; cat <<'D'; } > base/system/femdemMeshDict
targetSize 0.005; minAngle 20;
solids { block { type rectangle; min (0 0); max (0.06 0.02); material granite;
                 patches (south east north west); } }
D
# Both ends pulled apart (east also sheared): breaks, so the velocities vary
{ header femdemProperties; cat <<'D'; } > base/constant/femdemProperties
cohesiveLaw bilinear; contactLaw potential;
materials { granite { E 50e9; nu 0.2; rho 2650; tensileStrength 5e6; cohesion 20e6;
                      frictionAngle 40; GI 30; GII 300; } }
boundaryConditions { west { type velocity; value (-2 0); }
                     east { type velocity; value (2 1); } }
output { vtk false; }
D
(cd base && femdemMesh > log.femdemMesh 2>&1)

# (1) rigid translation
cp -r base translation
sed -i '/^boundaryConditions/,+1d' translation/constant/femdemProperties
echo 'initialVelocity (2.5 -1.25);' >> translation/constant/femdemProperties
(cd translation && femdemFoam > log.femdemFoam 2>&1)
/usr/bin/python3 - "$JWLIBFOAM_TUTORIALS/jwlIbFoam/common" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
import blastFigures as bf
p = bf.read_probes("translation/postProcessing/gauges")
err = max(np.abs(p[f"probe{i}_Ux"] - 2.5).max() + np.abs(p[f"probe{i}_Uy"] + 1.25).max()
          for i in range(3))
n = len(p["Time"])
print(f">> rigid translation (2.5, -1.25) m/s: {n} rows (t = {p['Time'][0]:g} to "
      f"{p['Time'][-1]:g} s), max probe error {err:.3g} m/s (tolerance 1e-6: the stiff"
      " joints answer the round-off of the positions; a wrong weight or column is O(1))")
sys.exit(0 if err < 1e-6 and n >= 20 and p["Time"][0] == 0 else 1)
PY

# (2) restart and rerun
cp -r base full && (cd full && femdemFoam > log.femdemFoam 2>&1)
cp -r base split
(cd split && sed -i 's/endTime 4e-5;/endTime 2e-5;/' system/controlDict \
    && femdemFoam > log.femdemFoam1 2>&1 && md5sum postProcessing/gauges/0/velocity.dat > first.md5 \
    && sed -i 's/endTime 2e-5;/endTime 4e-5;/' system/controlDict \
    && femdemFoam > log.femdemFoam2 2>&1)
(cd split && md5sum -c --quiet first.md5)
ls split/postProcessing/gauges/2e-05/velocity.dat > /dev/null
/usr/bin/python3 - "$JWLIBFOAM_TUTORIALS/jwlIbFoam/common" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
import blastFigures as bf
a = bf.read_probes("full/postProcessing/gauges")
b = bf.read_probes("split/postProcessing/gauges")
same = a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)
vmax = max(np.abs(a[k]).max() for k in a if k != "Time")
print(f">> restart at 2e-5 s: joined probe series identical to the uninterrupted run: "
      f"{'yes' if same else 'no  <-- FAIL'} ({len(a['Time'])} rows, max |U| {vmax:.3g} m/s)")
sys.exit(0 if same and vmax > 0.1 else 1)
PY
(cd split && rm -rf 4e-05 && md5sum postProcessing/gauges/2e-05/velocity.dat > second.md5 \
    && femdemFoam > log.femdemFoam3 2>&1 && md5sum -c --quiet second.md5 \
    && test -s postProcessing/gauges/2e-05/velocity_1.dat)
echo ">> rerun from 2e-5 s: velocity.dat unchanged, velocity_1.dat written"

# (3) bad input
cp -r base bad
sed -i 's/(0.055 0.017)/(0.07 0.01)/' bad/system/controlDict
if (cd bad && femdemFoam > log.femdemFoam 2>&1); then echo ">> probe outside the solid accepted  <-- FAIL"; exit 1; fi
grep -q "entry 'points': point 2" bad/log.femdemFoam && grep -q controlDict bad/log.femdemFoam \
    || { echo ">> probe outside: message lacks the entry or the file  <-- FAIL"; tail -15 bad/log.femdemFoam; exit 1; }
echo ">> probe outside the solid: FatalIOError names controlDict and entry 'points'"
