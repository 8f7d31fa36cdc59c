#!/usr/bin/python3
"""delayedRound figures: the delayed round beside the same round fired at once.

Reads the two generated sub-cases delayed/ and instantaneous/ (the solid's VTK
series, postProcessing/holeProbes, gauges and budget.dat, the lightingTime and
burnFraction fields) and writes delayedRound.png (crack patterns at the end
and the fragment curves with their Rosin-Rammler and Swebrec fits), firing.png
(gas pressure at each charge centre, initiation times marked, and the free-face
velocity in front of each hole) and summary.json.

Fragments as in benchBlast (the VTK readers and fragment table are benchBlast's
plot.py functions, loaded from it; fits from common/blastFigures.py): the rock
mass attached to the fixed sides and back is no fragment; size sqrt(4A/pi) of
the initial area; fits over the fragments of at least two element sizes.

Per hole (charges in the order of system/setChargeDict, holes of
system/femdemMeshDict in the same order):
- firing time: the first probe time at which the pressure at the charge
  centre exceeds FIRE_PRESSURE; checked against initiationTime (it must lie
  in [t0, t0 + burn time + 2 steps]);
- inertness: the largest burnFraction in the charge's cells (lightingTime =
  t0) at the written times before t0 (checked 0); max |p/p0 - 1| at the
  charge centre over the probe times before t0 and before the coupling first
  spreads energy over the gas (checked <= 1e-6), and over all times before t0
  (checked <= 1: not fired, no products arrived; the stress waves of the
  holes fired before compress it by a few per cent, and the spread, which
  goes mostly into the unreacted charges, changes it by 5e-4, README);
- the programmed burn's limit: products from other holes in this hole's air
  gap before t0 (the rise of alpha.products at the gap probe from its start
  value: alphaMin 1e-6 in the air, more where a coarse mesh puts part of the
  charge in the probe's cell), checked below ALPHA_ARRIVED;
- burden motion: the face speed in front of the previous hole when this hole
  fires (gauges on the face).
"""
import ast
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection, LineCollection
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
tutorials = os.environ.get("JWLIBFOAM_TUTORIALS", os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(tutorials, "jwlIbFoam", "common"))
from blastPost import (read_field, write_summary, figure, budget_table,  # noqa: E402
                       solid_energy, gas_energy, log_table, joined_rows)
import blastFigures as bf  # noqa: E402
from blastVtk import read_vtu, read_vtp_lines  # noqa: E402

quick = os.path.exists(os.path.join(here, ".quick"))
ROUNDS = ("delayed", "instantaneous")
field = os.path.exists(os.path.join(here, ".field"))
PREFIX = "field_" if field else ""   # the pictures of Allrun -field
P0 = 101325.0
FIRE_PRESSURE = 1e7             # Pa: a charge has fired (its products: GPa)
INERT_TOL = 1e-6                # relative pressure change before t0
UNFIRED_TOL = 1.0               # ... before t0, with the stress waves of the
                                # holes fired before (a few %) and the energy
                                # spread (5e-4): not fired, no products (GPa)
ALPHA_ARRIVED = 1e-3            # products fraction in an air gap: arrived
ENERGY_TOL = 1e-3               # gas + solid energy, relative to the initial
TNT_E0 = bf.jwl_explosive(os.path.join(here, "constant", "thermophysicalProperties"),
                          "products")["E0"]


def bench_blast_functions(*names):
    """The named functions of benchBlast's plot.py (its fragment table),
    without running that script"""
    src = os.path.join(tutorials, "jwlIbFoam", "benchBlast", "plot.py")
    tree = ast.parse(open(src).read(), src)
    keep = [n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name in names]
    scope = {"np": np, "json": __import__("json"), "os": os}
    exec(compile(ast.Module(body=keep, type_ignores=[]), src, "exec"), scope)
    return [scope[n] for n in names]


tri_areas, fragment_table = bench_blast_functions("tri_areas", "fragment_table")


