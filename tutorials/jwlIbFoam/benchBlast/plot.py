#!/usr/bin/python3
"""Bench blast post-processing (matplotlib only, no ParaView).

Reads the solid's VTK series written by jwlIbFoam (VTK/femdem_<i>.vtu: the
continuous view, with per-triangle velocity, damage and fragment id), the
broken joints (VTK/cracks_<i>.vtp), the borehole probe
(postProcessing/boreholeProbe/<t>/p), the budget (postProcessing/jwlIbFoam/<t>/
budget.dat) and the gas fields of the last written time. Writes
crackPattern.png, gasVenting.png, boreholePressure.png, fragments.png,
crackGas.png (with the crack gas) and summary.json (blastPost.write_summary);
with the lined hole of Allrun in lined/ (its own summary.json, found by
name), the lined versus unlined figures in summary.json, linedVsUnlined.dat
(columns with a header) and linedVsUnlined.png.

Fragment sizes: area A of each fragment (sum of the initial areas of its
triangles), equivalent size x = sqrt(4 A/pi) (diameter of the circle of the
same area). The rock mass behind the blast (fragments holding a triangle on
the fixed back or sides) is not a fragment. Mass-passing curve P(x) (mid-step,
blastFigures.passing_curve) fitted by Rosin-Rammler and Swebrec by least
squares on P itself, each point weighted by its mass fraction, over the
fragments of at least two element sizes (element size h of a fragment: the
side of the equilateral triangle of its triangles' mean area); the smaller
ones are resolution-limited, kept in P (their mass is real) but not fitted.
The Kuz-Ram / KCO prediction for the same round, the crushed and cracked
zones with the Esen et al. (2003) estimate, the peak particle velocity at
the solid probes (postProcessing/gauges) with the damage threshold
f_t c_p/E, the throw (system/throwDict) and an animation (blast.gif; skipped
with -noAnimation) come from blastFigures; assumptions in README.md.
"""
import json
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection, LineCollection
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import (read_field, write_summary, figure, latest_time, log_table,
                       budget_table, joined_rows, solid_energy, gas_energy,
                       gas_mass)
import blastFigures as bf
from blastVtk import read_vtu, read_vtp_lines, read_vtp_line_fields

here = os.path.dirname(os.path.abspath(__file__))
quick = os.path.exists(os.path.join(here, ".quick"))

# Geometry, rock and charge from the case dictionaries: the first hole and
# solid of system/femdemMeshDict, the first material of
# constant/femdemProperties, the first charge radius of system/setChargeDict,
# the JWL products of constant/thermophysicalProperties (preset + overrides)
def _case(*p):
    return os.path.join(here, *p)


meshDict = _case("system", "femdemMeshDict")
_hole = "holes." + bf.foam_keywords(meshDict, "holes")[0]
HOLE = bf.foam_entry(meshDict, _hole + ".centre")[:2]
R_HOLE = bf.foam_entry(meshDict, _hole + ".radius")
_solid = "solids." + bf.foam_keywords(meshDict, "solids")[0]
_lo, _hi = bf.foam_entry(meshDict, _solid + ".min"), bf.foam_entry(meshDict, _solid + ".max")
BENCH = (_lo[0], _hi[0], _lo[1], _hi[1])            # xmin xmax ymin ymax
FLUID = (-0.3, 0.3, -0.4, 0.3)                      # system/blockMeshDict
solidDict = _case("constant", "femdemProperties")
_mat = "materials." + bf.foam_keywords(solidDict, "materials")[0]
E_ROCK, NU_ROCK, RHO_ROCK, FT_ROCK, C_ROCK, PHI_ROCK = (
    bf.foam_entry(solidDict, f"{_mat}.{k}") for k in
    ("E", "nu", "rho", "tensileStrength", "cohesion", "frictionAngle"))
R_CHARGE = float(re.search(r"radius\s+([0-9.eE+-]+)\s*;",
                           open(_case("system", "setChargeDict")).read()).group(1))
_ibp = "".join(open(f).read() for f in (_case("constant", "immersedBodyProperties"),
                                        _case("constant", "immersedBodyProperties.mode"))
               if os.path.exists(f))
# A lined hole: the gas kept out of the cracks (no crack venting on the
# mesh, no crack gas)
lined = (re.search(r"^\s*crackVenting\s+(false|off|no)\s*;", _ibp, re.M) is not None
         and re.search(r"^\s*crackGas\s*\{", _ibp, re.M) is None)
TNT = bf.jwl_explosive(_case("constant", "thermophysicalProperties"), "products")
FLIGHT_SPEED = 5.0                      # m/s: a fragment "in flight"
# Kuz-Ram round: plan view of a long hole; assumptions (README.md)
BENCH_HEIGHT = 1.0                      # m: charge length = bench height
SPACING = BENCH[1] - BENCH[0]           # m: the block width between fixed sides
BURDEN = BENCH[3] - HOLE[1]             # m: hole to the free face
ANFO_ENERGY = 3.7e6                     # J/kg: RWS = 100 (explosive/ANFO energy)
ROCK_MASS_DESCRIPTION = 50              # Cunningham RMD: massive, no joints


def series():
    s = json.load(open(os.path.join(here, "VTK", "femdem.vtu.series")))
    return [(f["time"], os.path.join(here, "VTK", f["name"])) for f in s["files"]]


