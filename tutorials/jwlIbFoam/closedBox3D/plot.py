#!/usr/bin/python3
"""Closed 3D box: conservation over 200 steps, cubic symmetry, positivity."""
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
from blastPost import log_table, read_field, write_summary, figure, latest_time

here = os.path.dirname(os.path.abspath(__file__))
log = os.path.join(here, "log.jwlIbFoam")
m = re.search(r"Initial total mass (\S+) total energy (\S+)", open(log).read())
mass0, energy0 = float(m.group(1)), float(m.group(2))
tab = log_table(log)
dm = np.abs(tab[:, 3] / mass0 - 1).max()
de = np.abs(tab[:, 4] / energy0 - 1).max()

n = 24
t = latest_time(here)
p = read_field(here, t, "p", n ** 3).reshape(n, n, n)      # [z, y, x]
sym = max(np.abs(p - p[::-1]).max(), np.abs(p - p[:, ::-1]).max(),
          np.abs(p - p[:, :, ::-1]).max(), np.abs(p - p.transpose(1, 0, 2)).max(),
          np.abs(p - p.transpose(2, 1, 0)).max()) / p.max()

fig, ax = plt.subplots(1, 1, figsize=(5.5, 4.5))
im = ax.imshow(np.log10(p[n // 2]), origin="lower", extent=(0, 0.5, 0, 0.5))
fig.colorbar(im, ax=ax, label="log10 p [Pa]")
ax.set_title(f"closed 3D box, mid-plane, t = {t} s")
fig.tight_layout()
fig.savefig(os.path.join(here, "box3D.png"), dpi=110)

write_summary(os.path.join(here, "summary.json"), "closedBox3D", [
    figure("steps", len(tab), 200, 0),
    figure("max relative mass drift", dm, 0, 1e-10, error=dm),
    figure("max relative energy drift", de, 0, 1e-10, error=de),
    figure("cubic symmetry of p, relative", sym, 0, 1e-8, error=sym),
    figure("min density over all steps [kg/m3] (> 0)", tab[:, 5].min(), 0, 0,
           error=0, passed=bool(tab[:, 5].min() > 0)),
    figure("min pressure over all steps [Pa] (> 0)", tab[:, 6].min(), 0, 0,
           error=0, passed=bool(tab[:, 6].min() > 0)),
])