def case_geometry(case):
    """Holes (centres, radii), block, charges (centres, initiation times)"""
    meshDict = os.path.join(case, "system", "femdemMeshDict")
    holes = ["holes." + h for h in bf.foam_keywords(meshDict, "holes")]
    centres = np.array([bf.foam_entry(meshDict, h + ".centre")[:2] for h in holes])
    radius = bf.foam_entry(meshDict, holes[0] + ".radius")
    solid = "solids." + bf.foam_keywords(meshDict, "solids")[0]
    lo, hi = bf.foam_entry(meshDict, solid + ".min"), bf.foam_entry(meshDict, solid + ".max")
    text = open(os.path.join(case, "system", "setChargeDict")).read()
    t0 = np.array([float(x) for x in re.findall(r"initiationTime\s+([^;\s]+)\s*;", text)])
    return centres, radius, (lo[0], hi[0], lo[1], hi[1]), t0


def probe_table(case, field):
    """Times and values (one column per probe) of postProcessing/holeProbes"""
    data = joined_rows(case, "holeProbes", field)    # restarts joined
    return data[:, 0], data[:, 1:]


def fragments(case, block):
    """Fragment sizes, masses (areas), limited flags, fits and the last solid"""
    s = __import__("json").load(open(os.path.join(case, "VTK", "femdem.vtu.series")))
    steps = [(f["time"], os.path.join(case, "VTK", f["name"])) for f in s["files"]]
    v0 = read_vtu(steps[0][1])
    pts0, tris = v0["Points"][:, :2], v0["triangles"]
    area0 = tri_areas(pts0, tris)
    tol = 1e-6
    onFixed = ((np.abs(pts0[:, 0] - block[0]) < tol) | (np.abs(pts0[:, 0] - block[1]) < tol)
               | (np.abs(pts0[:, 1] - block[2]) < tol))
    vEnd = read_vtu(steps[-1][1])
    frag, fArea, fVel, fFixed = fragment_table(vEnd, area0, onFixed[tris].any(axis=1))
    loose = ~fFixed
    A = fArea[loose]
    size = np.sqrt(4 * A / np.pi)
    nTri = np.bincount(frag, minlength=len(fArea))
    hFrag = np.sqrt(4 / np.sqrt(3) * fArea / np.maximum(nTri, 1))[loose]
    xs, Pass, dP = bf.passing_curve(size, A)
    lim = (size < 2 * hFrag)[np.argsort(size)]
    r = {"t": steps[-1][0], "n": int(loose.sum()), "xs": xs, "P": Pass, "lim": lim,
         "x50": bf.percentile(xs, Pass, 0.5), "x80": bf.percentile(xs, Pass, 0.8),
         "limitedMass": dP[lim].sum(), "vtu": vEnd, "area0": area0,
         "speed": (np.linalg.norm(fVel[loose], axis=1) * A).sum() / A.sum(),
         "cracks": read_vtp_lines(os.path.join(case, "VTK", f"cracks_{len(steps) - 1}.vtp"))}
    r["rr"] = bf.fit_rosin_rammler(xs[~lim], Pass[~lim], dP[~lim])
    # Swebrec's xmax at most the solid's diagonal (no fragment is larger)
    r["sw"] = bf.fit_swebrec(xs[~lim], Pass[~lim], dP[~lim],
                             xmaxBound=np.hypot(*np.ptp(pts0[:, :2], axis=0)))
    return r


def written_times(case):
    """(time, directory name) of the time directories, in time order"""
    names = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d)]
    return sorted((float(d), d) for d in names)


def firing(case, centres, t0, tSpread):
    """Per charge: firing time, inertness before t0 (and before tSpread),
    products in its gap"""
    tP, p = probe_table(case, "p")
    _, alpha = probe_table(case, "alpha.products")
    nH = len(centres)
    light = read_field(case, "0", "lightingTime")
    burnTime = read_field(case, "0", "burnTime", len(light))
    dtMax = np.diff(tP).max()
    rows = []
    for k in range(nH):
        fired = tP[np.argmax(p[:, k] > FIRE_PRESSURE)] if (p[:, k] > FIRE_PRESSURE).any() else np.nan
        before = tP < t0[k]
        change = np.abs(p[:, k] / P0 - 1)       # setCharge: charge and air at 1 atm
        unfired = change[before].max() if before.any() else 0.0
        clean = before & (tP < tSpread * (1 - 1e-9))  # probe times: 12 digits
        inert = change[clean].max() if clean.any() else 0.0
        # (its rise from the start: a gap narrower than a cell shares the
        # probe's cell with the charge)
        gapAlpha = (alpha[before, nH + k] - alpha[0, nH + k]).max() if before.any() else 0.0
        cells = (np.abs(light - t0[k]) <= 1e-12 * max(1.0, t0[k])) & (burnTime > 0)
        Fmax, nWrites = 0.0, 0
        for t, d in written_times(case):
            if 0 < t < t0[k]:
                F = read_field(case, d, "burnFraction", len(light))
                Fmax, nWrites = max(Fmax, F[cells].max()), nWrites + 1
        rows.append({"t0": t0[k], "fired": fired, "inert": inert, "gapAlpha": gapAlpha,
                     "unfired": unfired, "nClean": int(clean.sum()),
                     "Fmax": Fmax, "nWrites": nWrites, "nCells": int(cells.sum()),
                     "lag": fired - t0[k], "lagMax": burnTime[cells].max() + 2 * dtMax})
    return tP, p, rows