# ------------------------------------------------------------- fragments
def tri_areas(pts, tris):
    a, b, c = pts[tris[:, 0]], pts[tris[:, 1]], pts[tris[:, 2]]
    return 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                        - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def fragment_table(vtu, area0, fixedTri):
    """Per fragment: area (initial), mean velocity (area-weighted), fixed?"""
    frag = np.rint(vtu["fragment"]).astype(int)
    nF = frag.max() + 1
    area = np.bincount(frag, area0, nF)
    vel = np.stack([np.bincount(frag, area0 * vtu["velocity"][:, k], nF)
                    for k in range(2)], 1) / np.maximum(area, 1e-300)[:, None]
    fixed = np.bincount(frag, fixedTri.astype(float), nF) > 0
    return frag, area, vel, fixed


# ------------------------------------------------------------------- main
steps = series()
t0, f0 = steps[0]
v0 = read_vtu(f0)
pts0 = v0["Points"][:, :2]
tris = v0["triangles"]
area0 = tri_areas(pts0, tris)
tol = 1e-6
onFixed = ((np.abs(pts0[:, 0] - BENCH[0]) < tol) | (np.abs(pts0[:, 0] - BENCH[1]) < tol)
           | (np.abs(pts0[:, 1] - BENCH[2]) < tol))
# The continuous view renumbers points as cracks open: use the initial
# centroids of the triangles (same order in every step) instead
cent0 = pts0[tris].mean(axis=1)
fixedTri = onFixed[tris].any(axis=1)

tEnd, fEnd = steps[-1]
vEnd = read_vtu(fEnd)
frag, fArea, fVel, fFixed = fragment_table(vEnd, area0, fixedTri)
loose = ~fFixed
A = fArea[loose]
speed = np.linalg.norm(fVel[loose], axis=1)
size = np.sqrt(4 * A / np.pi)
# Element size of each fragment: side of the equilateral triangle of the
# mean area of its triangles; below two element sizes a fragment's size is
# set by the mesh (resolution-limited)
nTri = np.bincount(frag, minlength=len(fArea))
hFrag = np.sqrt(4 / np.sqrt(3) * fArea / np.maximum(nTri, 1))[loose]
limited = size < 2 * hFrag
xs, Pass, dP = bf.passing_curve(size, A)
lim = limited[np.argsort(size)]
rr = bf.fit_rosin_rammler(xs[~lim], Pass[~lim], dP[~lim])
# Swebrec's xmax at most the block's diagonal (no fragment is larger)
BLOCK = np.hypot(BENCH[1] - BENCH[0], BENCH[3] - BENCH[2])
sw = bf.fit_swebrec(xs[~lim], Pass[~lim], dP[~lim], xmaxBound=BLOCK)
x50 = bf.percentile(xs, Pass, 0.5)
x80 = bf.percentile(xs, Pass, 0.8)
# The fit used before (why it was 32 % off): linear regression of
# ln(-ln(1 - P)) on ln x over every fragment, the end-of-step curve
Pend = np.cumsum(dP)
m = (Pend > 0.02) & (Pend < 0.98)
nOld, cOld = np.polyfit(np.log(xs[m]), np.log(-np.log(1 - Pend[m])), 1)
x50Old = np.exp(-cOld / nOld) * np.log(2) ** (1 / nOld)

# Kuz-Ram / KCO for the same round (assumptions: README.md)
chargePerMetre = TNT["rho0"] * np.pi * R_CHARGE ** 2
Qhole = chargePerMetre * BENCH_HEIGHT
qSpec = chargePerMetre / (BURDEN * SPACING)
rws = 100 * TNT["E0"] / TNT["rho0"] / ANFO_ENERGY
Arock = bf.cunningham_rock_factor(ROCK_MASS_DESCRIPTION, 0, RHO_ROCK, E_ROCK)
kco = bf.kco(Arock, qSpec, Qhole, rws, BURDEN, SPACING, 2e3 * R_HOLE, 0.0,
             BENCH_HEIGHT, BENCH_HEIGHT, SPACING)
inFlight = speed > FLIGHT_SPEED
crackLines = read_vtp_lines(os.path.join(here, "VTK", f"cracks_{len(steps) - 1}.vtp"))
crackFile = os.path.join(here, "postProcessing", "jwlIbFoam",
                         f"cracks_{latest_time(here)}.dat")
cracks0 = np.loadtxt(crackFile, ndmin=2) if os.path.exists(crackFile) else np.zeros((0, 4))
if len(cracks0):
    mid = 0.5 * (cracks0[:, :2] + cracks0[:, 2:])
    rCrack = np.linalg.norm(mid - HOLE, axis=1)
    lCrack = np.linalg.norm(cracks0[:, 2:] - cracks0[:, :2], axis=1)
    crackReach = rCrack.max()
    brokenLength = lCrack.sum()
    # Cracked zone: the circle about the hole holding 90 % of the broken
    # joint length (the spalling at the free face included)
    o = np.argsort(rCrack)
    crackedRadius = np.interp(0.9, np.cumsum(lCrack[o]) / brokenLength, rCrack[o])
else:
    crackReach = brokenLength = crackedRadius = 0.0
