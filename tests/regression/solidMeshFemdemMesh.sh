#!/bin/bash
# femdemMesh (CGAL constrained Delaunay mesher): a rock block with a steel
# inclusion, a borehole with local refinement and a separate polygonal solid.
# Checks: femdemMeshCheck accepts the mesh; smallest angle >= minAngle; every
# triangle's longest edge <= the size function at its centroid; material areas
# and patch lengths equal those of the input polygons; the VTK output decodes
# (inline base64) to the mesh's points.
set -eu
cd "$JWLIBFOAM_TEST_DIR"
mkdir -p case/system
cat > case/system/femdemMeshDict <<'D'
FoamFile { version 2.0; format ascii; class dictionary; object femdemMeshDict; }
targetSize 0.05;
minAngle   25;
solids
{
    block { type rectangle; min (0 0); max (1 0.5); material rock;
            patches (bottom right top left); }
    inclusion { type circle; centre (0.7 0.25); radius 0.1; nSegments 24;
            material steel; }
    wedge { type polygon; points ((1.2 0) (1.6 0) (1.4 0.3)); material rock;
            patches (wedgeBase wedgeRight wedgeLeft); }
}
holes
{
    borehole { type circle; centre (0.3 0.25); radius 0.02; nSegments 32; }
}
refinement
{
    aroundBorehole { type circle; centre (0.3 0.25); radius 0.02;
                     size 0.004; distance 0.01; grading 0.3; }
    crackPath { type polyline; points ((0.3 0.25) (0.3 0.5)); size 0.01; grading 0.5; }
}
D
start=$(date +%s.%N)
femdemMesh -case case -vtk > log.femdemMesh 2>&1 || { tail -20 log.femdemMesh; exit 1; }
echo ">> femdemMesh: $(grep -m1 'Solid mesh:' log.femdemMesh | sed 's/Solid mesh: //'), $(grep -m1 'Meshing time' log.femdemMesh)"
femdemMeshCheck -case case > log.femdemMeshCheck 2>&1 || { tail -20 log.femdemMeshCheck; exit 1; }
echo ">> femdemMeshCheck: $(grep -m1 'Mesh OK' log.femdemMeshCheck)"
/usr/bin/python3 - case <<'PY'
import base64, math, re, struct, sys
case = sys.argv[1]
text = open(f"{case}/constant/solidMesh").read()
def block(name):
    m = re.search(name + r"\s+(\d+)\s*\(", text)
    n, i, depth = int(m.group(1)), m.end(), 1
    j = i
    while depth:
        depth += {"(": 1, ")": -1}.get(text[j], 0); j += 1
    return n, text[i:j - 1]
n, s = block("points")
pts = [tuple(map(float, p.split())) for p in re.findall(r"\(([^()]*)\)", s)]
n, s = block("triangles")
tris = [tuple(map(int, t.split())) for t in re.findall(r"\(([^()]*)\)", s)]
n, s = block("triangleMaterials")
mats = list(map(int, s.split()))
materials = re.search(r"materials\s+\d*\s*\(([^)]*)\)", text).group(1).split()
ok = True

def size(x, y):   # the size function of the dictionary
    h = 0.05
    d = abs(math.hypot(x - 0.3, y - 0.25) - 0.02)
    h = min(h, 0.004 + 0.3 * max(d - 0.01, 0))
    t = min(max((y - 0.25) / 0.25, 0), 1)
    d = math.hypot(x - 0.3, y - (0.25 + 0.25 * t))
    return min(h, 0.01 + 0.5 * d)

area = {}
worst, smallest = 0, 180
for (a, b, c), m in zip(tris, mats):
    P = [pts[a], pts[b], pts[c]]
    ar = 0.5 * ((P[1][0]-P[0][0])*(P[2][1]-P[0][1]) - (P[1][1]-P[0][1])*(P[2][0]-P[0][0]))
    ok &= ar > 0
    area[materials[m]] = area.get(materials[m], 0) + ar
    L = [math.dist(P[k], P[(k+1) % 3]) for k in range(3)]
    cx, cy = sum(p[0] for p in P) / 3, sum(p[1] for p in P) / 3
    worst = max(worst, max(L) / size(cx, cy))
    for k in range(3):
        u = [P[(k+1) % 3][i] - P[k][i] for i in range(2)]
        v = [P[(k+2) % 3][i] - P[k][i] for i in range(2)]
        smallest = min(smallest, math.degrees(math.atan2(abs(u[0]*v[1]-u[1]*v[0]), u[0]*v[0]+u[1]*v[1])))
