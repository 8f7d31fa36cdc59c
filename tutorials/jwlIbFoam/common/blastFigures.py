"""Figures blast engineers read, for the jwlIbFoam tutorials' post-processing.

Fragment size curve (all sizes x in metres, passing fractions P in [0, 1]):
  passing_curve(size, mass): sizes sorted, P at each fragment = mass finer
      than it plus half its own (the mid-step of the empirical curve, so
      that a curve sampled from a distribution is unbiased), and the mass
      fraction dP of each fragment
  rosin_rammler(x, x50, n):  P = 1 - exp(-ln2 (x/x50)^n)
  swebrec(x, x50, xmax, b):  P = 1/(1 + (ln(xmax/x)/ln(xmax/x50))^b), x < xmax
      (Ouchterlony 2005), 1 beyond xmax
  fit_rosin_rammler(x, P, w), fit_swebrec(x, P, w): least squares on the
      passing curve itself, sum w_i (P_model(x_i) - P_i)^2 (w: the mass
      fractions dP of the fitted points, so that the fit measures the
      area between the curves, not the number of fragments), scipy
      least_squares on log-parameters; returns the parameters and the
      rms error of the fit in passing fraction
  percentile(x, P, p): size x_p of the empirical curve (log-linear
      interpolation)

Kuz-Ram / KCO prediction (Cunningham 1983, 1987; Ouchterlony 2005):
  kuz_ram_x50(A, q, Q, rws): x50 [m] = 0.01 A q^-0.8 Q^(1/6) (115/rws)^(19/30)
      (A rock factor, q specific charge [kg/m3], Q charge per hole [kg], rws
      weight strength relative to ANFO [%])
  cunningham_n(B, S, d, W, L, H): uniformity index n = (2.2 - 14 B/d)
      sqrt((1 + S/B)/2) (1 - W/B) (L/H)  (B burden, S spacing, W drilling
      deviation, L charge length, H bench height [m]; d hole diameter [mm])
  kco(...): x50, n, xmax and the Swebrec b = 2 ln2 ln(xmax/x50) n
  cunningham_rock_factor(rmd, jf, rho, E): A = 0.06 (RMD + JF + RDI + HF),
      RDI = 25 rho[t/m3] - 50, HF = E[GPa]/3 (E < 50 GPa)

Damage zone:
  esen_crushed_radius(Pb, sigma_c, E, nu, r0): Esen, Onederra & Bilgin (2003,
      IJRMMS 40: 485): CZI = Pb^3/(K sigma_c^2), K = E/(1 + nu) (all in Pa, so
      CZI is dimensionless), r_c = 0.812 r0 CZI^0.219
  ucs_mohr_coulomb(c, phi): sigma_c = 2 c cos(phi)/(1 - sin(phi))
  ppv_damage_threshold(ft, E, cp): PPV = f_t c_p/E (Persson et al.)

Throw:
  ballistic_landing(x0, z0, v, vz, zFloor, g): where a fragment launched at
      horizontal position x0 (vector), height z0 with horizontal velocity v
      and vertical vz lands on the floor z = zFloor: t = (vz + sqrt(vz^2 +
      2 g (z0 - zFloor)))/g, x = x0 + v t (drag neglected)

Probes:
  read_probes(dir): postProcessing/<probes>/<startTime>/velocity.dat of
      all start times (a restart writes a new one; a rerun from the same
      start time velocity_1.dat, ...) joined in time order, columns by name
  probe_points(dir): the probes' initial positions from the file headers

Case input and animation:
  read_entry(path, key, default): a scalar entry of an OpenFOAM dictionary
      file (top level), the default when the file or the entry is missing
  foam_entry(path, entry, default): any entry (a.b.c scoping) through
      OpenFOAM's foamDictionary, as a number, a vector or a word;
      foam_keywords(path, entry): the keywords of a sub-dictionary
  jwl_explosive(thermoFile, material): the JWL coefficients of a products
      material: the preset of its 'explosive' (the table of
      src/blastThermo/equationOfState/JWL/JWL.C) with the entries the
      dictionary overrides
  animate(...): GIF of the solid (fragments, broken joints) over the gas
      pressure at the written times (matplotlib PillowWriter, python3-pil)
"""
import os
import re
import subprocess

import numpy as np
from scipy.optimize import least_squares

LN2 = np.log(2.0)