# Crushed zone: rings about the hole (initial positions) in which at least
# half of the rock ends in fragments smaller than one element size (pieces
# of about one triangle); crushedRadius is the outer edge of the last such
# ring counted from the hole wall
hTri = np.sqrt(4 / np.sqrt(3) * area0)
small = np.sqrt(4 * fArea[frag] / np.pi) < hTri
rTri = np.linalg.norm(cent0 - HOLE, axis=1)
ring = np.arange(R_HOLE, 0.3, 0.005)
ringArea = np.histogram(rTri, ring, weights=area0)[0]
ringSmall = np.histogram(rTri, ring, weights=area0 * small)[0]
crushedFrac = ringSmall / np.maximum(ringArea, 1e-300)
nCrushed = np.argmax(crushedFrac < 0.5) if (crushedFrac < 0.5).any() else len(crushedFrac)
crushedRadius = ring[nCrushed]
# Esen et al. (2003): borehole pressure of the decoupled charge = the JWL
# products at their initial energy E0 filling the hole (relative volume
# V = (r_hole/r_charge)^2, no work done)
Vrel = (R_HOLE / R_CHARGE) ** 2
Pb = bf.jwl_pressure(TNT, Vrel, TNT["E0"])
sigmaC = bf.ucs_mohr_coulomb(C_ROCK, PHI_ROCK)
rEsen, czi = bf.esen_crushed_radius(Pb, sigmaC, E_ROCK, NU_ROCK, R_HOLE)

# Peak particle velocity at the solid probes, damage threshold f_t c_p/E
cP = np.sqrt(E_ROCK * (1 - NU_ROCK) / ((1 + NU_ROCK) * (1 - 2 * NU_ROCK)) / RHO_ROCK)
ppvCrit = bf.ppv_damage_threshold(FT_ROCK, E_ROCK, cP)
gauges = bf.read_probes(os.path.join(here, "postProcessing", "gauges"))
gaugePts = bf.probe_points(os.path.join(here, "postProcessing", "gauges"))
nG = len(gaugePts)
gaugeSpeed = np.stack([np.hypot(gauges[f"probe{i}_Ux"], gauges[f"probe{i}_Uy"])
                       for i in range(nG)], 1)
ppv = gaugeSpeed.max(axis=0)
rGauge = np.linalg.norm(gaugePts - HOLE, axis=1)

# Throw: ballistic landing of each loose fragment (system/throwDict)
throwDict = os.path.join(here, "system", "throwDict")
g = bf.read_entry(throwDict, "gravity", 9.81)
zFloor = bf.read_entry(throwDict, "floorLevel", -0.5)
cEnd = vEnd["Points"][:, :2][vEnd["triangles"]].mean(axis=1)
fCent = np.stack([np.bincount(frag, area0 * cEnd[:, k], len(fArea))
                  for k in range(2)], 1)[loose] / A[:, None]
# Only fragments moving out of the face fly; the others are held by the
# rock around them and stay where they are
towardsFace = fVel[loose][:, 1] > 0
land, tFlight = bf.ballistic_landing(fCent, np.zeros(len(A)),
                                     fVel[loose] * towardsFace[:, None],
                                     np.zeros(len(A)), zFloor, g)
throwDist = land[:, 1] - BENCH[3]          # beyond the free face y = 0
maxThrow = throwDist.max()

# Borehole pressure (probe at the hole centre)
probe = joined_rows(here, "boreholeProbe", "p")
tP, pP = probe[:, 0], probe[:, 1]

# Hole-wall pressure (Allrun -water and -waterCase: the probe beside the
# hole at its wall)
holeWallDir = os.path.join(here, "postProcessing", "holeWallProbe")
holeWall = joined_rows(here, "holeWallProbe", "p") if os.path.isdir(holeWallDir) else None
materials = re.search(r"^materials\s*\(([^)]*)\)", open(_case("constant", "thermophysicalProperties")).read(),
                      re.M).group(1).split()

# Budget: gas + solid energy, gas mass
b = budget_table(here)    # every start time's budget.dat, restarts joined
Etot = gas_energy(b) + solid_energy(b)
Echarge = Etot[0]                 # the products' energy dominates (air 0.3 %)
Egain = (Etot[-1] - Etot[0]) / Echarge
mGas = gas_mass(b)
massDrift = abs(mGas[-1] - mGas[0]) / mGas[0]
tab = log_table(os.path.join(here, "log.jwlIbFoam"))

# ---------------------------------------------------------------- figures
def draw_solid(ax, vtu, lines, title):
    P = vtu["Points"][:, :2]
    f = np.rint(vtu["fragment"]).astype(int)
    fa = np.bincount(f, area0)
    rng = np.random.default_rng(1)
    colours = plt.cm.tab20(rng.integers(0, 20, f.max() + 1))
    colours[np.argmax(fa)] = (0.75, 0.75, 0.75, 1)     # the rock mass
    ax.add_collection(PolyCollection(P[vtu["triangles"]], facecolors=colours[f],
                                     edgecolors="none"))
    if len(lines):
        ax.add_collection(LineCollection(lines, colors="k", linewidths=0.4))
    ax.set_xlim(-0.3, 0.3); ax.set_ylim(-0.4, 0.12)
    ax.set_aspect("equal"); ax.set_title(title, fontsize=9)


pick = np.unique(np.linspace(0, len(steps) - 1, 4).round().astype(int))
fig, axs = plt.subplots(1, len(pick), figsize=(4.2 * len(pick), 4.2))
for ax, i in zip(np.atleast_1d(axs), pick):
    t, f = steps[i]
    v = read_vtu(f)
    lines = read_vtp_lines(os.path.join(here, "VTK", f"cracks_{i}.vtp"))
    draw_solid(ax, v, lines, f"t = {t * 1e6:.0f} us: {len(lines)} broken joints, "
               f"{int(np.rint(v['fragment']).max()) + 1} pieces")
fig.suptitle("Bench blast (plan view): fragments (colours), broken joints (black); "
             "free face at y = 0")
