#!/usr/bin/python3
"""2D TNT charge: positivity, symmetry (x -> -x, y -> -y, x <-> y) to 1e-8,
and, when present, the 2-processor run against the serial one."""
import os
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
n = 80
t = latest_time(here)
p = read_field(here, t, "p", n * n).reshape(n, n)        # [j, i] = [y, x]
rho = read_field(here, t, "rho", n * n).reshape(n, n)
U = read_field(here, t, "U", n * n).reshape(n, n, 3)

# Minimum density and pressure over every step's written time and the log
tab = log_table(os.path.join(here, "log.jwlIbFoam"))
pmax = p.max()
sym_x = np.abs(p - p[:, ::-1]).max() / pmax
sym_y = np.abs(p - p[::-1, :]).max() / pmax
sym_d = np.abs(p - p.T).max() / pmax
symU = max(np.abs(U[:, :, 0] + U[:, ::-1, 0]).max(),
           np.abs(U[:, :, 0] - U[:, :, 1].T).max()) / np.abs(U).max()
sym = max(sym_x, sym_y, sym_d)

figs = [
    figure("min density over all steps [kg/m3] (> 0)", tab[:, 5].min(), 0, 0,
           error=max(0, -tab[:, 5].min()), passed=bool(tab[:, 5].min() > 0)),
    figure("min pressure over all steps [Pa] (> 0)", tab[:, 6].min(), 0, 0,
           error=max(0, -tab[:, 6].min()), passed=bool(tab[:, 6].min() > 0)),
    figure("symmetry of p (x, y, diagonal), relative", sym, 0, 1e-8, error=sym),
    figure("symmetry of U, relative", symU, 0, 1e-8, error=symU),
    figure("steps", len(tab)),
    figure("max p at end [Pa]", pmax),
]

par = os.path.join(here, "parallel")
if os.path.isdir(par):
    pp = read_field(par, t, "p", n * n).reshape(n, n)
    Up = read_field(par, t, "U", n * n).reshape(n, n, 3)
    dpar = max(np.abs(pp - p).max() / pmax, np.abs(Up - U).max() / np.abs(U).max())
    figs.append(figure("parallel (2 proc) vs serial, relative", dpar, 0, 1e-10,
                       error=dpar))

x = (np.arange(n) + 0.5) / n - 0.5
fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
im = ax[0].imshow(np.log10(p), origin="lower", extent=(-0.5, 0.5, -0.5, 0.5))
fig.colorbar(im, ax=ax[0], label="log10 p [Pa]")
ax[0].set_title(f"TNT charge r = 5 cm, t = {t} s")
ax[1].semilogy(x, p[n // 2, :], "r.-", ms=3, label="y = +dy/2")
ax[1].semilogy(x, p[:, n // 2], "b--", label="x = +dx/2 (transposed)")
ax[1].set_xlabel("x [m]"); ax[1].set_ylabel("p [Pa]"); ax[1].legend()
fig.tight_layout()
fig.savefig(os.path.join(here, "tntCharge2D.png"), dpi=110)

write_summary(os.path.join(here, "summary.json"), "tntCharge2D", figs)
