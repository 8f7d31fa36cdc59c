#!/usr/bin/python3
"""Closed box: relative drift of total mass and energy over 1000 steps
(tolerance 1e-10). Writes closedBox.png and summary.json."""
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
steps = len(tab)
dm = np.abs(tab[:, 3] / mass0 - 1)
de = np.abs(tab[:, 4] / energy0 - 1)

n = 50
t = latest_time(here)
p = read_field(here, t, "p", n * n).reshape(n, n)

fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
ax[0].semilogy(np.arange(1, steps + 1), np.maximum(dm, 1e-17), label="mass")
ax[0].semilogy(np.arange(1, steps + 1), np.maximum(de, 1e-17), label="energy")
ax[0].axhline(1e-10, color="k", ls="--", label="tolerance")
ax[0].set_xlabel("step"); ax[0].set_ylabel("relative drift"); ax[0].legend()
im = ax[1].imshow(p, origin="lower", extent=(0, 0.5, 0, 0.5))
fig.colorbar(im, ax=ax[1], label="p [Pa]")
ax[1].set_title(f"p at t = {t} s")
fig.tight_layout()
fig.savefig(os.path.join(here, "closedBox.png"), dpi=110)

# Bitwise restart: the conservative state and p after the restart
restart = os.path.join(here, "restart")
nDiff = 0
for name in ("rho", "rhoU", "rhoE", "alpha.products", "alphaRho.products", "p"):
    a = open(os.path.join(here, t, name)).read().split("internalField")[1]
    b = open(os.path.join(restart, t, name)).read().split("internalField")[1]
    a = a.split("boundaryField")[0]
    b = b.split("boundaryField")[0]
    nDiff += sum(x != y for x, y in zip(a.split(), b.split())) + abs(
        len(a.split()) - len(b.split()))

write_summary(os.path.join(here, "summary.json"), "closedBox", [
    figure("restart from step 500: differing values at step 1000", nDiff, 0, 0),
    figure("steps", steps, 1000, 0),
    figure("max relative mass drift", dm.max(), 0, 1e-10, error=dm.max()),
    figure("max relative energy drift", de.max(), 0, 1e-10, error=de.max()),
    figure("max pressure at end [Pa]", tab[-1, 2]),
])