fig.tight_layout()
fig.savefig(os.path.join(here, "crackPattern.png"), dpi=130)

# Gas: pressure and products in the cracks at the last time
tl = latest_time(here)
nx, ny = (240, 280) if os.path.exists(os.path.join(here, ".fine")) else (120, 140)
p = read_field(here, tl, "p", nx * ny).reshape(ny, nx)
ap = read_field(here, tl, "alpha.products", nx * ny).reshape(ny, nx)
phi = read_field(here, tl, "fluidFraction", nx * ny).reshape(ny, nx)
fig, axs = plt.subplots(1, 2, figsize=(10, 5.5))
ext = FLUID
im = axs[0].imshow(np.log10(np.where(phi > 0, p, np.nan)), origin="lower",
                   extent=ext, cmap="inferno")
fig.colorbar(im, ax=axs[0], label="log10 p [Pa] (gas cells)")
im = axs[1].imshow(np.where(phi > 0, ap, np.nan), origin="lower", extent=ext,
                   cmap="viridis", vmin=0, vmax=1)
fig.colorbar(im, ax=axs[1], label="products volume fraction")
for ax in axs:
    if len(crackLines):
        ax.add_collection(LineCollection(crackLines, colors="w", linewidths=0.3))
    ax.set_aspect("equal")
axs[0].set_title(f"gas pressure, t = {float(tl) * 1e6:.0f} us")
axs[1].set_title("detonation products venting into the cracks")
fig.tight_layout()
fig.savefig(os.path.join(here, "gasVenting.png"), dpi=130)

# Products along the cracks, at the write time nearest 0.2 ms (the end in
# quick mode): gas cells (cracks the mesh resolves) and the crack gas of the
# broken joints (crackGas, VTK/cracks_<i>.vtp) holding products above
# ALPHA_VENT at R_VENT or more from the hole centre; their directions about
# the hole, grouped where less than VENT_GAP degrees apart, are the radial
# cracks the products have run along
ALPHA_VENT, R_VENT, VENT_GAP = 0.01, 5 * R_HOLE, 10.0
T_VENT = 2e-4


def time_dir_near(t):
    times = [d for d in os.listdir(here) if re.fullmatch(r"[0-9.eE+-]+", d)
             and os.path.exists(os.path.join(here, d, "alpha.products"))]
    return min(times, key=lambda d: abs(float(d) - t))


def vent_directions(angles):
    """Groups of directions (degrees) less than VENT_GAP apart, on the circle"""
    a = np.sort(np.asarray(angles) % 360)
    if a.size == 0:
        return 0
    gaps = np.diff(np.append(a, a[0] + 360))
    return max(1, int((gaps > VENT_GAP).sum()))


iVent = int(np.argmin([abs(t - min(T_VENT, steps[-1][0])) for t, _ in steps]))
tVent = steps[iVent][0]
dVent = time_dir_near(tVent)
xc = FLUID[0] + (np.arange(nx) + 0.5) * (FLUID[1] - FLUID[0]) / nx
yc = FLUID[2] + (np.arange(ny) + 0.5) * (FLUID[3] - FLUID[2]) / ny
XC, YC = np.meshgrid(xc, yc)
apV = read_field(here, dVent, "alpha.products", nx * ny).reshape(ny, nx)
phiV = read_field(here, dVent, "fluidFraction", nx * ny).reshape(ny, nx)
rC = np.hypot(XC - HOLE[0], YC - HOLE[1])
cellsVent = (phiV > 0) & (apV > ALPHA_VENT) & (rC >= R_VENT)
ventAngles = list(np.degrees(np.arctan2(YC - HOLE[1], XC - HOLE[0]))[cellsVent])
# The farthest products in the rock: gas cells behind the free face (the
# hole, its crushed zone and the cracks the mesh resolves) and, below, the
# crack gas
inRock = (phiV > 0) & (apV > ALPHA_VENT) & (YC < BENCH[3])
meshVentReach = rC[inRock].max() if inRock.any() else 0.0
crackFile = lambda i: os.path.join(here, "VTK", f"cracks_{i}.vtp")
crackGasOn = "crackGas" in read_vtp_line_fields(crackFile(iVent))
netAlphaName = "alpha.products"
netVentReach = 0.0
if crackGasOn:
    seg = read_vtp_lines(crackFile(iVent))
    cf = read_vtp_line_fields(crackFile(iVent))
    mid = seg.mean(axis=1)
    rN = np.hypot(mid[:, 0] - HOLE[0], mid[:, 1] - HOLE[1])
    inNet = cf["crackGas"] > 0.5
    withProducts = inNet & (cf[netAlphaName] > ALPHA_VENT)
    netVentReach = rN[withProducts].max() if withProducts.any() else 0.0
    sel = withProducts & (rN >= R_VENT)
    ventAngles += list(np.degrees(np.arctan2(mid[sel, 1] - HOLE[1], mid[sel, 0] - HOLE[0])))
    # Crack gas pressure over the written times: the highest, and the mean
    # over the crack gas's volume (aperture x length)
    tN, pMaxN, pMeanN, nNet = [], [], [], []
    for i, (t, _) in enumerate(steps):
        f = read_vtp_line_fields(crackFile(i))
        if "crackGas" not in f:
            continue
        on = f["crackGas"] > 0.5
        sg = read_vtp_lines(crackFile(i))
        vol = f["aperture"] * np.hypot(*(sg[:, 1] - sg[:, 0]).T)
        tN.append(t)
        nNet.append(on.sum())
        pMaxN.append(f["p"][on].max() if on.any() else 0.0)
        pMeanN.append((f["p"] * vol)[on].sum() / vol[on].sum() if on.any() else 0.0)
    fig, axs = plt.subplots(1, 2, figsize=(11, 4))
    ax = axs[0]
    ax.semilogy(np.array(tN) * 1e6, np.maximum(pMaxN, 1), "r-", label="highest")
    ax.semilogy(np.array(tN) * 1e6, np.maximum(pMeanN, 1), "b-", label="volume mean")
    ax.set_xlabel("t [us]"); ax.set_ylabel("crack gas pressure [Pa]")
    ax.legend(); ax.grid(True, which="both", alpha=0.3)
    ax.set_title(f"Gas in the cracks narrower than a cell ({nNet[-1]} joints at the end)",
                 fontsize=9)
    ax = axs[1]
    seg = read_vtp_lines(crackFile(iVent))
    lc = LineCollection(seg[inNet], array=cf[netAlphaName][inNet], cmap="viridis",
                        linewidths=1.2)
    lc.set_clim(0, 1)
    ax.add_collection(lc)
    ax.add_collection(LineCollection(seg[~inNet], colors="0.7", linewidths=0.6))
    ax.add_patch(plt.Circle(HOLE, R_VENT, fill=False, ls="--", color="k", lw=0.6))
    fig.colorbar(lc, ax=ax, label="products volume fraction in the crack gas")
    ax.set_xlim(BENCH[0], BENCH[1]); ax.set_ylim(BENCH[2], BENCH[3])
    ax.set_aspect("equal")
    ax.set_title(f"t = {tVent * 1e6:.0f} us; dashed: 5 hole radii; grey: cracks open "
                 "to the mesh", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "crackGas.png"), dpi=130)
