#!/usr/bin/python3
"""Compare the gas fields and the solid state of two jwlIbFoam time
directories: prints the largest relative difference (0 = bitwise equal).
    compareCases.py dirA dirB [fields...]"""
import re
import sys

import numpy as np


def numbers(path):
    """All numbers after the header (internalField values and the solid
    state), as one flat array."""
    text = open(path).read()
    text = text[text.find("}") + 1:]           # skip FoamFile header
    text = re.sub(r"//.*", "", text)
    # A partitioned run's bookkeeping of its rank count: the per-rank split
    # of the energy accounts (their sums are the entry energyAccounts), the
    # triangles' owner ranks and the load-balancing schedule
    for entry in ("rankEnergyAccounts", "triangleOwner", "balanceState"):
        text = re.sub(entry + r"\b[^;]*;", "", text)
    toks = re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", text)
    return np.array([float(t) for t in toks])


def internal(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\((.*?)\n\)\s*;",
                  text, re.S)
    if not m:
        m2 = re.search(r"internalField\s+uniform\s+([^;]+);", text)
        return np.array([float(t) for t in re.findall(r"[-+\d.eE]+", m2.group(1))])
    body = m.group(2).replace("(", " ").replace(")", " ")
    return np.array([float(t) for t in body.split()])


if __name__ == "__main__":
    a, b = sys.argv[1], sys.argv[2]
    fields = sys.argv[3:] or ["p", "rho", "U", "rhoU", "rhoE", "alpha.solid", "fluidFraction"]
    worst = 0.0
    for f in fields:
        x, y = internal(f"{a}/{f}"), internal(f"{b}/{f}")
        if x.shape != y.shape:
            print(f"{f}: sizes differ {x.shape} {y.shape}")
            sys.exit(1)
        scale = max(np.abs(x).max(), 1e-300)
        d = np.abs(x - y).max() / scale
        worst = max(worst, d)
        print(f"{f}: {d:.3e}")
    sa, sb = numbers(f"{a}/uniform/femdemState"), numbers(f"{b}/uniform/femdemState")
    d = np.abs(sa - sb).max() / max(np.abs(sa).max(), 1e-300) if sa.shape == sb.shape else np.inf
    print(f"femdemState: {d:.3e}")
    worst = max(worst, d)
    print(f"max {worst:.3e}")