def fluid_box(case):
    """(x0, x1, y0, y1) of the fluid mesh (its points)"""
    text = open(os.path.join(case, "constant", "polyMesh", "points")).read()
    xy = np.array(re.findall(r"\(([-+0-9.eE]+) ([-+0-9.eE]+) [-+0-9.eE]+\)", text), float)
    return xy[:, 0].min(), xy[:, 0].max(), xy[:, 1].min(), xy[:, 1].max()


def products_margin(case, centres, rHole, t0):
    """Per hole: the closest approach of products (alpha.products > 1e-3 in
    gas cells outside this hole) to this hole's wall at the written times
    before its t0 (inf: none written); the uniform blockMesh grid"""
    x0, x1, y0, y1 = fluid_box(case)
    nx = int(bf.foam_entry(os.path.join(case, "system", "blockMeshDict"), "nx"))
    ny = int(bf.foam_entry(os.path.join(case, "system", "blockMeshDict"), "ny"))
    X, Y = np.meshgrid(x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx,
                       y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny)
    XY = np.stack([X.ravel(), Y.ravel()], 1)
    out = []
    for k, c in enumerate(centres):
        r = np.linalg.norm(XY - c, axis=1)
        gap = np.inf
        for t, d in written_times(case):
            if 0 < t < t0[k]:
                a = read_field(case, d, "alpha.products", nx * ny)
                phi = read_field(case, d, "fluidFraction", nx * ny)
                hit = (a > 1e-3) & (phi > 0) & (r > rHole)
                if hit.any():
                    gap = min(gap, r[hit].min() - rHole)
        out.append(gap)
    return out


def face_motion(case, t):
    """Face gauges (the first nH points): speed |v| and displacement at time t"""
    g = bf.read_probes(os.path.join(case, "postProcessing", "gauges"))
    tg = g["Time"]
    out = []
    i = 0
    while f"probe{i}_Ux" in g:
        sp = np.hypot(g[f"probe{i}_Ux"], g[f"probe{i}_Uy"])
        disp = np.concatenate([[0], np.cumsum(0.5 * (g[f"probe{i}_Uy"][1:] + g[f"probe{i}_Uy"][:-1])
                                              * np.diff(tg))])
        out.append((np.interp(t, tg, sp), np.interp(t, tg, disp)))
        i += 1
    return g, out


def energy(case):
    b = budget_table(case)    # every start time's budget.dat, restarts joined
    Etot = gas_energy(b) + solid_energy(b)
    return (Etot[-1] - Etot[0]) / Etot[0], b


# ------------------------------------------------------------------- main
res = {}
for rnd in ROUNDS:
    case = os.path.join(here, rnd)
    centres, rHole, block, t0 = case_geometry(case)
    dE, b = energy(case)
    spread = b["gasSpreadEnergy"]
    # The first step whose spread changes an unreacted charge's pressure by
    # more than a tenth of the tolerance (round-off spreads of 1e-22 J too)
    big = np.abs(spread) / b["gasEnergy"][0] * TNT_E0 / P0 > 0.1 * INERT_TOL
    tSpread = b["time"][np.argmax(big)] if big.any() else np.inf
    tP, p, rows = firing(case, centres, t0, tSpread)
    g, face = face_motion(case, t0)
    for row, gap in zip(rows, products_margin(case, centres, rHole, t0)):
        row["productsGap"] = gap
        # The spread energy's share of an unreacted charge (internal energy
        # E0 per volume, Grueneisen 1 near rest): p change it makes
        s = np.abs(spread[b["time"] < row["t0"]]).max() if (b["time"] < row["t0"]).any() else 0
        row["spreadEstimate"] = s / b["gasEnergy"][0] * TNT_E0 / P0
    tab = log_table(os.path.join(case, "log.jwlIbFoam"))
    res[rnd] = {"frag": fragments(case, block), "tP": tP, "p": p, "rows": rows,
                "gauges": g, "face": face, "dE": dE, "budget": b, "t0": t0, "tab": tab}