ventCracks = vent_directions(ventAngles)

fig, ax = plt.subplots(figsize=(6, 4))
ax.semilogy(tP * 1e6, pP, "r-")
ax.set_xlabel("t [us]"); ax.set_ylabel("p at the borehole centre [Pa]")
ax.set_title("Borehole pressure (probe at the hole centre)")
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "boreholePressure.png"), dpi=130)

fig, axs = plt.subplots(1, 2, figsize=(12, 4.6))
xg = np.geomspace(xs.min(), max(xs.max(), sw["xmax"]) * 1.2, 200)
ax = axs[0]
ax.semilogx(xs[~lim] * 1e3, Pass[~lim] * 100, "b.", ms=3, label="fragments (fitted)")
ax.semilogx(xs[lim] * 1e3, Pass[lim] * 100, ".", color="0.6", ms=3,
            label="resolution-limited (< 2 element sizes, not fitted)")
ax.semilogx(xg * 1e3, 100 * bf.rosin_rammler(xg, rr["x50"], rr["n"]), "k-",
            label=f"Rosin-Rammler x50 {rr['x50'] * 1e3:.1f} mm, n {rr['n']:.2f} "
                  f"(rms {rr['rms']:.3f})")
ax.semilogx(xg * 1e3, 100 * bf.swebrec(xg, sw["x50"], sw["xmax"], sw["b"]), "r-",
            label=f"Swebrec x50 {sw['x50'] * 1e3:.1f} mm, xmax {sw['xmax'] * 1e3:.0f} mm, "
                  f"b {sw['b']:.2f} (rms {sw['rms']:.3f})")
ax.semilogx(xg * 1e3, 100 * bf.swebrec(xg, kco["x50"], kco["xmax"], kco["b"]), "g--",
            label=f"KCO prediction x50 {kco['x50'] * 1e3:.1f} mm, b {kco['b']:.2f}")
ax.semilogx(xg * 1e3, 100 * bf.rosin_rammler(xg, kco["x50"], kco["n"]), "g:",
            label=f"Kuz-Ram (Rosin-Rammler) n {kco['n']:.2f}")
ax.axvline(x50 * 1e3, color="b", ls=":", lw=0.8)
ax.set_xlabel("equivalent size sqrt(4A/pi) [mm]"); ax.set_ylabel("passing by mass [%]")
ax.set_ylim(0, 100)
ax.legend(fontsize=7, loc="upper left")
ax.set_title(f"{loose.sum()} fragments at t = {tEnd * 1e6:.0f} us, measured x50 "
             f"{x50 * 1e3:.1f} mm", fontsize=9)
axs[1].hist(speed, bins=30, color="tab:orange")
axs[1].set_xlabel("mean fragment velocity [m/s]"); axs[1].set_ylabel("fragments")
axs[1].set_title(f"throw velocities: max {speed.max():.1f} m/s, "
                 f"{inFlight.sum()} above {FLIGHT_SPEED:g} m/s")
fig.tight_layout()
fig.savefig(os.path.join(here, "fragments.png"), dpi=130)

# Damage zones and vibration
fig, axs = plt.subplots(1, 2, figsize=(12, 4.6))
ax = axs[0]
draw_solid(ax, vEnd, crackLines, "")
th = np.linspace(0, 2 * np.pi, 200)
for r, c, lab in [(R_HOLE, "k", "hole"), (crushedRadius, "r", "crushed zone (simulated)"),
                  (max(rEsen, R_HOLE), "m", f"Esen et al. r_c = {rEsen * 1e3:.1f} mm"),
                  (crackedRadius, "b", "cracked zone (90 % of broken joint length)")]:
    ax.plot(HOLE[0] + r * np.cos(th), HOLE[1] + r * np.sin(th), c + "-", lw=1, label=lab)
