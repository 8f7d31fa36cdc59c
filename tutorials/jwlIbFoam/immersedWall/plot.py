"""Immersed wall: reflected-shock pressure and position against the
Rankine-Hugoniot solution; writes summary.json and immersedWall.png."""
import os
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

gamma, p1, rho1, mach, x0 = 1.4, 1e5, 1.2, 2.0, 0.4
ny, dx = 4, 0.0025


def reflected_state():
    """Incident Mach 2 shock into air at rest, reflected by a wall."""
    c1 = np.sqrt(gamma * p1 / rho1)
    W = mach * c1
    p2 = p1 * (1 + 2 * gamma / (gamma + 1) * (mach**2 - 1))
    rho2 = rho1 * (gamma + 1) * mach**2 / ((gamma - 1) * mach**2 + 2)
    u2 = W * (1 - rho1 / rho2)
    r = p2 / p1
    p5 = p2 * ((3 * gamma - 1) * r - (gamma - 1)) / ((gamma - 1) * r + gamma + 1)
    pi = p5 / p2
    rho5 = rho2 * ((gamma + 1) * pi + gamma - 1) / ((gamma - 1) * pi + gamma + 1)
    Wr = rho2 * u2 / (rho5 - rho2)  # gas at rest behind the reflected shock
    return W, p2, p5, Wr


def column_pressure(case):
    t = bp.latest_time(case)
    p = bp.read_field(case, t, "p")
    nx = p.size // ny
    px = p.reshape(ny, nx).mean(axis=0)
    x = (np.arange(nx) + 0.5) * bp_dx(case, nx)
    return float(t), x, px


def bp_dx(case, nx):
    for line in open(os.path.join(case, "system", "blockMeshDict")):
        if line.startswith("xMax"):
            return float(line.split()[1].rstrip(";")) / nx
    raise RuntimeError("xMax not found")


W, p2, p5, Wr = reflected_state()
cases = [("immersedOnFace", 0.7), ("immersedInCell", 0.701),
         ("bodyFitted", 0.701)]
figures = []
fig, ax = plt.subplots(figsize=(8, 4.5))
for name, xw in cases:
    t, x, px = column_pressure(name)
    fluid = x < xw
    x, px = x[fluid], px[fluid]
    xs = xw - Wr * (t - (xw - x0) / W)          # exact reflected shock
    plateau = (x > xs + 0.02) & (x < xw - 3 * dx)
    p_plateau = px[plateau].mean()
    # shock position: where p crosses the mean of p2 and p5
    i = np.where(px > 0.5 * (p2 + p5))[0][0]
    x_num = x[i - 1] + (0.5 * (p2 + p5) - px[i - 1]) / (px[i] - px[i - 1]) * dx
    err_p = abs(p_plateau - p5) / p5
    err_x = abs(x_num - xs) / (xw - xs)
    figures.append(bp.figure(f"{name}: reflected-shock pressure [Pa]",
                             p_plateau, p5, 0.05, err_p))
    figures.append(bp.figure(f"{name}: reflected-shock position [m]",
                             x_num, xs, 0.02, err_x))
    ax.plot(x, px / 1e6, label=f"{name} (wall x = {xw})")
ax.axhline(p5 / 1e6, color="k", ls="--", lw=0.8, label="Rankine-Hugoniot p5")
ax.set_xlim(0.45, 0.72)
ax.set_xlabel("x [m]")
ax.set_ylabel("p [MPa]")
ax.set_title(f"Mach 2 shock reflected by a wall, t = {t:.2e} s")
ax.legend()
fig.tight_layout()
fig.savefig("immersedWall.png", dpi=120)
bp.write_summary("summary.json", "immersedWall", figures)
