#!/usr/bin/python3
"""jointedBench figures.

    plot.py [-noAnimation]   benchBlast's plot.py run on this case (the same
                             figures and summary.json; geometry from
                             system/femdemMeshDict), then the joint-set
                             figures added to summary.json
    plot.py -compare         the jointed round beside the reference run
                             noJoints/ (fragment count, x50, broken joints):
                             summary.json and jointsVsIntact.png

Joint-set figures: the joints of constant/solidMesh's jointSets, their
share of the total joint length, and their share of the broken joint
length (postProcessing/jwlIbFoam/cracks_<last time>.dat, initial positions):
a weak set breaks more than its share (checked: broken share > length share).
"""
import json
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
tutorials = os.environ.get("JWLIBFOAM_TUTORIALS", os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(tutorials, "jwlIbFoam", "common"))
from blastPost import figure, write_summary, latest_time  # noqa: E402


def run_bench_blast_plot():
    """benchBlast's plot.py with this case as its directory."""
    src = os.path.join(tutorials, "jwlIbFoam", "benchBlast", "plot.py")
    code = compile(open(src).read(), src, "exec")
    exec(code, {"__file__": os.path.join(here, "plot.py"), "__name__": "__main__"})


def mesh_joints(path):
    """Points, all interior edges and the joint-set edges of a solidMesh."""
    text = open(path).read()

    def block(name, start=0):
        m = re.compile(r"\b" + name + r"\s+(\d+)\s*\(").search(text, start)
        i, depth, j = m.end(), 1, m.end()
        while depth:
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            j += 1
        return re.findall(r"\(([^()]*)\)", text[i:j - 1])

    pts = np.array([list(map(float, p.split())) for p in block("points")])
    tris = np.array([list(map(int, t.split())) for t in block("triangles")])
    e = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    uniq, count = np.unique(e, axis=0, return_counts=True)
    interior = uniq[count == 2]
    sets = []
    m = re.search(r"\njointSets\s*\{", text)
    if m:
        sets = [np.sort(np.array([list(map(int, x.split())) for x in block("edges", m.end())]), axis=1)]
    setEdges = np.concatenate(sets) if sets else np.zeros((0, 2), int)
    return pts, interior, setEdges


def joint_figures():
    pts, interior, setEdges = mesh_joints(os.path.join(here, "constant", "solidMesh"))
    length = lambda e: np.linalg.norm(pts[e[:, 1]] - pts[e[:, 0]], axis=1)
    keys = set()
    for a, b in setEdges:
        pa, pb = tuple(np.round(pts[a], 9)), tuple(np.round(pts[b], 9))
        keys |= {pa + pb, pb + pa}
    shareLength = length(setEdges).sum() / length(interior).sum()
    crackFile = os.path.join(here, "postProcessing", "jwlIbFoam", f"cracks_{latest_time(here)}.dat")
    cracks = np.loadtxt(crackFile, ndmin=2) if os.path.exists(crackFile) else np.zeros((0, 4))
    onSet = np.array([tuple(np.round(c, 9)) in keys for c in cracks], bool)
    lc = np.linalg.norm(cracks[:, 2:] - cracks[:, :2], axis=1)
    shareBroken = lc[onSet].sum() / max(lc.sum(), 1e-300)
    figs = [
        figure("joint-set joints (edges of constant/solidMesh jointSets)", len(setEdges)),
        figure("joint-set share of the joint length", shareLength),
        figure("joint-set share of the broken joint length", shareBroken),
    ]
    if len(setEdges):
        figs.append(figure("joint set breaks more than its share (broken share / length share > 1)",
                           shareBroken / shareLength, 1, None,
                           passed=bool(shareBroken > shareLength)))
    return figs


def compare():
    """Jointed against noJoints: fragments, x50, broken joints."""
    def values(d):
        return {f["name"]: f["value"] for f in json.load(open(os.path.join(d, "summary.json")))["figures"]}
    a, b = values(here), values(os.path.join(here, "noJoints"))
    pick = lambda v, start: next(v[k] for k in v if k.startswith(start))
    rows = [("fragments", "fragments (loose"), ("x50 [m]", "x50 measured"),
            ("x80 [m]", "x80 measured"), ("broken joints", "broken joints"),
            ("broken joint length [m]", "broken joint length"),
            ("max throw [m]", "max throw distance")]
    figs = []
    for label, start in rows:
        ja, jb = pick(a, start), pick(b, start)
        figs += [figure(f"{label}, jointed", ja), figure(f"{label}, no joints (same mesh)", jb),
                 figure(f"{label}, jointed / no joints", ja / jb if jb else float("nan"))]
    data = json.load(open(os.path.join(here, "summary.json")))
    data["figures"] = [f for f in data["figures"] if "jointed" not in f["name"]
                       and "no joints" not in f["name"]] + figs
    write_summary(os.path.join(here, "summary.json"), data["case"], data["figures"])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(11, 3.4))
    for ax, (label, start) in zip(axs, rows[:3]):
        ax.bar(["jointed", "no joints"], [pick(a, start), pick(b, start)], color=["C3", "C0"])
        ax.set_title(label, fontsize=9)
    fig.suptitle("jointedBench: the same round with and without the joint set")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "jointsVsIntact.png"), dpi=120)


if "-compare" in sys.argv:
    compare()
else:
    run_bench_blast_plot()
    path = os.path.join(here, "summary.json")
    data = json.load(open(path))
    write_summary(path, "jwlIbFoam/jointedBench", data["figures"] + joint_figures())
