#!/usr/bin/python3
"""Interface advection: p and u must stay uniform (1e-3 relative) after the
products / air interface crossed 50 cells. Writes interface.png, summary.json."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import read_field, write_summary, figure, latest_time

here = os.path.dirname(os.path.abspath(__file__))
n, p0, u0, L = 100, 1e5, 500.0, 1.0
t = latest_time(here)
x = (np.arange(n) + 0.5) / n
p = read_field(here, t, "p", n)
u = read_field(here, t, "U", n)[:, 0]
rho = read_field(here, t, "rho", n)
a = read_field(here, t, "alpha.products", n)
a0 = read_field(here, "0", "alpha.products", n)
rho0 = read_field(here, "0", "rho", n) if os.path.exists(
    os.path.join(here, "0", "rho")) else None
cells = u0 * float(t) / (L / n)
dp = np.abs(p / p0 - 1).max()
du = np.abs(u / u0 - 1).max()
ratio = rho.max() / rho.min()

fig, ax = plt.subplots(1, 3, figsize=(13, 4))
ax[0].semilogy(x, rho, "r.-", ms=3); ax[0].set_title("rho [kg/m3]")
ax[1].plot(x, p / p0 - 1, "b.-", ms=3); ax[1].set_title("p/p0 - 1")
ax[2].plot(x, u / u0 - 1, "g.-", ms=3); ax[2].set_title("u/u0 - 1")
for axi in ax:
    axi.set_xlabel("x [m]")
fig.suptitle(f"Products/air interface after {cells:.0f} cells: "
             f"max |p/p0-1| = {dp:.2e}, max |u/u0-1| = {du:.2e}")
fig.tight_layout()
fig.savefig(os.path.join(here, "interface.png"), dpi=110)

# Periodic variant: after one period the slab is back; p, u uniform, alpha
# profile as at the start of the run, mass conserved exactly
per = os.path.join(here, "periodic")
tp = latest_time(per)
pp = read_field(per, tp, "p", n)
up = read_field(per, tp, "U", n)[:, 0]
ap = read_field(per, tp, "alpha.products", n)
dpp = max(np.abs(pp / p0 - 1).max(), np.abs(up / u0 - 1).max())
masses = [float(l.split()[8]) for l in open(os.path.join(per, "log.jwlIbFoam"))
          if l.startswith("Time =")]
dmass = abs(masses[-1] / masses[0] - 1)
centre = (x * ap).sum() / ap.sum()

write_summary(os.path.join(here, "summary.json"), "interfaceAdvection", [
    figure("periodic: max |p/p0 - 1|, |u/u0 - 1| after one period", dpp, 0,
           1e-3, error=dpp),
    figure("periodic: slab centre after one period [m]", centre, 0.8, 0.01),
    figure("periodic: relative mass drift", dmass, 0, 1e-12, error=dmass),
    figure("density ratio (> 100)", ratio, 100, 0, error=max(0, 100 - ratio)),
    figure("cells crossed (>= 50)", cells, 50, 0, error=max(0, 50 - cells)),
    figure("max |p/p0 - 1|", dp, 0, 1e-3, error=dp),
    figure("max |u/u0 - 1|", du, 0, 1e-3, error=du),
    figure("alpha.products range min", a.min(), 0, 0, error=max(0, -a.min())),
    figure("alpha.products range max", a.max(), 1, 0, error=max(0, a.max() - 1)),
])
