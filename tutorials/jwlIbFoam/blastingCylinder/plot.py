"""Blasting cylinder (1-inch copper cylinder test, TNT or another preset, quarter section):
wall radius and velocity against time, wall velocity at R - R0 = 6 and
19 mm, terminal velocity against the Gurney cylinder formula, rupture of the
wall. Writes summary.json and blastingCylinder.png.

Wall velocity per step: the mass-averaged radial velocity of the quarter
tube from its momentum in budget.dat, v = (pi/4)(P_x + P_y)/M (for radial
motion P_x = P_y = (2/pi) M v); R - R0 is its time integral. Checked at the
write times against the mass-averaged radius and radial velocity of the
FEMDEM nodes (<time>/uniform/femdemState).
"""
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS",
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")),
    "jwlIbFoam", "common"))
import blastPost as bp  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Geometry and materials (system/femdemMeshDict, constant/femdemProperties);
# the explosive: the last 'explosive' entry of constant/thermophysicalProperties
# and its .mode file (Allrun -explosive), its density as setCharge used it
Ri, Ro = 0.0127, 0.0153
rhoCu = 8930.0
# Gurney constants sqrt(2E) [m/s] (Cooper, Explosives Engineering; HMX at
# 1.89 g/cm3, the preset's density). Every JWL preset of the library has
# one, so that ./Allrun -explosive NAME ends with its plot for each
GURNEY = {"TNT": 2440.0, "PETN": 2930.0, "CompB": 2700.0, "HMX": 2970.0}
tp = "".join(open(f).read() for f in ("constant/thermophysicalProperties",
             "constant/thermophysicalProperties.mode") if os.path.isfile(f))
explosive = re.findall(r"\bexplosive\s+(\w+)\s*;", tp)[-1]
if explosive not in GURNEY:
    sys.exit(f"plot.py: no Gurney constant for explosive {explosive}; "
             f"known: {' '.join(GURNEY)}")
sqrt2E = GURNEY[explosive]
rho0 = float(re.search(r"Explosive products: rho0 (\S+) kg/m3",
                       open("log.setCharge").read()).group(1))
M = rhoCu * np.pi * (Ro**2 - Ri**2)       # copper per unit length [kg/m]
C = rho0 * np.pi * Ri**2                  # explosive per unit length [kg/m]
vGurney = sqrt2E / np.sqrt(M / C + 0.5)


def read_list(text, name, kind=float):
    # OpenFOAM writes a list of equal values as N{value} (e.g. no joint
    # broken yet at an early write time)
    m = re.search(r"\n%s\s+(\d+)\s*\{\s*([^\s}]+)\s*\}" % name, text)
    if m:
        return np.full(int(m.group(1)), kind(m.group(2)))
    m = re.search(r"\n%s\s+(\d+)\s*\(" % name, text)
    n = int(m.group(1))
    body = text[m.end():]
    if kind is tuple:
        pairs = re.findall(r"\(\s*([^\s()]+)\s+([^\s()]+)\s*\)", body[:n * 64])[:n]
        return np.array(pairs, dtype=float)
    return np.array(body.split(None, n)[:n], dtype=kind)


def femdem_state(t):
    text = open(os.path.join(t, "uniform", "femdemState")).read()
    x, v = read_list(text, "x", tuple), read_list(text, "v", tuple)
    broken = read_list(text, "broken", int)
    return x, v, broken


def wall_mean(x, v):
    """Mass-averaged radius and radial velocity (node mass = rho A/3)."""
    tri = x.reshape(-1, 3, 2)
    a = 0.5 * np.abs((tri[:, 1, 0] - tri[:, 0, 0]) * (tri[:, 2, 1] - tri[:, 0, 1])
                     - (tri[:, 2, 0] - tri[:, 0, 0]) * (tri[:, 1, 1] - tri[:, 0, 1]))
    m = np.repeat(a / 3, 3)
    r = np.hypot(x[:, 0], x[:, 1])
    vr = (x[:, 0] * v[:, 0] + x[:, 1] * v[:, 1]) / r
    return np.sum(m * r) / m.sum(), np.sum(m * vr) / m.sum(), tri