# ------------------------------------------------------- size distributions
def passing_curve(size, mass):
    """Sorted sizes, mid-step passing fractions and mass fractions"""
    order = np.argsort(size)
    x = np.asarray(size, float)[order]
    dP = np.asarray(mass, float)[order] / np.sum(mass)
    return x, np.cumsum(dP) - 0.5 * dP, dP


def rosin_rammler(x, x50, n):
    return 1.0 - np.exp(-LN2 * (np.asarray(x, float) / x50) ** n)


def swebrec(x, x50, xmax, b):
    x = np.asarray(x, float)
    r = np.log(xmax / np.minimum(x, xmax)) / np.log(xmax / x50)
    return np.where(x < xmax, 1.0 / (1.0 + r ** b), 1.0)


def percentile(x, P, p):
    """Size at passing fraction p of the curve (x, P) (log-linear)"""
    return float(np.exp(np.interp(p, P, np.log(x))))


def _fit(model, p0, x, P, w, upper=None):
    """Least squares of model(x, q) on P over log q; upper: bounds on q
    (None: unbounded)"""
    w = np.ones_like(P) if w is None else np.asarray(w, float)
    sw = np.sqrt(w / w.sum())
    if upper is None:
        kw = {"method": "lm" if len(P) > len(p0) else "trf"}
    else:
        kw = {"method": "trf", "bounds": (-np.inf, np.log(upper))}
    res = least_squares(lambda q: sw * (model(x, np.exp(q)) - P), np.log(p0),
                        xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=5000, **kw)
    rms = float(np.sqrt(np.sum((sw * (model(x, np.exp(res.x)) - P)) ** 2)))
    return np.exp(res.x), rms


def fit_rosin_rammler(x, P, w=None, p0=None):
    """Least squares on P; start from p0 (x50, n), default the linearised
    fit"""
    x, P = np.asarray(x, float), np.asarray(P, float)
    m = (P > 0.01) & (P < 0.99)
    if p0 is not None:
        x500, n0 = p0
    elif m.sum() >= 2:
        n0, c0 = np.polyfit(np.log(x[m]), np.log(-np.log(1 - P[m])), 1)
        n0 = max(n0, 0.1)
        x500 = np.exp(-c0 / n0) * LN2 ** (1 / n0)
    else:
        n0, x500 = 1.0, np.median(x)
    (x50, n), rms = _fit(lambda x, q: rosin_rammler(x, q[0], q[1]),
                         [x500, n0], x, P, w)
    return {"x50": x50, "n": n, "x80": x50 * (np.log(5) / LN2) ** (1 / n),
            "rms": rms}


def fit_swebrec(x, P, w=None, p0=None, xmaxBound=None):
    """Least squares on P over x50, xmax - x50 (> 0) and b; start from p0
    (x50, xmax, b), default the curve's x50, xmax above the largest size
    and b = 2. xmaxBound: the largest fragment the rock can give (the
    block's size); a fit whose xmax runs past it (the curve is closer to
    the Swebrec's log-logistic limit xmax, b -> infinity, which it never
    reaches: xmax 2.5e306 m was seen) is made again with xmax - x50 at
    most xmaxBound less the curve's x50, and "atBound" says so"""
    x, P = np.asarray(x, float), np.asarray(P, float)
    if p0 is None:
        x500 = percentile(x, P, 0.5) if P.min() < 0.5 < P.max() else np.median(x)
        p0 = [x500, max(1.5 * x.max(), 2 * x500), 2.0]
    model = lambda x, q: swebrec(x, q[0], q[0] + q[1], q[2])
    q0 = [p0[0], p0[1] - p0[0], p0[2]]
    (x50, dx, b), rms = _fit(model, q0, x, P, w)
    atBound = xmaxBound is not None and not x50 + dx <= xmaxBound
    if atBound:
        # xmax - x50 <= xmaxBound - (the curve's x50): xmax ends near the bound
        dxMax = xmaxBound - q0[0]
        q0[1] = min(q0[1], 0.5 * dxMax)
        (x50, dx, b), rms = _fit(model, q0, x, P, w, upper=[np.inf, dxMax, np.inf])
    xmax = x50 + dx
    x80 = xmax * np.exp(-np.log(xmax / x50) * 0.25 ** (1 / b))
    return {"x50": x50, "xmax": xmax, "b": b, "x80": x80, "rms": rms, "atBound": atBound}


