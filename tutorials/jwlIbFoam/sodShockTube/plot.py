#!/usr/bin/python3
"""Sod shock tube: L1 density error against the exact solution for 100, 200,
400 cells, observed convergence rate, plot sod.png and summary.json."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import read_field, read_exact, write_summary, figure

here = os.path.dirname(os.path.abspath(__file__))
L1 = {}
profiles = {}
for n in (100, 200, 400):
    case = os.path.join(here, f"mesh{n}")
    rho = read_field(case, 0.2, "rho", n)
    ex, _ = read_exact(case, 0.2)
    L1[n] = np.mean(np.abs(rho - ex[:, 1]))     # domain length 1
    profiles[n] = (ex, rho, read_field(case, 0.2, "U", n)[:, 0],
                   read_field(case, 0.2, "p", n))

# Outlet: after the shock left (t = 0.35), the pressure near the right
# boundary must still be p* (no reflected wave), relative to p*
case = os.path.join(here, "mesh400")
ex35, info35 = read_exact(case, 0.35)
p35 = read_field(case, 0.35, "p", 400)
right = ex35[:, 0] > 0.85
reflect = np.abs(p35[right] - ex35[right, 3]).max() / info35["(p*"]

rate1 = np.log2(L1[100] / L1[200])
rate2 = np.log2(L1[200] / L1[400])
rate = np.log(L1[100] / L1[400]) / np.log(4)

fig, ax = plt.subplots(1, 3, figsize=(13, 4))
ex, rho, u, p = profiles[400]
for a, col, num, lab in zip(ax, (1, 2, 3), (rho, u, p), ("rho", "u", "p")):
    a.plot(ex[:, 0], ex[:, col], "k-", lw=1, label="exact")
    a.plot(ex[:, 0], num, "r.", ms=2, label="jwlIbFoam 400 cells")
    a.set_xlabel("x"); a.set_title(lab)
ax[0].legend()
fig.suptitle(f"Sod shock tube t = 0.2, HLLC + vanLeer + SSP-RK2: L1(rho) = "
             f"{L1[400]:.2e} (400 cells), rate {rate:.2f}")
fig.tight_layout()
fig.savefig(os.path.join(here, "sod.png"), dpi=110)

write_summary(os.path.join(here, "summary.json"), "sodShockTube", [
    figure("L1(rho) 100 cells", L1[100]),
    figure("L1(rho) 200 cells", L1[200]),
    figure("L1(rho) 400 cells", L1[400], reference=0, tolerance=5e-3,
           error=L1[400]),
    figure("observed rate 100->200", rate1, tolerance=None),
    figure("observed rate 200->400", rate2, tolerance=None),
    figure("observed rate 100->400 (>= 0.6)", rate, reference=0.6,
           error=max(0.0, 0.6 - rate), tolerance=0.0),
    figure("outlet reflection: max |p - p_exact|/p*, x > 0.85, t = 0.35",
           reflect, 0, 0.05, error=reflect),
    figure("L1 decreasing", float(L1[100] > L1[200] > L1[400]),
           passed=bool(L1[100] > L1[200] > L1[400])),
])
