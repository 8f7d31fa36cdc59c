#!/bin/bash
# gmshToFemdem: the same geometry (solidMeshData/blockWithBorehole.geo, two
# materials, a borehole, named boundaries) meshed headless by gmsh in formats
# 2.2 and 4.1 must give identical solid meshes, which femdemMeshCheck accepts;
# the materials' areas are those of the geometry.
set -eu
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
geo="$here/solidMeshData/blockWithBorehole.geo"
cd "$JWLIBFOAM_TEST_DIR"
for fmt in msh22 msh41; do
    mkdir -p "$fmt/constant"
    gmsh -2 -format $fmt -o "$fmt/block.msh" "$geo" > "log.gmsh.$fmt" 2>&1
    gmshToFemdem -case "$fmt" "$fmt/block.msh" > "log.gmshToFemdem.$fmt" 2>&1 \
        || { tail -20 "log.gmshToFemdem.$fmt"; exit 1; }
done
if cmp -s msh22/constant/solidMesh msh41/constant/solidMesh; then
    echo ">> constant/solidMesh from msh 2.2 and 4.1: identical"
else
    echo ">> constant/solidMesh from msh 2.2 and 4.1: DIFFERENT"; exit 1
fi
femdemMeshCheck -case msh22 -E 50e9 -nu 0.25 -rho 2700 > log.femdemMeshCheck 2>&1 \
    || { tail -20 log.femdemMeshCheck; exit 1; }
grep -E "Solid mesh:|material (granite|steel):|patch borehole|joints:|stable time step" log.femdemMeshCheck \
    | sed 's/^ */>> /'
/usr/bin/python3 - log.femdemMeshCheck log.gmshToFemdem.msh22 <<'PY'
import math, re, sys
check = open(sys.argv[1]).read()
area = {m: float(a) for m, a in re.findall(r"material (\w+): \d+ triangles, area (\S+)", check)}
# granite: block minus borehole (polygon of the meshed circle) minus inclusion
patches = dict(re.findall(r"patch (\w+): (\d+) edges", check))
n = int(patches["borehole"])                 # chords of the meshed borehole
steel = 0.2 * 0.2
hole = 0.5 * n * 0.03**2 * math.sin(2 * math.pi / n)
ok = abs(area["steel"] - steel) < 1e-9
ok &= abs(area["granite"] - (0.5 - steel - hole)) < 1e-6   # printed with 6 digits
print(f">> steel area {area['steel']:.9g} (exact {steel}), granite {area['granite']:.9g}"
      f" (exact 0.5 - 0.04 - {n}-gon of radius 0.03 = {0.5 - steel - hole:.9g})")
ok &= all(int(patches[p]) > 0 for p in ("bottom", "right", "top", "left", "borehole"))
ok &= patches.get("interface") == "0"    # the inclusion's outline is inside
print(">> patches:", patches)
sys.exit(0 if ok else 1)
PY
