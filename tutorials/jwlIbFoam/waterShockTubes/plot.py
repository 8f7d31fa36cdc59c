#!/usr/bin/python3
"""Water shock tubes against the exact Riemann solution (water/air,
TNT/water), the three-material contact (p, u uniform, masses kept) and the
cavitating water expansion against the exact solution of the cut-off model.
Writes waterShockTubes.png and summary.json."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import read_field, read_exact, write_summary, figure, latest_time, log_table

here = os.path.dirname(os.path.abspath(__file__))
L = 1.0


def crossing(x, q, level, last=True):
    """x where q crosses level (the last or first crossing, linear)"""
    above = q > level
    idx = np.where(above[:-1] != above[1:])[0]
    i = idx[-1] if last else idx[0]
    return x[i] + (x[i + 1] - x[i]) * (q[i] - level) / (q[i] - q[i + 1])


def tube(name, first):
    """Simulated and exact profiles; the contact where alpha.<first>
    crosses 1/2, the shock where p crosses (p* + p_right)/2"""
    case = os.path.join(here, name)
    t = latest_time(case)
    ex, info = read_exact(case, t)
    n = len(ex)
    r = dict(x=ex[:, 0], ex=ex, info=info, t=float(t),
             rho=read_field(case, t, "rho", n),
             u=read_field(case, t, "U", n)[:, 0],
             p=read_field(case, t, "p", n),
             a=read_field(case, t, "alpha." + first, n))
    for k, col in (("rho", 1), ("u", 2), ("p", 3)):
        r["L1" + k] = np.abs(r[k] - ex[:, col]).mean() / np.abs(ex[:, col]).max()
    pR = ex[-1, 3]
    r["xc"] = crossing(r["x"], r["a"], 0.5)
    r["xs"] = crossing(r["x"], r["p"], 0.5 * (info["(p*"] + pR))
    r["xsEx"] = crossing(r["x"], ex[:, 3], 0.5 * (info["(p*"] + pR))
    r["xcEx"] = crossing(r["x"], ex[:, 4], 0.5)
    # rarefaction head: where p first falls 1 % below the left state
    pL = ex[0, 3]
    r["xh"] = crossing(r["x"], r["p"], 0.99 * pL, last=False)
    r["xhEx"] = crossing(r["x"], ex[:, 3], 0.99 * pL, last=False)
    # the pressure behind the transmitted shock: the middle half between
    # contact and shock
    m = (r["x"] > r["xc"] + 0.25 * (r["xs"] - r["xc"])) & \
        (r["x"] < r["xs"] - 0.25 * (r["xs"] - r["xc"]))
    r["pBehind"] = r["p"][m].mean()
    return r


wa = tube("waterAir", "water")
tw = tube("tntWater", "products")

# Three-material contact through cyclic ends: one period
c3 = os.path.join(here, "contact3")
n, p0, u0 = 100, 1e5, 500.0
V = 1.0 / n * 0.01 * 0.01
a1 = read_field(c3, "0", "alpha.products", n)
a2 = read_field(c3, "0", "alpha.water", n)
r1 = read_field(c3, "0", "rho.products", n)
r2 = read_field(c3, "0", "rho.water", n)
r3 = read_field(c3, "0", "rho.air", n)
m0 = np.array([(a1 * r1).sum(), (a2 * r2).sum(), ((1 - a1 - a2) * r3).sum()]) * V
dp = du = 0.0
for t in ("0.001", "0.002"):
    dp = max(dp, np.abs(read_field(c3, t, "p", n) / p0 - 1).max())
    du = max(du, np.abs(read_field(c3, t, "U", n)[:, 0] / u0 - 1).max())
rho = read_field(c3, "0.002", "rho", n)
ar1 = read_field(c3, "0.002", "alphaRho.products", n)
ar2 = read_field(c3, "0.002", "alphaRho.water", n)
m1 = np.array([ar1.sum(), ar2.sum(), (rho - ar1 - ar2).sum()]) * V
dm = np.abs(m1 / m0 - 1)
ap = read_field(c3, "0.002", "alpha.products", n)
aw = read_field(c3, "0.002", "alpha.water", n)
x3 = (np.arange(n) + 0.5) / n

# Restart (tntWaterRestart from 30 us): field files at 60 us that differ
import filecmp
d1, d2 = os.path.join(here, "tntWater", "6e-05"), os.path.join(here, "tntWaterRestart", "6e-05")
restartFiles = sorted(f for f in os.listdir(d1) if os.path.isfile(os.path.join(d1, f)))
restartDiffer = sum(not filecmp.cmp(os.path.join(d1, f), os.path.join(d2, f), shallow=False)
                    for f in restartFiles)

# Water expansion with the cavitation cut-off (waterExpansion): two streams
# of water at rho0, p0 moving apart at u0 from x = xm = 1 m (2000 cells on
# [0, 2] m). Exact solution of
# the Euler equations with p = max(p_EOS, p_cav), stiffened gas: each
# rarefaction follows the isentrope (p + pInf)/rho^gamma = const and the
# Riemann invariant u -+ 2c/(gamma - 1) down to p_cav, where the sound
# speed of the cut-off equation of state falls to zero; the state at p_cav
# (rho_cav, -+u_c) is a plateau from the fan's tail (x/t = -+(u_c + c_cav))
# to the cavity's edges x/t = -+u_c, and the cavity between them is empty
# (p uniform: the water moves ballistically). Without the cut-off the
# rarefactions would meet at u = 0, p* < 0 (tension).
gw, pInfW = 4.4, 6e8
rho0, p0, u0, pCav = 1000.0, 1e5, 1.0, 2300.0
we = os.path.join(here, "waterExpansion")
tW = latest_time(we)
T = float(tW)
nW, LW, xm = 2000, 2.0, 1.0
hW = LW / nW
xW = (np.arange(nW) + 0.5) * hW
c0 = np.sqrt(gw * (p0 + pInfW) / rho0)
ratio = (pCav + pInfW) / (p0 + pInfW)
cCav = c0 * ratio ** ((gw - 1) / (2 * gw))
rhoCav = rho0 * ratio ** (1 / gw)
uC = u0 - 2 * (c0 - cCav) / (gw - 1)          # |u| of the plateau
cStar = c0 - (gw - 1) * u0 / 2                # no cut-off: u* = 0
pStarNoCut = (p0 + pInfW) * (cStar / c0) ** (2 * gw / (gw - 1)) - pInfW
head, tail = (u0 + c0) * T, (uC + cCav) * T  # distances from xm


def expansion_exact(x):
    """rho, u, p of the exact cut-off solution at time T"""
    d = np.abs(x - xm)
    sgn = np.sign(x - xm)
    xi = d / T
    # in the fan (x > xm; the left one mirrored): xi = u + c and
    # u - 2c/(gamma - 1) = u0 - 2 c0/(gamma - 1)
    c = np.where(d >= head, c0, np.where(d > tail, (gw - 1) / (gw + 1) * (xi + 2 * c0 / (gw - 1) - u0), cCav))
    u = np.where(d >= head, u0, np.where(d > tail, xi - c, uC))
    pr = (c / c0) ** (2 * gw / (gw - 1)) * (p0 + pInfW) - pInfW
    rho = rho0 * ((pr + pInfW) / (p0 + pInfW)) ** (1 / gw)
    cav = d < uC * T
    rho = np.where(cav, 0.0, rho)
    pr = np.where(cav, pCav, pr)
    u = np.where(cav, xi, u)
    return rho, sgn * u, pr


exW = expansion_exact(xW)
pW = read_field(we, tW, "p", nW)
uW = read_field(we, tW, "U", nW)[:, 0]
rW = read_field(we, tW, "rho", nW)
# The plateaus: 20 cells inside the fan's tail to 20 cells outside the
# cavity (its numerical smear), on both sides
dW = np.abs(xW - xm)
plateau = (dW < tail - 20 * hW) & (dW > uC * T + 20 * hW)
pPlat = np.abs(pW[plateau] - pCav).max() / (p0 - pCav)
uPlat = np.abs(np.abs(uW[plateau]) - uC).max() / (u0 - uC)
rPlat = np.abs(rW[plateau] / rhoCav - 1).max()
# The cavity's volume (per unit area): what the water between the fans'
# tails lacks against the plateau density; exact 2 u_c T
inner = dW < tail - 20 * hW
cavity = ((1 - rW[inner] / rhoCav) * hW).sum()
cutCells = int((pW == pCav).sum())
# The rarefactions' position: where p crosses (p0 + p_cav)/2 nearest the
# middle outside the cavity, each side (the front, 0.02 mm wide in the
# exact solution, is smeared over ~25 cells; the wall shocks are beyond
# 1.6 MPa)
pMid = 0.5 * (p0 + pCav)
frontEx = 0.5 * (head + tail)
outer = dW > uC * T + 20 * hW
xFrontL = crossing(xW[outer & (xW < xm)], pW[outer & (xW < xm)], pMid, last=True)
xFrontR = crossing(xW[outer & (xW > xm)], pW[outer & (xW > xm)], pMid, last=False)
frontErr = max(abs(xm - xFrontL - frontEx), abs(xFrontR - xm - frontEx)) / LW
# Mass and energy over the run (walls: no flux), from the log
logW = log_table(os.path.join(we, "log.jwlIbFoam"))
dMassW = abs(logW[-1, 3] / logW[0, 3] - 1)
dEnergyW = abs(logW[-1, 4] / logW[0, 4] - 1)
# Restart at 100 us (waterExpansionRestart): field files at 200 us that differ
dW1, dW2 = os.path.join(we, tW), os.path.join(here, "waterExpansionRestart", tW)
restartFilesW = sorted(f for f in os.listdir(dW1) if os.path.isfile(os.path.join(dW1, f)))
restartDifferW = sum(not filecmp.cmp(os.path.join(dW1, f), os.path.join(dW2, f), shallow=False)
                     for f in restartFilesW)
pRestart = read_field(we, "0.0001", "p", nW)
cutAtRestart = int((pRestart == pCav).sum())
# Without the cut-off: the run must stop at the first tension
noCutLog = open(os.path.join(here, "waterExpansionNoCutOff", "log.jwlIbFoam")).read()
noCutStopped = "non-physical state at time" in noCutLog

fig, ax = plt.subplots(3, 3, figsize=(15, 12))
for row, r, title in ((0, wa, "water 1 GPa | air 1 bar"),
                      (1, tw, "TNT products | water")):
    for a, col, key, lab, log in ((ax[row, 0], 1, "rho", "rho [kg/m3]", False),
                                  (ax[row, 1], 2, "u", "u [m/s]", False),
                                  (ax[row, 2], 3, "p", "p [Pa]", True)):
        a.plot(r["x"], r["ex"][:, col], "k-", lw=1, label="exact")
        a.plot(r["x"], r[key], "r-", lw=0.8, label="jwlIbFoam")
        if log:
            a.set_yscale("log")
        a.set_title(f"{title}: {lab}, t = {r['t']:.3g} s")
        a.set_xlabel("x [m]")
ax[0, 1].legend()
for a, ex, sim, lab in ((ax[2, 0], exW[0], rW, "rho [kg/m3]"), (ax[2, 1], exW[1], uW, "u [m/s]"),
                        (ax[2, 2], exW[2], pW, "p [Pa]")):
    # the exact solution of the expansion alone: not where the walls'
    # reflected shocks have reached
    nearWall = np.minimum(xW, LW - xW) < (c0 - u0) * T + 0.02
    a.plot(xW, np.where(nearWall, np.nan, ex), "k-", lw=1, label="exact (cut-off)")
    a.plot(xW, sim, "r-", lw=0.8, label="jwlIbFoam")
    a.set_title(f"water expansion, cut-off {pCav:g} Pa: {lab}, t = {T:.3g} s")
    a.set_xlabel("x [m]")
ax[2, 0].set_ylim(rhoCav - 0.1, rho0 + 0.05)
fig.tight_layout()
fig.savefig(os.path.join(here, "waterShockTubes.png"), dpi=100)

# Tolerances: about 1.5-2 x the measured figures on these meshes (1000
# cells; a wrong wave speed or equation of state, a few %, fails); the
# pressures behind the shocks 2 % (the brief's figure)
# waterExpansion: about 3-4 x the measured figures (2000 cells). The
# plateau pressure to 1e-3 of p0 - p_cav catches a cut-off ~100 Pa off, its
# density to 1e-7 one ~260 Pa off (d rho/rho = dp/(gamma (p + pInf))), the
# cavity volume (2 u_c T) to 2e-3 a plateau velocity 2 mm/s off; the front
# position to 2.5e-3 L (5 cells; a sound speed 1.5 % off fails); mass and
# energy to round-off (walls)
TOL_P, TOL_U, TOL_R, TOL_CAV, TOL_X = 1e-3, 1e-3, 1e-7, 2e-3, 2.5e-3
write_summary(os.path.join(here, "summary.json"), "waterShockTubes", [
    figure("water/air: L1(rho)/max rho", wa["L1rho"], 0, 3e-3, error=wa["L1rho"]),
    figure("water/air: L1(u)/max u", wa["L1u"], 0, 5e-3, error=wa["L1u"]),
    figure("water/air: L1(p)/max p", wa["L1p"], 0, 1.2e-3, error=wa["L1p"]),
    figure("water/air: shock position / L", wa["xs"] / L, wa["xsEx"] / L, 3e-3),
    figure("water/air: contact position / L", wa["xc"] / L, wa["xcEx"] / L, 1e-3),
    figure("water/air: rarefaction head / L", wa["xh"] / L, wa["xhEx"] / L, 3e-3),
    figure("water/air: pressure behind the shock [Pa]", wa["pBehind"],
           wa["info"]["(p*"], 0.02, relative=True),
    figure("TNT/water: transmitted shock pressure [Pa]", tw["pBehind"],
           tw["info"]["(p*"], 0.02, relative=True),
    figure("TNT/water: L1(rho)/max rho", tw["L1rho"], 0, 2e-3, error=tw["L1rho"]),
    figure("TNT/water: L1(u)/max u", tw["L1u"], 0, 4e-3, error=tw["L1u"]),
    figure("TNT/water: L1(p)/max p", tw["L1p"], 0, 2e-3, error=tw["L1p"]),
    figure("TNT/water: shock position / L", tw["xs"] / L, tw["xsEx"] / L, 2e-3),
    figure("TNT/water: contact position / L", tw["xc"] / L, tw["xcEx"] / L, 1e-3),
    figure(f"TNT/water restart at 30 us: field files of {len(restartFiles)} at 60 us that"
           " differ from the run through", restartDiffer, 0, 0),
    figure("contact3: max |p/p0 - 1|", dp, 0, 1e-9, error=dp),
    figure("contact3: max |u/u0 - 1|", du, 0, 1e-9, error=du),
    figure("contact3: products mass drift", dm[0], 0, 1e-12, error=dm[0]),
    figure("contact3: water mass drift", dm[1], 0, 1e-12, error=dm[1]),
    figure("contact3: air mass drift", dm[2], 0, 1e-12, error=dm[2]),
    figure("contact3: alpha.products + alpha.water max", (ap + aw).max(), 1, 0,
           error=max(0.0, (ap + aw).max() - 1)),
    figure("contact3: slab centre (products) after one period [m]",
           (x3 * ap).sum() / ap.sum(), 0.2, 0.01),
    figure("waterExpansion: no cut-off, exact p* [Pa] (tension)", pStarNoCut),
    figure("waterExpansion: plateau max |p - p_cav|/(p0 - p_cav)", pPlat, 0, TOL_P, error=pPlat),
    figure("waterExpansion: plateau max ||u| - u_c|/(u0 - u_c)", uPlat, 0, TOL_U, error=uPlat),
    figure("waterExpansion: plateau max |rho/rho_cav - 1|", rPlat, 0, TOL_R, error=rPlat),
    figure("waterExpansion: exact u_c [m/s]", uC),
    figure("waterExpansion: cavity volume per area [m]", cavity, 2 * uC * T, TOL_CAV, relative=True),
    figure("waterExpansion: cells at p_cav", cutCells),
    figure("waterExpansion: rarefaction position error / L", frontErr, 0, TOL_X, error=frontErr),
    figure(f"waterExpansion restart at 100 us ({cutAtRestart} cells at p_cav): field files of"
           f" {len(restartFilesW)} at 200 us that differ from the run through", restartDifferW, 0, 0),
    figure("waterExpansion: mass drift", dMassW, 0, 1e-13, error=dMassW),
    figure("waterExpansion: energy drift", dEnergyW, 0, 1e-13, error=dEnergyW),
    figure("waterExpansion without the cut-off stops at the first tension",
           float(noCutStopped), 1, 0),
])