nH = len(centres)

# ---------------------------------------------------------------- figures
fig, axs = plt.subplots(1, 3, figsize=(16, 4.8))
for ax, rnd in zip(axs[:2], ROUNDS):
    r = res[rnd]["frag"]
    P = r["vtu"]["Points"][:, :2]
    f = np.rint(r["vtu"]["fragment"]).astype(int)
    fa = np.bincount(f, r["area0"])
    colours = plt.cm.tab20(np.random.default_rng(1).integers(0, 20, f.max() + 1))
    colours[np.argmax(fa)] = (0.75, 0.75, 0.75, 1)
    ax.add_collection(PolyCollection(P[r["vtu"]["triangles"]], facecolors=colours[f],
                                     edgecolors="none"))
    if len(r["cracks"]):
        ax.add_collection(LineCollection(r["cracks"], colors="k", linewidths=0.4))
    ax.plot(centres[:, 0], centres[:, 1], "r+")
    times = ", ".join(f"{t * 1e6:.0f}" for t in res[rnd]["t0"])
    ax.set_xlim(block[0], block[1]); ax.set_ylim(block[2], 0.08); ax.set_aspect("equal")
    ax.set_title(f"{rnd} (t0 = {times} us): t = {r['t'] * 1e6:.0f} us, {r['n']} fragments,"
                 f" {len(r['cracks'])} broken joints", fontsize=8)
ax = axs[2]
for rnd, c in zip(ROUNDS, ("b", "r")):
    r = res[rnd]["frag"]
    xg = np.geomspace(r["xs"].min(), r["xs"].max() * 1.5, 200)
    ax.semilogx(r["xs"] * 1e3, r["P"] * 100, c + ".", ms=2)
    ax.semilogx(xg * 1e3, 100 * bf.swebrec(xg, r["sw"]["x50"], r["sw"]["xmax"], r["sw"]["b"]),
                c + "-", label=f"{rnd}: x50 {r['x50'] * 1e3:.1f} mm (Swebrec "
                f"{r['sw']['x50'] * 1e3:.1f}, Rosin-Rammler {r['rr']['x50'] * 1e3:.1f})")
    ax.semilogx(xg * 1e3, 100 * bf.rosin_rammler(xg, r["rr"]["x50"], r["rr"]["n"]), c + ":")
ax.set_xlabel("equivalent size sqrt(4A/pi) [mm]"); ax.set_ylabel("passing by mass [%]")
ax.set_ylim(0, 100); ax.legend(fontsize=7, loc="upper left")
ax.set_title("Fragment curves (dots; Swebrec solid, Rosin-Rammler dotted)", fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, PREFIX + "delayedRound.png"), dpi=120)

fig, axs = plt.subplots(1, 2, figsize=(12, 4.4))
for rnd, ls in zip(ROUNDS, ("-", "--")):
    d = res[rnd]
    for k in range(nH):
        axs[0].semilogy(d["tP"] * 1e6, d["p"][:, k], ls, color=f"C{k}", lw=0.9,
                        label=f"{rnd} hole {k + 1}: fired {d['rows'][k]['fired'] * 1e6:.2f} us")
        tg = d["gauges"]["Time"]
        axs[1].plot(tg * 1e6, d["gauges"][f"probe{k}_Uy"], ls, color=f"C{k}", lw=0.9,
                    label=f"{rnd}: face in front of hole {k + 1}")
for t in res["delayed"]["t0"]:
    for ax in axs:
        ax.axvline(t * 1e6, color="0.5", lw=0.6, ls=":")
axs[0].set_xlabel("t [us]"); axs[0].set_ylabel("p at the charge centre [Pa]")
axs[0].legend(fontsize=6); axs[0].set_title("Firing (dotted: delayed initiation times)", fontsize=9)
axs[1].set_xlabel("t [us]"); axs[1].set_ylabel("face velocity v_y [m/s]")
axs[1].legend(fontsize=6); axs[1].set_title("Burden motion: free face in front of each hole", fontsize=9)
fig.tight_layout()
fig.savefig(os.path.join(here, PREFIX + "firing.png"), dpi=120)