budgetFile = sorted(glob.glob("postProcessing/jwlIbFoam/*/budget.dat"))[0]
b = np.loadtxt(budgetFile)
col = {n: i for i, n in enumerate(open(budgetFile).readline().split(":")[1].split())}
t, dt = b[:, col["time"]], b[:, col["dt"]]
Mq = 0.25 * M                              # the quarter's mass per depth
v = 0.25 * np.pi * (b[:, col["solidMomentumX"]] + b[:, col["solidMomentumY"]]) / Mq
broken, fragments = b[:, col["brokenJoints"]], b[:, col["fragments"]]
gasSolidEnergy = b[:, col["gasEnergy"]] + sum(
    b[:, col[n]] for n in ("solidKinetic", "solidElastic", "solidJointStored",
                           "solidFracture", "solidDamping", "solidContact"))

# Until gas leaves through the outer boundary (the gas mass, with what
# vanished pockets took, starts to change) nothing crosses the domain's edge:
# the energy budget is closed there
gasMass = b[:, col["gasMass"]] + (b[:, col["gasLostMass"]]
                                  if "gasLostMass" in col else 0)
leaving = np.abs(gasMass / gasMass[0] - 1) > 1e-9
closedUntil = int(np.argmax(leaving)) if leaving.any() else len(t)
closedUntil = max(closedUntil, 1)

# R - R0 by the trapezium rule from v = 0 at t = 0
dR = np.cumsum(0.5 * (v + np.concatenate(([0.0], v[:-1]))) * dt)
R0 = 2.0 / 3.0 * (Ro**3 - Ri**3) / (Ro**2 - Ri**2)   # mass-averaged radius

# Nodes at the write times
times = sorted((d for d in os.listdir(".")
                if re.match(r"^[0-9.e+-]+$", d) and float(d) > 0
                and os.path.isfile(os.path.join(d, "uniform", "femdemState"))),
               key=float)
stateR, stateV, stateT = [], [], []
for d in times:
    x, vn, _ = femdem_state(d)
    Rm, vr, _ = wall_mean(x, vn)
    stateT.append(float(d))
    stateR.append(Rm - R0)
    stateV.append(vr)
stateT, stateR, stateV = map(np.array, (stateT, stateR, stateV))

figures = []
dRend = dR[-1]
figures.append(bp.figure(
    f"terminal wall velocity [m/s] (at R - R0 = {dRend*1e3:.1f} mm, t = "
    f"{t[-1]*1e6:.1f} us) vs Gurney sqrt(2E)(M/C + 1/2)^-1/2, {explosive}"
    f" sqrt(2E) = {sqrt2E:.0f} m/s, M/C = {M/C:.3f}",
    v[-1], vGurney, 0.05, relative=True))
for target in (0.006, 0.019):
    if dRend >= target:
        vt = float(np.interp(target, dR, v))
        figures.append(bp.figure(
            f"wall velocity at R - R0 = {target*1e3:.0f} mm [m/s] (t = "
            f"{np.interp(target, dR, t)*1e6:.2f} us)", vt))
    else:
        figures.append(bp.figure(
            f"wall velocity at R - R0 = {target*1e3:.0f} mm [m/s]: not reached"
            f" (R - R0 = {dRend*1e3:.1f} mm at the end)", np.nan, passed=False))
# Two independent measures of the wall position and velocity
figures.append(bp.figure(
    "R - R0 from the femdemState nodes at the last write [mm] vs the time"
    " integral of the momentum velocity", stateR[-1] * 1e3,
    np.interp(stateT[-1], t, dR) * 1e3, 0.02 * dRend * 1e3))
figures.append(bp.figure(
    "radial velocity of the femdemState nodes at the last write [m/s] vs"
    " the momentum velocity", stateV[-1], np.interp(stateT[-1], t, v), 0.03,
    relative=True))

# Rupture of the wall
i1 = np.argmax(broken > 0) if broken.max() > 0 else None
i2 = np.argmax(fragments > 1) if fragments.max() > 1 else None
if i1 is not None:
    figures.append(bp.figure(
        f"first broken joint: time [us] (R - R0 = {dR[i1]*1e3:.2f} mm)",
        t[i1] * 1e6))
if i2 is not None:
    figures.append(bp.figure(
        f"first fragment separated: time [us] (R - R0 = {dR[i2]*1e3:.2f} mm)",
        t[i2] * 1e6))
