#!/usr/bin/python3
"""TNT products / air shock tube: contact pressure and velocity and shock
position against the exact solution; Q-scheme on versus off (oscillation
measure and shock shift). Writes tntAir.png and summary.json."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import read_field, read_exact, write_summary, figure, latest_time

here = os.path.dirname(os.path.abspath(__file__))
L = 1.0                      # domain length
pAir = 101325.0


def analyse(name):
    case = os.path.join(here, name)
    t = latest_time(case)
    ex, info = read_exact(case, t)
    n = len(ex)
    x = ex[:, 0]
    p = read_field(case, t, "p", n)
    u = read_field(case, t, "U", n)[:, 0]
    a = read_field(case, t, "alpha.products", n)
    rho = read_field(case, t, "rho", n)
    # contact: where alpha.products crosses 1/2 (linear interpolation)
    i = np.where(a > 0.5)[0].max()
    w = (a[i] - 0.5) / (a[i] - a[i + 1])
    pc = p[i] + w * (p[i + 1] - p[i])
    uc = u[i] + w * (u[i + 1] - u[i])
    # shock: last crossing of (p* + p_air)/2
    pm = 0.5 * (info["(p*"] + pAir)
    j = np.where(p > pm)[0].max()
    xs = x[j] + (x[j + 1] - x[j]) * (p[j] - pm) / (p[j] - p[j + 1])
    # oscillation measure: total variation of u in excess of the exact one
    tv = np.abs(np.diff(u)).sum()
    tvEx = np.abs(np.diff(ex[:, 2])).sum()
    osc = (tv - tvEx) / tvEx
    over = max(0.0, u.max() / info["u*"] - 1)
    return dict(x=x, p=p, u=u, rho=rho, ex=ex, info=info, pc=pc, uc=uc,
                xs=xs, osc=osc, over=over, t=float(t))


off = analyse("QOff")
on = analyse("QOn")
info = off["info"]

fig, ax = plt.subplots(1, 3, figsize=(14, 4))
for a, col, key, lab, log in ((ax[0], 1, "rho", "rho [kg/m3]", True),
                              (ax[1], 2, "u", "u [m/s]", False),
                              (ax[2], 3, "p", "p [Pa]", True)):
    a.plot(off["x"], off["ex"][:, col], "k-", lw=1, label="exact")
    a.plot(off["x"], off[key], "r-", lw=0.8, label="Q-scheme off")
    a.plot(on["x"], on[key], "b--", lw=0.8, label="Q-scheme on")
    if log:
        a.set_yscale("log")
    a.set_xlabel("x [m]"); a.set_title(lab)
ax[1].legend()
fig.suptitle(f"TNT (CV explosion state) / air at t = {off['t']:.1e} s, "
             f"2000 cells: p* {info['(p*']:.4g} Pa, u* {info['u*']:.5g} m/s")
fig.tight_layout()
fig.savefig(os.path.join(here, "tntAir.png"), dpi=110)

write_summary(os.path.join(here, "summary.json"), "tntAirShockTube", [
    figure("contact pressure [Pa]", off["pc"], info["(p*"], 0.02, relative=True),
    figure("contact velocity [m/s]", off["uc"], info["u*"], 0.02, relative=True),
    figure("shock position / L", off["xs"] / L, info["rightFront"] / L, 0.01),
    figure("oscillation TV(u) excess, Q off", off["osc"]),
    figure("oscillation TV(u) excess, Q on", on["osc"]),
    figure("u overshoot above u*, Q off", off["over"]),
    figure("u overshoot above u*, Q on", on["over"]),
    figure("shock shift Q on - off / L", (on["xs"] - off["xs"]) / L, 0, 0.01),
    figure("contact pressure, Q on [Pa]", on["pc"], info["(p*"], 0.02,
           relative=True),
])
