"""Projectile fire (gas gun): the projectile velocity of the ideal-gas gun
against the exact simple-wave solution, and the TNT gun's muzzle velocity,
velocity versus travel and breech pressure; the momentum budget of the
closed barrel. Writes summary.json and projectileFire_*.png.

Exact solution (ideal gas, gas at rest p0, rho0 in a chamber of length L
behind the projectile, mass m per unit area): until the rarefaction
reflected by the breech reaches the projectile the gas behind it is a
simple wave, u + 2c/(gamma - 1) = 2 c0/(gamma - 1), so
    m dv/dt = p0 (1 - (gamma - 1) v/(2 c0))^(2 gamma/(gamma - 1)).
The C- characteristics leaving the projectile at time tau are straight,
x = L + X(tau) + ((gamma + 1) v(tau)/2 - c0)(t - tau); the head of the
reflected wave is the C+ characteristic dx/dt = u + c = c0 + (3 - gamma) u/2
from (x = 0, t = L/c0) through that fan; the comparison ends where it meets
the projectile.
"""
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

# Set-up (system/setFieldsDict, system/femdemMeshDict, femdemProperties)
gamma, p0, rho0 = 1.4, 20e6, 160.0
L_air = 0.8                         # ideal-gas chamber length [m]
L_tnt = 0.1                         # TNT chamber length [m]
rho_s, Lp, H = 7850.0, 0.02, 0.01   # steel, projectile length, barrel height
m = rho_s * Lp                      # projectile mass per unit area [kg/m2]
travel_muzzle = 1.0                 # TNT gun: travel at the muzzle [m]
rho_tnt, sqrt2E_tnt = 1630.0, 2400.0  # Gurney velocity of TNT (model.md)


def piston(t_end, n=20000):
    """RK4 of the simple-wave projectile: times, travel X, velocity v."""
    c0 = np.sqrt(gamma * p0 / rho0)
    k = 2 * gamma / (gamma - 1)

    def rhs(s):
        return np.array([s[1], p0 / m * (1 - 0.5 * (gamma - 1) * s[1] / c0)**k])

    h = t_end / n
    s = np.zeros(2)
    out = np.zeros((n + 1, 3))
    for i in range(n):
        k1 = rhs(s)
        k2 = rhs(s + 0.5 * h * k1)
        k3 = rhs(s + 0.5 * h * k2)
        k4 = rhs(s + h * k3)
        s = s + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out[i + 1] = ((i + 1) * h, s[0], s[1])
    return out[:, 0], out[:, 1], out[:, 2]


def reflection_time(T, X, V, L, nSteps=4000):
    """Time at which the head of the wave reflected by the breech meets the
    projectile (midpoint-rule march along the C+ characteristic)."""
    c0 = np.sqrt(gamma * p0 / rho0)

    def u(x, t):
        # the C- characteristic through (x, t): f(tau) increases with tau
        sel = T <= t
        f = L + X[sel] + (0.5 * (gamma + 1) * V[sel] - c0) * (t - T[sel]) - x
        if f[0] >= 0:
            return 0.0          # ahead of the first rarefaction characteristic
        return np.interp(0.0, f, V[sel])

    def speed(x, t):
        return c0 + 0.5 * (3 - gamma) * u(x, t)

    t, x = L / c0, 0.0
    h = (T[-1] - t) / nSteps
    gap = L - x
    while t + h <= T[-1]:
        xm = x + 0.5 * h * speed(x, t)
        x += h * speed(xm, t + 0.5 * h)
        t += h
        gapNew = L + np.interp(t, T, X) - x
        if gapNew <= 0:
            return t - h * gapNew / (gapNew - gap)
        gap = gapNew
    raise RuntimeError("the reflected wave does not reach the projectile")


