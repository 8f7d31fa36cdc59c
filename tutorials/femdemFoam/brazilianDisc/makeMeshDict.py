#!/usr/bin/python3
"""Writes system/femdemMeshDict for a disc of diameter D made of nSides
polygon sides (vertices every 360/nSides degrees, two of them at the top and
bottom of the disc). The sides within +-loadAngle/2 of the top and bottom
are the loading patches 'top' and 'bottom', the others 'rim'.
With 'split' the disc is meshed as two half-discs (left, right) sharing the
loaded diameter, so that the mesh has a straight line of edges (joints)
along it: the crack can run straight, as in the laboratory, instead of
zig-zagging along inclined joints.
Usage: makeMeshDict.py D targetSize nSides loadAngleDeg [split]"""
import math, sys

D, size, n, angle = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
split = len(sys.argv) > 5 and sys.argv[5] == "split"
assert n % 4 == 0, "nSides must be a multiple of 4"
R = D / 2


def vertex(i):
    a = 2 * math.pi * i / n
    return (R * math.cos(a), R * math.sin(a))


def side_patch(i):                      # side from vertex i to i+1
    deg = (360.0 * (i + 0.5) / n) % 360
    if abs(deg - 90) <= angle / 2:
        return "top"
    if abs(deg - 270) <= angle / 2:
        return "bottom"
    return "rim"


def polygon(name, first, last, closing):
    """Vertices first..last (CCW), closed by a side named closing"""
    idx = [i % n for i in range(first, last + 1)]
    pts = [vertex(i) for i in idx]
    patches = [side_patch(i) for i in range(first, last)] + [closing]
    return (f"    {name}\n    {{\n        type polygon;\n        material sandstone;\n"
            "        points (" + " ".join(f"({x:.15g} {y:.15g})" for x, y in pts) + ");\n"
            "        patches (" + " ".join(patches) + ");\n    }\n")


with open("system/femdemMeshDict", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object femdemMeshDict; }\n")
    f.write(f"targetSize {size};\nminAngle 20;\nsolids\n{{\n")
    if split:
        q = n // 4
        f.write(polygon("left", q, 3 * q, "diameter"))
        f.write(polygon("right", 3 * q, 5 * q, "diameter"))
    else:
        idx = list(range(n))
        pts = [vertex(i) for i in idx]
        f.write("    disc\n    {\n        type polygon;\n        material sandstone;\n"
                "        points (" + " ".join(f"({x:.15g} {y:.15g})" for x, y in pts) + ");\n"
                "        patches (" + " ".join(side_patch(i) for i in idx) + ");\n    }\n")
    f.write("}\n")
print(f"disc D = {D}, {n} sides, load arcs {angle} deg, split = {split}")