# ------------------------------------------------------------------ Kuz-Ram
def kuz_ram_x50(A, q, Q, rws):
    """Kuznetsov-Cunningham x50 [m]"""
    return 0.01 * A * q ** -0.8 * Q ** (1 / 6) * (115.0 / rws) ** (19 / 30)


def cunningham_n(B, S, d_mm, W, L, H):
    return (2.2 - 14 * B / d_mm) * np.sqrt((1 + S / B) / 2) * (1 - W / B) * (L / H)


def cunningham_rock_factor(rmd, jf, rho, E):
    """A = 0.06 (RMD + JF + RDI + HF); rho [kg/m3], E [Pa]"""
    rdi = 25 * rho / 1000 - 50
    hf = E / 1e9 / 3 if E < 50e9 else 0.0   # UCS/5 above 50 GPa: not needed here
    return 0.06 * (rmd + jf + rdi + hf)


def kco(A, q, Q, rws, B, S, d_mm, W, L, H, xmax):
    x50 = kuz_ram_x50(A, q, Q, rws)
    n = cunningham_n(B, S, d_mm, W, L, H)
    return {"x50": x50, "n": n, "xmax": xmax,
            "b": 2 * LN2 * np.log(xmax / x50) * n}


# -------------------------------------------------------------- damage zone
def ucs_mohr_coulomb(c, phi_deg):
    phi = np.radians(phi_deg)
    return 2 * c * np.cos(phi) / (1 - np.sin(phi))


def esen_crushed_radius(Pb, sigma_c, E, nu, r0):
    K = E / (1 + nu)
    czi = Pb ** 3 / (K * sigma_c ** 2)
    return 0.812 * r0 * czi ** 0.219, czi


def ppv_damage_threshold(ft, E, cp):
    return ft * cp / E


# -------------------------------------------------------------------- throw
def ballistic_landing(x0, z0, v, vz, zFloor, g=9.81):
    """Landing positions (N, dim) and flight times of launches from x0
    (N, dim) at height z0 with horizontal velocity v (N, dim), vertical vz"""
    vz = np.asarray(vz, float)
    t = (vz + np.sqrt(vz ** 2 + 2 * g * (np.asarray(z0, float) - zFloor))) / g
    return np.asarray(x0, float) + np.asarray(v, float) * np.atleast_1d(t)[:, None], t


# ------------------------------------------------------------------- probes
def read_probes(directory, name="velocity"):
    """Columns (by the names of the '# Time ...' header line) of all the
    files <startTime>/<name>.dat and <name>_<k>.dat (a rerun from the same
    start time) in directory, joined in time order: a later file replaces
    the rows of the earlier ones from its first time on"""
    files = []
    for d in os.listdir(directory):
        try:
            t0 = float(d)
        except ValueError:
            continue
        for f in os.listdir(os.path.join(directory, d)):
            stem = f[:-4] if f.endswith(".dat") else None
            if stem == name:
                files.append((t0, 0, os.path.join(directory, d, f)))
            elif stem and stem.startswith(name + "_") and stem[len(name) + 1:].isdigit():
                files.append((t0, int(stem[len(name) + 1:]), os.path.join(directory, d, f)))
    if not files:
        raise FileNotFoundError(f"no {name}.dat under {directory}")
    names, rows = None, np.zeros((0, 0))
    for _, _, path in sorted(files):
        head = [l for l in open(path) if l.startswith("# Time")]
        if not head:
            raise RuntimeError(f"{path}: no '# Time ...' header line")
        if names is not None and head[-1][1:].split() != names:
            raise RuntimeError(f"{path}: columns differ from the earlier files")
        names = head[-1][1:].split()
        data = np.loadtxt(path, ndmin=2).reshape(-1, len(names))
        if len(data):
            rows = data if rows.size == 0 else np.vstack([rows[rows[:, 0] < data[0, 0]], data])
    return {n: rows[:, i] for i, n in enumerate(names)}


def probe_points(directory, name="velocity"):
    """Initial positions of the probes ('# Probe i (x y) ...' header lines)"""
    for d in sorted(os.listdir(directory)):
        path = os.path.join(directory, d, name + ".dat")
        if os.path.isfile(path):
            pts = [re.match(r"# Probe \d+ \((\S+) (\S+)\)", l) for l in open(path)]
            return np.array([[float(m.group(1)), float(m.group(2))] for m in pts if m])
    raise FileNotFoundError(f"no {name}.dat under {directory}")


