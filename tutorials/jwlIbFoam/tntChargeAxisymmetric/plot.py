#!/usr/bin/python3
"""Axisymmetric TNT charge on a wedge: conservation, x-mirror symmetry,
positivity; air at rest stays at rest."""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "JWLIBFOAM_TUTORIALS", os.path.join(os.path.dirname(__file__), "..", "..")),
    "jwlIbFoam", "common"))
from blastPost import read_field, write_summary, figure, latest_time, log_table

here = os.path.dirname(os.path.abspath(__file__))
nx, nr = 80, 40
log = os.path.join(here, "log.jwlIbFoam")
text = open(log).read()
m = re.search(r"Initial total mass (\S+) total energy (\S+)", text)
mass0, energy0 = float(m.group(1)), float(m.group(2))
tab = log_table(log)
dm = np.abs(tab[:, 3] / mass0 - 1).max()
de = np.abs(tab[:, 4] / energy0 - 1).max()
retries = len(re.findall("needed first-order", text))

t = latest_time(here)
p = read_field(here, t, "p", nx * nr).reshape(nr, nx)
rho = read_field(here, t, "rho", nx * nr).reshape(nr, nx)
U = read_field(here, t, "U", nx * nr).reshape(nr, nx, 3)
sym = max(np.abs(p - p[:, ::-1]).max() / p.max(),
          np.abs(U[:, :, 0] + U[:, ::-1, 0]).max() / np.abs(U).max())

rest = os.path.join(here, "atRest")
Ur = read_field(rest, latest_time(rest), "U", nx * nr)
pr = read_field(rest, latest_time(rest), "p", nx * nr)
umax = np.abs(Ur).max()
prel = np.abs(pr / 101325 - 1).max()

fig, ax = plt.subplots(1, 1, figsize=(8, 4.5))
im = ax.imshow(np.log10(p), origin="lower", extent=(-0.5, 0.5, 0, 0.5))
fig.colorbar(im, ax=ax, label="log10 p [Pa]")
ax.set_xlabel("x (axis) [m]"); ax.set_ylabel("r [m]")
ax.set_title(f"TNT sphere r = 5 cm, wedge, t = {t} s")
fig.tight_layout()
fig.savefig(os.path.join(here, "axi.png"), dpi=110)

write_summary(os.path.join(here, "summary.json"), "tntChargeAxisymmetric", [
    figure("max relative mass drift", dm, 0, 1e-10, error=dm),
    figure("max relative energy drift", de, 0, 1e-10, error=de),
    figure("mirror symmetry x -> -x, relative", sym, 0, 1e-8, error=sym),
    figure("min density over all steps [kg/m3] (> 0)", tab[:, 5].min(), 0, 0,
           error=max(0, -tab[:, 5].min()), passed=bool(tab[:, 5].min() > 0)),
    figure("min pressure over all steps [Pa] (> 0)", tab[:, 6].min(), 0, 0,
           error=max(0, -tab[:, 6].min()), passed=bool(tab[:, 6].min() > 0)),
    figure("steps redone at first order", retries),
    figure("at rest: max |U| [m/s] after 100 steps", umax, 0, 1e-8, error=umax),
    figure("at rest: max |p/p0 - 1|", prel, 0, 1e-12, error=prel),
])
