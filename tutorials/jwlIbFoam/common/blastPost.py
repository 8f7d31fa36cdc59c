"""Small helpers for the jwlIbFoam tutorials' post-processing (no PyFoam).

read_field(case, time, name): internal field of an ascii OpenFOAM field as a
numpy array (scalars: shape (n,), vectors: shape (n, 3)); a uniform field
needs n.
read_exact(case, time): columns of postProcessing/exactRiemann/<time>/exact.dat
budget_table(path or case), solid_energy(b): budget.dat columns by name
    (of a case: every start time's, joined across restarts);
joined_rows(case, function, file): a postProcessing time series joined
    across restarts;
log_table(logfile): per-step (time, dt, maxP, mass, energy, minRho, minP)
    from a jwlIbFoam log
write_summary(path, case, figures): summary.json as doc/developing.md says.
"""
import json
import os
import re

import numpy as np


def _time_dir(case, time):
    if isinstance(time, str):
        return os.path.join(case, time)
    # match the directory whose name parses to this value
    best = None
    for d in os.listdir(case):
        try:
            v = float(d)
        except ValueError:
            continue
        if abs(v - time) <= 1e-9 * max(1.0, abs(time)):
            best = d
    if best is None:
        raise FileNotFoundError(f"no time {time} in {case}")
    return os.path.join(case, best)


def latest_time(case):
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    return max(times)[1]