def solid_history(case):
    """Time, dt, projectile velocity and travel (from the solid momentum),
    gas + solid momentum, gas mass, from budget.dat."""
    b = bp.budget_table(os.path.join(case, "postProcessing", "jwlIbFoam", "0",
                                     "budget.dat"))
    t, dt = b["time"], b["dt"]
    v = b["solidMomentumX"] / (m * H)
    x = np.concatenate(([0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    # the first row is after one step: prepend the state at rest
    x += 0.5 * v[0] * t[0]
    return t, dt, v, x, b["gasMomentumX"] + b["solidMomentumX"], b["gasMass"]


def block_mesh(case):
    """nx, ny, dx, dy of the barrel (system/blockMeshDict)."""
    val = {}
    for line in open(os.path.join(case, "system", "blockMeshDict")):
        w = line.split()
        if len(w) == 2 and w[0] in ("xMax", "nx", "ny", "H"):
            val[w[0]] = float(w[1].rstrip(";"))
    nx, ny = int(val["nx"]), int(val["ny"])
    return nx, ny, val["xMax"] / nx, val["H"] / ny


def gas_density(case, time, n):
    try:
        return bp.read_field(case, time, "rho", n)
    except FileNotFoundError:
        a = bp.read_field(case, time, "alpha.products", n)
        return (a * bp.read_field(case, time, "rho.products", n)
                + (1 - a) * bp.read_field(case, time, "rho.air", n))


def leak_figure(label, case, xFront0):
    """Gas mass ahead of the projectile at the end against the start: the
    projectile seals the barrel (its covered cells hold no gas), so the
    chamber gas must not leak past it. Split at the middle of the covered
    cells."""
    nx, ny, dx, dy = block_mesh(case)
    x = np.tile((np.arange(nx) + 0.5) * dx, ny)
    rho0 = gas_density(case, "0", nx * ny)
    m0 = np.sum(rho0[x > xFront0]) * dx * dy
    tEnd = bp.latest_time(case)
    a = bp.read_field(case, tEnd, "alpha.solid", nx * ny)
    phi = bp.read_field(case, tEnd, "fluidFraction", nx * ny)
    covered = a > 0.999
    if not covered.any():
        raise RuntimeError(f"{case}: no cell covered by the projectile")
    split = 0.5 * (x[covered].min() + x[covered].max())
    rho = gas_density(case, tEnd, nx * ny)
    m1 = np.sum((rho * phi)[x > split]) * dx * dy
    return bp.figure(f"{label}: gas mass ahead of the projectile, change "
                     "(relative)", m1 / m0 - 1, 0.0, 1e-3)


def energy_figure(label, case, tolerance):
    """Gas + solid energy (kinetic, elastic, joints, fracture, damping,
    contact) of the closed barrel: the walls do no work, so it is
    conserved; the first row is one step after the start. The cut-cell
    coupling conserves it to round-off for rigid motion (the ideal-gas gun:
    1e-8) and to the sub-cycling error of the ringing projectile otherwise
    (the TNT gun: 1e-4); the first generation gained 1.6 - 2.4 % and 12 %."""
    b = bp.budget_table(os.path.join(case, "postProcessing", "jwlIbFoam", "0",
                                     "budget.dat"))
    e = b["gasEnergy"] + bp.solid_energy(b)
    return bp.figure(f"{label}: gas + solid energy change (relative)",
                     e[-1] / e[0] - 1, 0.0, tolerance)


def wall_pressure(case):
    """Probes at the breech and at the muzzle-end wall: t, pB, pM."""
    p = np.loadtxt(os.path.join(case, "postProcessing", "wallPressure", "0",
                                "p"))
    return p[:, 0], p[:, 1], p[:, 2]


def momentum_figure(label, case, t, dt, mom):
    """Gas + solid momentum of the closed barrel against the impulse of the
    end-wall pressures (first-cell pressures; per unit depth)."""
    tp, pB, pM = wall_pressure(case)
    if len(tp) != len(t):
        raise RuntimeError(f"{case}: probes and budget have different steps")
    impulse = np.sum(dt * (pB - pM)) * H
    return bp.figure(f"{label}: momentum change / end-wall impulse - 1",
                     mom[-1] / impulse - 1, 0.0, 0.005)


def ideal_gas(figures):
    case = "idealGas"
    c0 = np.sqrt(gamma * p0 / rho0)
    T, X, V = piston(4 * c0 * m / p0)
    tw = reflection_time(T, X, V, L_air)
    t, dt, v, x, mom, mass = solid_history(case)
    if t[-1] < tw:
        raise RuntimeError(f"{case} ends at {t[-1]} s, before the window "
                           f"end {tw} s")
    vEnd, vEndExact = np.interp(tw, t, v), np.interp(tw, T, V)
    xEnd, xEndExact = np.interp(tw, t, x), np.interp(tw, T, X)
    w = t <= tw
    errMax = np.max(np.abs(v[w] - np.interp(t[w], T, V))) / vEndExact
    figures += [
        bp.figure("idealGas: window end (reflected wave at the projectile) [s]",
                  tw),
        bp.figure("idealGas: muzzle velocity at the window end [m/s]",
                  vEnd, vEndExact, 0.01, relative=True),
        bp.figure("idealGas: max |v - v_exact| over the window / v_exact(end)",
                  errMax, 0.0, 0.01),
        bp.figure("idealGas: travel at the window end [m]",
                  xEnd, xEndExact, 0.01, relative=True),
        momentum_figure("idealGas", case, t, dt, mom),
        energy_figure("idealGas", case, 1e-8),
        leak_figure("idealGas", case, L_air + Lp),
        bp.figure("idealGas: gas mass change (relative)",
                  abs(mass[-1] / mass[0] - 1), 0.0, 1e-10),
    ]

    fig, ax = plt.subplots(figsize=(7, 4.5))
    sel = T <= 1.15 * t[-1]
    ax.plot(T[sel] * 1e3, V[sel], "k--", lw=1, label="exact simple wave")
    ax.plot(t * 1e3, v, "r", lw=1.2, label="jwlIbFoam (solid momentum / mass)")
    ax.axvline(tw * 1e3, color="gray", ls=":",
               label="reflected wave reaches the projectile")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("projectile velocity [m/s]")
    ax.set_title(f"Ideal-gas gun: p0 = {p0/1e6:g} MPa, c0 = {c0:.0f} m/s, "
                 f"m = {m:g} kg/m2, L = {L_air} m")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig("projectileFire_idealGas.png", dpi=120)


def tnt(figures):
    case = "tnt"
    t, dt, v, x, mom, mass = solid_history(case)
    if x[-1] < travel_muzzle:
        raise RuntimeError(f"{case}: travel {x[-1]} m < {travel_muzzle} m")
    vMuzzle = np.interp(travel_muzzle, x, v)
    tMuzzle = np.interp(travel_muzzle, x, t)
    tp, pB, pM = wall_pressure(case)
    # Gurney, charge tamped by a rigid wall (infinite travel)
    MC = m / (rho_tnt * L_tnt)
    vGurney = sqrt2E_tnt / np.sqrt(MC + 1 / 3)
    figures += [
        bp.figure(f"tnt: muzzle velocity (travel {travel_muzzle} m) [m/s]",
                  vMuzzle),
        bp.figure("tnt: time to the muzzle [s]", tMuzzle),
        bp.figure("tnt: muzzle velocity / Gurney tamped-charge velocity "
                  f"({vGurney:.0f} m/s, infinite travel)", vMuzzle / vGurney),
        bp.figure("tnt: peak breech pressure [Pa]", pB.max()),
        bp.figure("tnt: breech pressure at muzzle exit [Pa]",
                  np.interp(tMuzzle, tp, pB)),
        momentum_figure("tnt", case, t, dt, mom),
        energy_figure("tnt", case, 1e-4),
        leak_figure("tnt", case, L_tnt + Lp),
        bp.figure("tnt: gas mass change (relative)",
                  abs(mass[-1] / mass[0] - 1), 0.0, 1e-10),
    ]

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    sel = x <= travel_muzzle * 1.02
    a1.plot(x[sel], v[sel], "r")
    a1.axhline(vGurney, color="k", ls="--", lw=0.8,
               label="Gurney, tamped charge, infinite travel")
    a1.plot([travel_muzzle], [vMuzzle], "ko")
    a1.annotate(f"muzzle {vMuzzle:.0f} m/s", (travel_muzzle, vMuzzle),
                textcoords="offset points", xytext=(-90, -20))
    a1.set_xlabel("travel [m]")
    a1.set_ylabel("projectile velocity [m/s]")
    a1.legend(loc="lower right")
    a1.set_title(f"TNT gun: {L_tnt} m charge, M/C = {MC:.2f}")
    selp = tp <= tMuzzle * 1.02
    a2.semilogy(tp[selp] * 1e3, pB[selp], "b")
    a2.axvline(tMuzzle * 1e3, color="gray", ls=":", label="muzzle exit")
    a2.set_xlabel("t [ms]")
    a2.set_ylabel("breech pressure [Pa]")
    a2.legend()
    fig.tight_layout()
    fig.savefig("projectileFire_tnt.png", dpi=120)


figures = []
ideal_gas(figures)
if "-quick" not in sys.argv[1:]:
    tnt(figures)
bp.write_summary("summary.json", "projectileFire", figures)