def read_entry(path, key, default):
    if not os.path.isfile(path):
        return default
    text = re.sub(r"//[^\n]*", "", open(path).read())
    m = re.search(r"(?:^|[;{}\s])" + re.escape(key) + r"\s+([^;\s]+)\s*;", text)
    if not m:
        return default
    try:
        return float(m.group(1))
    except ValueError:
        raise ValueError(f"{path}: entry '{key}' is not a number: {m.group(1)}")


def foam_entry(path, entry, default=None):
    out = subprocess.run(["foamDictionary", "-entry", entry, "-value", path],
                         capture_output=True, text=True)
    if out.returncode != 0:
        if default is None:
            raise KeyError(f"{path}: no entry '{entry}'")
        return default
    v = out.stdout.strip()
    try:
        if v.startswith("("):
            return np.array([float(x) for x in v.strip("()").split()])
        return float(v)
    except ValueError:
        return v


def foam_keywords(path, entry):
    out = subprocess.run(["foamDictionary", "-entry", entry, "-keywords", path],
                         capture_output=True, text=True, check=True)
    return out.stdout.split()


# JWL presets (rho0 kg/m3, A B Pa, R1 R2 omega, E0 J/m3, D m/s): the table
# of src/blastThermo/equationOfState/JWL/JWL.C (LLNL Explosives Handbook)
JWL_PRESETS = {
    "TNT": (1630, 371.2e9, 3.231e9, 4.15, 0.95, 0.30, 7.0e9, 6930),
    "PETN": (1770, 617.1e9, 16.926e9, 4.40, 1.20, 0.25, 10.1e9, 8300),
    "CompB": (1717, 524.2e9, 7.678e9, 4.20, 1.10, 0.34, 8.5e9, 7980),
    "HMX": (1891, 778.3e9, 7.071e9, 4.20, 1.00, 0.30, 10.5e9, 9110),
}
JWL_KEYS = ("rho0", "A", "B", "R1", "R2", "omega", "E0", "D")


def jwl_explosive(thermoFile, material="products"):
    name = foam_entry(thermoFile, material + ".explosive", "")
    base = dict(zip(JWL_KEYS, JWL_PRESETS.get(name, (None,) * len(JWL_KEYS))))
    out = {k: foam_entry(thermoFile, f"{material}.{k}", base[k] if base[k] is not None
                         else None) for k in JWL_KEYS}
    out["name"] = name or material
    return out


def jwl_pressure(c, Vrel, e):
    """JWL pressure at relative volume Vrel and energy e per initial volume"""
    w = c["omega"]
    return (c["A"] * (1 - w / (c["R1"] * Vrel)) * np.exp(-c["R1"] * Vrel)
            + c["B"] * (1 - w / (c["R2"] * Vrel)) * np.exp(-c["R2"] * Vrel)
            + w * e / Vrel)


def animate(path, steps, read_vtu, draw_solid, read_lines, case, shape, extent,
            fps=2):
    """One frame per written solid step: log10 gas pressure (time
    directories of the case, fluid cells shape = (nx, ny) over extent) under
    the solid coloured by fragment with its broken joints"""
    import matplotlib.pyplot as plt
    from matplotlib.animation import PillowWriter
    from blastPost import read_field
    nx, ny = shape
    fig, ax = plt.subplots(figsize=(6.5, 6.5))
    norm = plt.Normalize(4.5, 9.7)
    fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="inferno"), ax=ax,
                 label="gas log10 p [Pa]", shrink=0.8)
    writer = PillowWriter(fps=fps)
    with writer.saving(fig, path, dpi=90):
        for i, (t, f) in enumerate(steps):
            ax.clear()
            try:
                p = read_field(case, t, "p", nx * ny).reshape(ny, nx)
                ax.imshow(np.log10(np.maximum(p, 1.0)), origin="lower", extent=extent,
                          cmap="inferno", norm=norm)
            except (FileNotFoundError, ValueError):
                pass
            v = read_vtu(f)
            draw_solid(ax, v, read_lines(i),
                       f"t = {t * 1e6:.0f} us: gas pressure, fragments, broken joints")
            ax.set_ylim(extent[2], extent[3])
            writer.grab_frame()
    plt.close(fig)