# ---------------------------------------------------------------- summary
figs = []
for rnd in ROUNDS:
    d, r = res[rnd], res[rnd]["frag"]
    tab = d["tab"]
    figs += [
        figure(f"{rnd}: end time [s]", r["t"]),
        figure(f"{rnd}: min gas density over all steps [kg/m3] (> 0)", tab[:, 5].min(), 0, 0,
               error=max(0, -tab[:, 5].min()), passed=bool(tab[:, 5].min() > 0)),
        figure(f"{rnd}: gas + solid energy change / initial (cutCell)", d["dE"], 0, ENERGY_TOL,
               error=abs(d["dE"])),
        figure(f"{rnd}: broken joints", d["budget"]["brokenJoints"][-1]),
        figure(f"{rnd}: fragments (loose pieces, >= 1)", r["n"], 1, 0,
               error=max(0, 1 - r["n"]), passed=bool(r["n"] >= 1)),
        figure(f"{rnd}: mass-weighted mean fragment velocity [m/s]", r["speed"]),
        figure(f"{rnd}: x50 measured [m]", r["x50"]),
        figure(f"{rnd}: x80 measured [m]", r["x80"]),
        figure(f"{rnd}: resolution-limited mass fraction", r["limitedMass"]),
        figure(f"{rnd}: Rosin-Rammler x50 [m] (not checked; n {r['rr']['n']:.2f}, rms {r['rr']['rms']:.3f})",
               r["rr"]["x50"], r["x50"], relative=True),
        figure(f"{rnd}: Swebrec x50 [m] (not checked; b {r['sw']['b']:.2f}, rms {r['sw']['rms']:.3f})",
               r["sw"]["x50"], r["x50"], relative=True),
    ]
    prev = None
    for k, row in enumerate(d["rows"]):
        h = f"{rnd}: hole {k + 1} (t0 {row['t0']:g} s)"
        figs += [
            figure(f"{h} fired at [s] (p > {FIRE_PRESSURE:g} Pa at the centre; "
                   f"after t0 by at most the burn time + 2 steps, {row['lagMax']:.3g} s)",
                   row["fired"], row["t0"], row["lagMax"], error=row["lag"],
                   passed=bool(0 <= row["lag"] <= row["lagMax"])),
        ]
        if row["t0"] > 0:
            figs += [
                figure(f"{h} inert before t0 and the first energy spread: max |p/p0 - 1|"
                       f" at the centre over {row['nClean']} steps", row["inert"], 0, INERT_TOL,
                       error=row["inert"]),
                figure(f"{h} unfired before t0: max |p/p0 - 1| at the centre (stress waves;"
                       f" the energy spread's estimate {row['spreadEstimate']:.2g})", row["unfired"],
                       0, UNFIRED_TOL, error=row["unfired"]),
                figure(f"{h} max burnFraction in its {row['nCells']} lit cells at the "
                       f"{row['nWrites']} writes before t0", row["Fmax"], 0, 0,
                       error=row["Fmax"]),
                figure(f"{h} products fraction rise in its air gap before t0 (air: 1e-6)",
                       row["gapAlpha"], 0, ALPHA_ARRIVED, error=row["gapAlpha"]),
                figure(f"{h} closest products (alpha > 1e-3) to its wall at the writes "
                       f"before t0 [m] (> 0; 1e9: none outside the holes)",
                       min(row["productsGap"], 1e9), 0, 0, error=0.0,
                       passed=bool(row["productsGap"] > 0)),
            ]
        if prev is not None:
            figs += [
                figure(f"{h} fired after hole {k} (delay order) [s]", row["fired"] - prev, 0, 0,
                       error=max(0.0, prev - row["fired"]), passed=bool(row["fired"] >= prev)),
            ]
            if row["t0"] > 0:
                sp, disp = d["face"][k - 1][0][k], d["face"][k - 1][1][k]
                figs += [figure(f"{h} face speed in front of hole {k} when it fires [m/s]", sp),
                         figure(f"{h} face displacement in front of hole {k} when it fires [m]",
                                disp)]
        prev = row["fired"]
x50d, x50i = res["delayed"]["frag"]["x50"], res["instantaneous"]["frag"]["x50"]
figs.append(figure("x50 delayed / x50 instantaneous", x50d / x50i))
write_summary(os.path.join(here, "summary.json"), "jwlIbFoam/delayedRound", figs)
