#!/usr/bin/python3
"""Read postProcessing/jwlIbFoam/<t>/budget.dat by column name and print the
conservation figures of a coupled run.
    budget.py [budget.dat]   -> columns as a dict of numpy arrays (import)
Columns are found by the names in the header line
('# per unit depth: time dt gasMass ...')."""
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [here, os.path.join(here, "..", "..", "..", "tutorials", "jwlIbFoam", "common")]
import blastPost  # noqa: E402 (budget_table, solid_energy)
from compareCases import internal  # noqa: E402,F401 (ASCII field reader)


def load(path="postProcessing/jwlIbFoam/0/budget.dat"):
    return blastPost.budget_table(path)


solidEnergy = blastPost.solid_energy


def drifts(b):
    """Relative drifts over the run: total energy (gas + solid), total
    momentum, gas mass"""
    E = b["gasEnergy"] + solidEnergy(b)
    P = np.stack([b["gasMomentumX"] + b["solidMomentumX"],
                  b["gasMomentumY"] + b["solidMomentumY"]], axis=1)
    m = b["gasMass"]
    scale = max(np.abs(P).max(), 1e-300)
    return (np.abs(E - E[0]).max() / abs(E[0]),
            np.abs(P - P[0]).max() / scale,
            np.abs(m - m[0]).max() / m[0])


def report(results):
    """Print (name, value, tolerance or None, "<=" or ">=") rows as '>>'
    lines, marking failures; the number of failures"""
    bad = 0
    for name, v, tol, how in results:
        ok = tol is None or (v >= tol if how == ">=" else abs(v) <= tol)
        bad += not ok
        lim = "" if tol is None else f" ({'at least' if how == '>=' else 'tolerance'} {tol:g})"
        print(f">> {name} = {v:.4g}{lim}" + ("" if ok else "  <-- FAIL"))
    return bad


if __name__ == "__main__":
    b = load(*sys.argv[1:2])
    dE, dP, dm = drifts(b)
    print(f"energy {dE:.3e} momentum {dP:.3e} mass {dm:.3e}")