# Pattern of the first cracks: the earliest crack table with broken joints;
# initial positions; a radial crack has its faces along r (hoop opening)
for d in times:
    f = os.path.join("postProcessing", "jwlIbFoam", f"cracks_{d}.dat")
    c = np.loadtxt(f, ndmin=2) if os.path.isfile(f) else np.zeros((0, 4))
    if len(c):
        mid = 0.5 * (c[:, :2] + c[:, 2:])
        r = np.hypot(mid[:, 0], mid[:, 1])
        e = c[:, 2:] - c[:, :2]
        cosr = np.abs((e * mid).sum(axis=1)) / (np.hypot(e[:, 0], e[:, 1]) * r)
        figures.append(bp.figure(
            f"first cracks (t = {float(d)*1e6:.1f} us, {len(c)} joints):"
            f" median initial radius [mm] (wall {Ri*1e3:.1f} - {Ro*1e3:.1f});"
            f" radial (hoop-opening) fraction {np.mean(cosr > 0.7):.2f}",
            np.median(r) * 1e3))
        break
nJoints = None
if times:
    _, _, brk = femdem_state(times[-1])
    nJoints = brk.size
figures.append(bp.figure(
    f"broken joints at the end (of {nJoints}), fragments {int(fragments[-1])}",
    broken[-1]))
figures.append(bp.figure(
    f"gas + solid energy change until gas leaves the domain (t = "
    f"{t[closedUntil - 1]*1e6:.1f} us; relative, max over the steps; the"
    f" cut-cell coupling conserves it, FEMDEM's own budget closes to ~5e-5)",
    np.abs(gasSolidEnergy[:closedUntil] / gasSolidEnergy[0] - 1).max(),
    0.0, 1e-3))
figures.append(bp.figure(
    "gas + solid energy change over the run (relative, with the gas that"
    " left through the outer boundary; not checked)",
    gasSolidEnergy[-1] / gasSolidEnergy[0] - 1))

# Plot: velocity against R - R0, R - R0 against time, the tube
fig = plt.figure(figsize=(14, 4.8))
ax1 = fig.add_subplot(1, 3, 1)
ax1.plot(dR * 1e3, v, label="jwlIbFoam (momentum of the tube)")
ax1.plot(stateR * 1e3, stateV, "o", ms=4, label="femdemState nodes")
ax1.axhline(vGurney, color="k", ls="--",
            label=f"Gurney {vGurney:.0f} m/s (M/C = {M/C:.2f})")
ax1.axhspan(0.9 * vGurney, 1.1 * vGurney, color="k", alpha=0.08)
for target in (6, 19):
    ax1.axvline(target, color="grey", lw=0.8, ls=":")
if i2 is not None:
    ax1.axvline(dR[i2] * 1e3, color="tab:red", lw=0.8,
                label="first fragment")
ax1.set_xlabel("R - R0 [mm]")
ax1.set_ylabel("wall velocity [m/s]")
ax1.legend(fontsize=8, loc="lower right")
ax2 = fig.add_subplot(1, 3, 2)
ax2.plot(t * 1e6, dR * 1e3, label="R - R0 [mm]")
ax2.plot(stateT * 1e6, stateR * 1e3, "o", ms=4, label="femdemState nodes")
ax2b = ax2.twinx()
ax2b.plot(t * 1e6, broken, color="tab:red", lw=0.8, label="broken joints")
ax2b.set_ylabel("broken joints", color="tab:red")
ax2.set_xlabel("t [us]")
ax2.set_ylabel("R - R0 [mm]")
ax2.legend(fontsize=8, loc="upper left")
ax3 = fig.add_subplot(1, 3, 3)
for d, colour in zip(times[::max(1, len(times) // 4)], plt.cm.viridis(
        np.linspace(0, 0.9, 5))):
    x, vn, _ = femdem_state(d)
    _, _, tri = wall_mean(x, vn)
    for tr in tri:
        ax3.fill(tr[:, 0] * 1e3, tr[:, 1] * 1e3, fc=colour, ec="none")
    ax3.plot([], [], "s", color=colour, label=f"t = {float(d)*1e6:.0f} us")
ax3.set_aspect("equal")
ax3.set_xlabel("x [mm]")
ax3.set_ylabel("y [mm]")
ax3.legend(fontsize=8, loc="upper right")
ax3.set_title("copper tube (quarter)")
fig.tight_layout()
fig.savefig("blastingCylinder.png", dpi=110)
bp.write_summary("summary.json", "blastingCylinder", figures)