def read_field(case, time, name, n=None):
    text = open(os.path.join(_time_dir(case, time), name)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    if m:
        kind, count = m.group(1), int(m.group(2))
        body = text[m.end():]
        if kind == "scalar":
            vals = np.array(body.split(None, count)[:count], dtype=float)
            return vals
        vecs = re.findall(r"\(([^()]*)\)", body)[:count]
        return np.array([[float(x) for x in v.split()] for v in vecs])
    m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
    if m:
        v = m.group(1).strip()
        if v.startswith("("):
            vec = [float(x) for x in v.strip("()").split()]
            return np.tile(vec, (n or 1, 1))
        return np.full(n or 1, float(v))
    raise ValueError(f"cannot parse {name}")


def read_exact(case, time):
    d = _time_dir(os.path.join(case, "postProcessing", "exactRiemann"), time)
    data = np.loadtxt(os.path.join(d, "exact.dat"))
    head = open(os.path.join(d, "exact.dat")).readline()
    info = dict(zip(head.split()[6::2], [float(x.rstrip(")"))
                                          for x in head.split()[7::2]]))
    return data, info


def log_table(logfile):
    rows = []
    pat = re.compile(r"^Time = (\S+)\s+dt = (\S+)\s+maxP = (\S+)\s+mass = (\S+)"
                     r"\s+energy = (\S+)\s+minRho = (\S+)\s+minP = (\S+)")
    for line in open(logfile):
        m = pat.match(line)
        if m:
            rows.append([float(x) for x in m.groups()])
    return np.array(rows)


def _rows(path, ncol=None):
    """Numeric rows of a column file ('#' comments), the rows without ncol
    values left out (a run killed mid-row leaves one cut short)"""
    rows = []
    with open(path) as fh:
        for line in fh:
            if line.startswith("#") or not line.strip():
                continue
            v = line.replace("(", " ").replace(")", " ").split()
            if ncol is None:
                ncol = len(v)
            if len(v) == ncol:
                rows.append([float(x) for x in v])
    return np.array(rows).reshape(-1, ncol or 0)


def series_files(case, *parts):
    """The files postProcessing/<parts[0]>/<startTime>/<parts[1:]> of a
    case, in the order of their start times: a run writes its function
    outputs under its start time, so a restart adds a directory"""
    base = os.path.join(case, "postProcessing", parts[0])
    found = []
    for d in os.listdir(base) if os.path.isdir(base) else []:
        f = os.path.join(base, d, *parts[1:])
        try:
            found.append((float(d), f))
        except ValueError:
            continue
        if not os.path.isfile(f):
            found.pop()
    if not found:
        raise RuntimeError(f"{os.path.join(base, '<time>', *parts[1:])}: "
                           "no such file for any start time")
    return sorted(found)


def joined_rows(case, *parts):
    """The rows (first column the time) of the files series_files finds,
    joined across restarts: each run's rows up to the next run's start
    time, where the next run took over"""
    files = series_files(case, *parts)
    out = []
    for k, (t0, f) in enumerate(files):
        data = _rows(f, out[0].shape[1] if out else None)
        if k + 1 < len(files):
            data = data[data[:, 0] <= files[k + 1][0] * (1 + 1e-12)]
        out.append(data)
    return np.vstack(out)


def budget_table(path):
    """Columns of a jwlIbFoam budget.dat by the names of its header line
    ('# per unit depth: time dt gasMass ...'), as a dict of arrays; a case
    directory instead of a file: the budget.dat of every start time,
    joined across restarts (joined_rows)"""
    files = [path]
    if os.path.isdir(path):
        files = [f for _, f in series_files(path, "jwlIbFoam", "budget.dat")]
    names = None
    with open(files[0]) as fh:
        for line in fh:
            if not line.startswith("#"):
                break
            head = line[1:].split(":", 1)[-1].split()
            if "time" in head:
                names = head
    if names is None:
        raise RuntimeError(f"{files[0]}: no header line with column names")
    if os.path.isdir(path):
        data = joined_rows(path, "jwlIbFoam", "budget.dat")
    else:
        data = _rows(path, len(names))
    if data.shape[1] != len(names):
        raise RuntimeError(f"{files[0]}: {data.shape[1]} columns, "
                           f"{len(names)} names in the header")
    return {n: data[:, i] for i, n in enumerate(names)}


def gas_mass(b):
    """Gas mass of a budget table: the mesh's, plus the crack gas's
    (crackGas) with what the network could not hand back and less the
    ambient gas it created for isolated joints"""
    m = b["gasMass"].copy()
    if "crackGasMass" in b:
        m += (b["crackGasMass"] + b["crackGasLostMass"]
              - b["crackGasCreatedMass"])
    return m


def gas_energy(b):
    """Gas energy of a budget table: the mesh's, plus the crack gas's
    (crackGas) with what the network could not hand back and less the
    ambient gas it created for isolated joints"""
    E = b["gasEnergy"].copy()
    if "crackGasEnergy" in b:
        E += (b["crackGasEnergy"] + b["crackGasLostEnergy"]
              - b["crackGasCreatedEnergy"])
    return E


def solid_energy(b):
    """Solid energy of a budget table: kinetic, elastic, stored and
    dissipated, minus the work of gravity"""
    return (b["solidKinetic"] + b["solidElastic"] + b["solidJointStored"]
            + b["solidFracture"] + b["solidDamping"] + b["solidContact"]
            - b["solidGravityWork"])


def figure(name, value, reference=None, tolerance=None, error=None,
           passed=None, relative=False):
    """One summary entry; error defaults to |value - reference| (relative
    if asked); pass defaults to error <= tolerance."""
    if error is None and reference is not None:
        error = abs(value - reference)
        if relative:
            error /= abs(reference)
    if passed is None:
        passed = True if tolerance is None else bool(error <= tolerance)
    return {"name": name, "value": float(value),
            "reference": None if reference is None else float(reference),
            "error": None if error is None else float(error),
            "tolerance": None if tolerance is None else float(tolerance),
            "pass": bool(passed)}


def write_summary(path, case, figures):
    with open(path, "w") as fh:
        json.dump({"case": case, "figures": figures}, fh, indent=1)
    for f in figures:
        print(f"{f['name']}: {f['value']:.6g}"
              + ("" if f['tolerance'] is None else
                 f" (error {f['error']:.3g}, tolerance {f['tolerance']:.3g})")
              + ("" if f['pass'] else "  FAIL"))