ax.plot(gaugePts[:, 0], gaugePts[:, 1], "k^", ms=5, label="solid probes (initial positions)")
ax.legend(fontsize=7, loc="lower left")
ax.set_title(f"t = {tEnd * 1e6:.0f} us: crushed {crushedRadius * 1e3:.0f} mm, cracked "
             f"{crackedRadius * 1e3:.0f} mm (hole r {R_HOLE * 1e3:.0f} mm)", fontsize=9)
ax = axs[1]
for i in range(nG):
    ax.plot(gauges["Time"] * 1e6, gaugeSpeed[:, i], lw=0.8,
            label=f"({gaugePts[i, 0]:g}, {gaugePts[i, 1]:g}): r {rGauge[i]:.3f} m, "
                  f"PPV {ppv[i]:.2f} m/s")
ax.axhline(ppvCrit, color="k", ls="--", label=f"damage threshold f_t c_p/E = {ppvCrit:.2f} m/s")
ax.set_xlabel("t [us]"); ax.set_ylabel("particle speed |v| [m/s]")
ax.set_yscale("log"); ax.set_ylim(1e-3, None)
ax.legend(fontsize=6)
ax.set_title("Solid probes (postProcessing/gauges)", fontsize=9)
fig.tight_layout()
fig.savefig(os.path.join(here, "damageVibration.png"), dpi=130)

# Muck pile: landed area per unit distance from the face
fig, ax = plt.subplots(figsize=(7, 4))
edges = np.linspace(min(0.0, throwDist.min()), maxThrow * 1.02 + 1e-9, 60)
hist, _ = np.histogram(throwDist, edges, weights=A)
ax.bar(0.5 * (edges[1:] + edges[:-1]), hist / np.diff(edges) / A.sum(),
       width=np.diff(edges), color="tab:brown")
ax.set_xlabel("landing distance from the free face [m]")
ax.set_ylabel("fraction of the broken rock per metre [1/m]")
ax.set_title(f"Muck pile: ballistic from the face, floor {-zFloor:g} m below the "
             f"section, g {g:g}: max throw {maxThrow:.2f} m", fontsize=9)
fig.tight_layout()
fig.savefig(os.path.join(here, "muckPile.png"), dpi=130)

if "-noAnimation" not in sys.argv:
    bf.animate(os.path.join(here, "blast.gif"), steps, read_vtu, draw_solid,
               lambda i: read_vtp_lines(os.path.join(here, "VTK", f"cracks_{i}.vtp")),
               here, (nx, ny), FLUID)

# ---------------------------------------------------------------- summary
nMin = 10 if quick else 30
FIT_RMS = 0.05                          # rms of the fits in passing fraction
X50_TOL, X80_TOL = 0.15, 0.25
figs = [
    figure("end time [s]", tEnd),
    figure("peak pressure at the borehole centre [Pa]", pP.max()),
    figure("borehole pressure at the end [Pa]", pP[-1]),
    figure("min gas density over all steps [kg/m3] (> 0)", tab[:, 5].min(), 0, 0,
           error=max(0, -tab[:, 5].min()), passed=bool(tab[:, 5].min() > 0)),
    figure("min gas pressure over all steps [Pa] (> 0)", tab[:, 6].min(), 0, 0,
           error=max(0, -tab[:, 6].min()), passed=bool(tab[:, 6].min() > 0)),
    figure("gas mass drift (relative)", massDrift, 0, 1e-3, error=massDrift),
    figure("fragment areas / solid area (fragment partition)",
           fArea.sum() / area0.sum(), 1, 1e-6, relative=True),
    figure("broken joints", b["brokenJoints"][-1]),
    figure("broken joint length [m]", brokenLength),
    figure("crack reach from the hole centre [m] (burden 0.15)", crackReach),
    figure("cracked zone radius (90 % of the broken joint length) [m]", crackedRadius),
    figure("crushed zone radius (rings >= 50 % in one-element fragments) [m]", crushedRadius),
    figure("Esen et al. crushed zone radius [m] (below the hole radius: none)", rEsen),
    figure("Esen et al. borehole pressure (products filling the hole) [Pa]", Pb),
    figure("Esen et al. crushed zone index CZI", czi),
    figure(f"fragments (loose pieces, >= {nMin})", loose.sum(), nMin, 0,
           error=max(0, nMin - loose.sum()), passed=bool(loose.sum() >= nMin)),
    figure(f"fragments in flight (> {FLIGHT_SPEED:g} m/s, >= 1)", inFlight.sum(), 1, 0,
           error=max(0, 1 - inFlight.sum()), passed=bool(inFlight.sum() >= 1)),
    figure("max fragment throw velocity [m/s]", speed.max()),
    figure("mass-weighted mean fragment velocity [m/s]", (speed * A).sum() / A.sum()),
    figure("x50 measured [m]", x50),
    figure("x80 measured [m]", x80),
    figure("resolution-limited mass fraction (< 2 element sizes)", A[limited].sum() / A.sum()),
    figure("Rosin-Rammler uniformity n", rr["n"]),
    figure("Rosin-Rammler fit rms error (passing fraction)", rr["rms"], 0, FIT_RMS,
           error=rr["rms"]),
    figure("Rosin-Rammler x50 [m] (vs measured)", rr["x50"], x50, X50_TOL, relative=True),
    figure("Rosin-Rammler x80 [m] (vs measured)", rr["x80"], x80, X80_TOL, relative=True),
    figure("Swebrec fit rms error (passing fraction)", sw["rms"], 0, FIT_RMS,
           error=sw["rms"]),
    figure("Swebrec x50 [m] (vs measured)", sw["x50"], x50, X50_TOL, relative=True),
    figure("Swebrec x80 [m] (vs measured)", sw["x80"], x80, X80_TOL, relative=True),
    figure("Swebrec xmax [m]" + (f" (at its bound, the block's diagonal {BLOCK:.3g} m: the curve"
           " is nearer the log-logistic limit)" if sw["atBound"] else ""), sw["xmax"]),
    figure("Swebrec undulation b", sw["b"]),
    figure("old linearised Rosin-Rammler x50 [m] (all fragments; not checked)", x50Old,
           x50, relative=True, passed=True),
    figure("KCO x50 [m] (Kuz-Ram, assumptions in README)", kco["x50"]),
    figure("KCO uniformity n (Cunningham)", kco["n"]),
    figure("KCO Swebrec b", kco["b"]),
    figure("Kuz-Ram rock factor A (Cunningham)", Arock),
    figure("Kuz-Ram specific charge [kg/m3]", qSpec),
    figure("Kuz-Ram relative weight strength (ANFO 100)", rws),
    figure("PPV damage threshold f_t c_p/E [m/s]", ppvCrit),
    *[figure(f"PPV at gauge ({gaugePts[i, 0]:g} {gaugePts[i, 1]:g}), r = {rGauge[i]:.3f} m"
             " [m/s]", ppv[i]) for i in range(nG)],
    figure("max throw distance from the free face [m] (ballistic)", maxThrow),
    figure("mean throw distance (mass-weighted) [m]", (throwDist * A).sum() / A.sum()),
    figure("fragments thrown out of the face", towardsFace.sum()),
    # The cut-cell coupling is exact; what is left is FEMDEM's own budget
    # and the gas leaving through the outlet (the removed first generation
    # gained 1 - 2 %, README)
    figure("energy gained by gas + solid / initial gas energy (cut cells:"
           " includes the gas leaving through the outlet)", Egain, 0.0, 1e-2),
    figure(f"products (> {ALPHA_VENT:g}) at >= 5 hole radii at t = {tVent:g} s: "
           "radial cracks", ventCracks),
    figure("products in the crack gas: farthest from the hole centre [m]", netVentReach),
    figure(f"products (> {ALPHA_VENT:g}) in the rock at t = {tVent:g} s: farthest from the hole"
           " centre, gas cells or crack gas [m]", max(meshVentReach, netVentReach)),
    figure("lined hole (crackVenting false, no crackGas)", float(lined)),
]
if crackGasOn:
    figs += [figure("crack gas: joints at the end", nNet[-1]),
             figure("crack gas: highest pressure over the run [Pa]", max(pMaxN))]

