#!/usr/bin/python3
"""Read postProcessing/jwlIbFoam/<t>/budget.dat by column name and print the
conservation figures of a coupled run.
    budget.py [budget.dat]   -> columns as a dict of numpy arrays (import)
Columns are found by the names in the header line
('# per unit depth: time dt gasMass ...')."""
import sys

import numpy as np


def load(path="postProcessing/jwlIbFoam/0/budget.dat"):
    names = None
    with open(path) as fh:
        for line in fh:
            if line.startswith("#"):
                head = line[1:].split(":", 1)[-1].split()
                if "time" in head:
                    names = head
            else:
                break
    if names is None:
        raise SystemExit(f"{path}: no header line with column names")
    data = np.atleast_2d(np.loadtxt(path))
    return {n: data[:, i] for i, n in enumerate(names)}


from compareCases import internal  # noqa: E402 (ASCII field reader)


def solidEnergy(b):
    """Mechanical energy of the solid plus what it dissipated or stored"""
    return (b["solidKinetic"] + b["solidElastic"] + b["solidJointStored"]
            + b["solidFracture"] + b["solidDamping"] + b["solidContact"]
            - b["solidGravityWork"])


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


if __name__ == "__main__":
    b = load(*sys.argv[1:2])
    dE, dP, dm = drifts(b)
    print(f"energy {dE:.3e} momentum {dP:.3e} mass {dm:.3e}")