poly = lambda n, r: 0.5 * n * r * r * math.sin(2 * math.pi / n)
exact = {"steel": poly(24, 0.1), "rock": 0.5 - poly(24, 0.1) - poly(32, 0.02) + 0.5 * 0.4 * 0.3}
for m in exact:
    err = abs(area[m] - exact[m])
    print(f">> area {m}: {area[m]:.12f} (exact {exact[m]:.12f}, error {err:.1e}, tolerance 1e-12)")
    ok &= err < 1e-12
print(f">> smallest angle {smallest:.2f} deg (minAngle 25); longest edge / local size: max {worst:.4f} (tolerance 1)")
ok &= smallest >= 25 - 1e-9 and worst <= 1 + 1e-9
near = [max(math.dist(pts[t[k]], pts[t[(k+1)%3]]) for k in range(3)) for t in tris
        if math.hypot(sum(pts[v][0] for v in t)/3 - 0.3, sum(pts[v][1] for v in t)/3 - 0.25) < 0.03]
print(f">> {len(tris)} triangles, {len(near)} within 0.01 of the borehole, longest edge there {max(near):.4f} (size 0.004 + grading)")

# Patch lengths
def patch_length(name):
    m = re.search(name + r"\s*\{\s*edges\s+\d+\s*\(", text)
    i, depth, j = m.end(), 1, m.end()
    while depth:
        depth += {"(": 1, ")": -1}.get(text[j], 0); j += 1
    es = [tuple(map(int, e.split())) for e in re.findall(r"\(([^()]*)\)", text[i:j-1])]
    return sum(math.dist(pts[a], pts[b]) for a, b in es)
lengths = {p: patch_length(p) for p in ("bottom", "right", "top", "left", "borehole", "wedgeBase", "wedgeLeft")}
expected = {"bottom": 1, "right": 0.5, "top": 1, "left": 0.5, "borehole": 32 * 2 * 0.02 * math.sin(math.pi / 32),
            "wedgeBase": 0.4, "wedgeLeft": math.hypot(0.2, 0.3)}
for p in lengths:
    ok &= abs(lengths[p] - expected[p]) < 1e-12
print(">> patch lengths equal the input sides (1e-12):", ", ".join(f"{p} {lengths[p]:.6g}" for p in lengths))

# VTK: decode the inline base64 Points array and compare with the mesh
vtu = open(f"{case}/VTK/solidMesh_0.vtu").read()
m = re.search(r"Name='Points'[^>]*format='binary'>\s*([A-Za-z0-9+/=\s]+?)\s*<", vtu)
raw = base64.b64decode("".join(m.group(1).split()))
nbytes = struct.unpack("<Q", raw[:8])[0]
xyz = struct.unpack(f"<{nbytes // 4}f", raw[8:8 + nbytes])
vtk_ok = nbytes == 12 * len(pts) and all(abs(xyz[3*i] - p[0]) < 1e-6 and abs(xyz[3*i+1] - p[1]) < 1e-6 for i, p in enumerate(pts))
print(f">> VTK solidMesh_0.vtu: {len(pts)} points decoded from base64, match: {vtk_ok}")
ok &= vtk_ok and "NumberOfCells='%d'" % len(tris) in vtu

# Figure: the mesh coloured by material
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(12, 4))
ax.tripcolor([p[0] for p in pts], [p[1] for p in pts], tris, facecolors=mats,
             edgecolors="k", linewidth=0.2, cmap="Pastel1")
ax.set_aspect("equal")
ax.set_title(f"femdemMesh: {len(tris)} triangles, smallest angle {smallest:.1f} deg")
fig.tight_layout()
fig.savefig("femdemMesh.png", dpi=110)
print(">> figure: femdemMesh.png")
sys.exit(0 if ok else 1)
PY