# ------------------------------------------------ lined versus unlined
# The lined hole run by Allrun in the generated copy lined/ (its own
# plot.py wrote lined/summary.json): the figures the liner experiments
# compare, side by side, found by the start of their names
COMPARE = [
    ("broken joint length [m]", "broken joint length"),
    ("broken joints", "broken joints"),
    ("crack reach from the hole centre [m]", "crack reach from the hole centre"),
    ("cracked zone radius [m]", "cracked zone radius"),
    ("crushed zone radius [m]", "crushed zone radius"),
    ("fragments (loose pieces)", "fragments (loose pieces"),
    ("fragments in flight (> 5 m/s)", "fragments in flight"),
    ("max fragment throw velocity [m/s]", "max fragment throw velocity"),
    ("mass-weighted mean fragment velocity [m/s]", "mass-weighted mean fragment velocity"),
    ("max throw distance from the face [m]", "max throw distance"),
    ("mean throw distance [m]", "mean throw distance"),
    ("x50 measured [m]", "x50 measured"),
    ("peak borehole pressure [Pa]", "peak pressure at the borehole centre"),
    ("borehole pressure at the end [Pa]", "borehole pressure at the end"),
    (f"radial cracks with products at >= 5 hole radii at {tVent:g} s",
     f"products (> {ALPHA_VENT:g}) at >= 5 hole radii"),
    (f"products reach in the rock at {tVent:g} s [m]", f"products (> {ALPHA_VENT:g}) in the rock"),
    ("products reach in the crack gas [m]", "products in the crack gas: farthest"),
    ("gas + solid energy change / initial gas energy", "energy gained by gas + solid"),
]
linedSummary = _case("lined", "summary.json")
if not lined and os.path.exists(linedSummary):
    def by_start(figures, start):
        hit = [f for f in figures if f["name"].startswith(start)]
        if not hit:
            sys.exit(f"plot.py: no figure '{start}...' for the lined versus unlined table")
        return hit[0]["value"]
    linedFigs = json.load(open(linedSummary))["figures"]
    rows = [(label, by_start(figs, start), by_start(linedFigs, start))
            for label, start in COMPARE]
    tLined = by_start(linedFigs, "end time")
    # the same round to the same time, or the comparison means nothing
    figs.append(figure("lined versus unlined: lined end time [s] (= unlined)", tLined,
                       tEnd, 1e-9, relative=True))
    figs.append(figure("lined versus unlined: lined hole (lined/summary.json, crackVenting"
                       " false, no crackGas)", by_start(linedFigs, "lined hole"), 1, 0))
    for label, u, l in rows:
        figs.append(figure(f"lined versus unlined: {label}: unlined", u))
        figs.append(figure(f"lined versus unlined: {label}: lined", l))
    with open(os.path.join(here, "linedVsUnlined.dat"), "w") as fh:
        fh.write(f"# benchBlast at t = {tEnd:g} s: unlined (this case) and lined (lined/)\n"
                 "# figure\tunlined\tlined\tlined/unlined\n")
        for label, u, l in rows:
            fh.write(f"{label}\t{u:.6g}\t{l:.6g}\t"
                     f"{(l / u if u else float('nan')):.4g}\n")
    # Picture: borehole pressure of both, the ratios, the broken joints
    probeL = joined_rows(_case("lined"), "boreholeProbe", "p")
    fig, axs = plt.subplots(1, 3, figsize=(16, 5), gridspec_kw={"width_ratios": [1, 1.2, 1]})
    ax = axs[0]
    ax.semilogy(tP * 1e6, pP, "r-", label="unlined")
    ax.semilogy(probeL[:, 0] * 1e6, probeL[:, 1], "b-", label="lined")
    ax.set_xlabel("t [us]"); ax.set_ylabel("p at the borehole centre [Pa]")
    ax.legend(); ax.grid(True, which="both", alpha=0.3)
    ax.set_title("Borehole pressure", fontsize=9)
    ax = axs[1]
    ratio = [l / u if u else np.nan for _, u, l in rows]
    yy = np.arange(len(rows))
    ax.barh(yy, ratio, color=["tab:blue" if r <= 1 else "tab:red" for r in ratio])
    ax.axvline(1, color="k", lw=0.8)
    ax.set_yticks(yy)
    ax.set_yticklabels([f"{lab} ({u:.3g} / {l:.3g})" for lab, u, l in rows], fontsize=6)
    ax.invert_yaxis()
    ax.set_xlabel("lined / unlined")
    ax.set_title(f"t = {tEnd * 1e6:.0f} us (unlined / lined values)", fontsize=9)
    ax = axs[2]
    linesL = read_vtp_lines(_case("lined", "VTK", os.path.basename(crackFile(len(steps) - 1))))
    if len(crackLines):
        ax.add_collection(LineCollection(crackLines, colors="r", linewidths=0.4,
                                         label=f"unlined: {len(crackLines)}"))
    if len(linesL):
        ax.add_collection(LineCollection(linesL, colors="b", linewidths=0.4,
                                         label=f"lined: {len(linesL)}"))
    ax.set_xlim(BENCH[0], BENCH[1]); ax.set_ylim(BENCH[2], 0.12)
    ax.set_aspect("equal"); ax.legend(fontsize=7, loc="lower left")
    ax.set_title("Broken joints at the end (current positions)", fontsize=9)
    fig.suptitle("Liner experiment: the hole unlined (gas in the cracks) and lined "
                 "(stress wave and hole pressure only)")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "linedVsUnlined.png"), dpi=130)
if holeWall is not None:
    figs.append(figure("peak hole-wall pressure [Pa]", holeWall[:, 1].max()))
    figs.append(figure("time of the peak hole-wall pressure [s]",
                       holeWall[np.argmax(holeWall[:, 1]), 0]))
    figs.append(figure("gap material (1 water, 0 air)", float("water" in materials)))

# ------------------------------------------------ water versus air decoupling
# Allrun -water: this case has the air gap, water/ the water-filled one.
# Estimates: air gap, the quasi-static borehole pressure of the products
# filling the hole (Esen et al. 2003, Pb above); water gap, acoustic
# impedance matching: the products' shock into water at the charge (the
# exact Riemann solution of TNT in the constant-volume explosion state |
# water, p* = 3.3555 GPa: tutorials/jwlIbFoam/waterShockTubes), spreading
# cylindrically to the wall (amplitude ~ r^-1/2) and transmitted into the
# rock with 2 Z_rock/(Z_rock + Z_water) (Z = rho c: water 1000 kg/m3 at
# the stiffened gas's 1625 m/s, the rock's p-wave impedance)
waterSummary = _case("water", "summary.json")
if holeWall is not None and "water" not in materials and os.path.exists(waterSummary):
    wf = {f["name"]: f["value"] for f in json.load(open(waterSummary))["figures"]}
    pAir = holeWall[:, 1].max()
    pWater = wf["peak hole-wall pressure [Pa]"]
    P_STAR_WATER = 3.3555e9
    zWater, zRock = 1000 * 1625.0, RHO_ROCK * cP
    estWater = P_STAR_WATER * np.sqrt(R_CHARGE / R_HOLE) * 2 * zRock / (zRock + zWater)
    figs += [
        figure("water versus air: water end time [s] (= air)", wf["end time [s]"], tEnd,
               1e-9, relative=True),
        figure("water versus air: peak hole-wall pressure, air gap [Pa]", pAir),
        figure("water versus air: peak hole-wall pressure, water gap [Pa]", pWater),
        figure("water versus air: estimate, air gap (Esen et al. Pb) [Pa]", Pb),
        figure("water versus air: estimate, water gap (impedance matching) [Pa]", estWater),
        # water transmits more: the ratio must exceed 1 (error: how far below)
        figure("water versus air: peak hole-wall pressure ratio water/air (> 1)",
               pWater / pAir, 1, 0, error=max(0.0, 1 - pWater / pAir)),
        figure("water versus air: estimated ratio water/air", estWater / Pb),
        figure("water versus air: water gap energy gained by gas + solid / initial gas"
               " energy", wf["energy gained by gas + solid / initial gas energy (cut cells:"
               " includes the gas leaving through the outlet)"], 0.0, 1e-2),
    ]

write_summary(os.path.join(here, "summary.json"), "jwlIbFoam/benchBlast", figs)
