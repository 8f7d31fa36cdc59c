#!/usr/bin/python3
"""Brazilian disc post-processing: indirect tensile strength 2P/(pi D t)
against f_t, crack along the loaded diameter, energy budget; writes
brazilianDisc.png and summary.json."""
import glob, json, math, os, re
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

D, t = 0.05, 1.0                       # disc diameter, thickness (plane strain)
props = open("constant/femdemProperties").read()
ft = float(re.search(r"tensileStrength\s+([0-9.eE+-]+)", props).group(1))

post = "postProcessing/femdem/0"
r = np.loadtxt(f"{post}/reactions.dat")
time = r[:, 0]
P = 0.5 * (-r[:, 2] + r[:, 4])          # mean of the two platens' loads
sigma = 2 * P / (math.pi * D * t)
ipk = int(np.argmax(sigma))
peak, tPeak = sigma[ipk], time[ipk]


def cracks(file):
    c = np.loadtxt(file, ndmin=2)
    return c.reshape(-1, 4)


# Crack events: each broken joint with the (log) time it broke
ev = np.loadtxt(f"{post}/crackEvents.dat", ndmin=2).reshape(-1, 5)
final = ev[:, 1:]


def length(c):
    return np.hypot(c[:, 2] - c[:, 0], c[:, 3] - c[:, 1])


def on_diameter(c):
    return (np.abs(c[:, 0]) < 1e-9 * D) & (np.abs(c[:, 2]) < 1e-9 * D)


# The split: first time the loaded diameter is cracked over 80 % of D;
# the crack pattern then must lie mostly along the diameter
onDiam = on_diameter(final)
cum = np.cumsum(np.where(onDiam, length(final), 0.0))
iSplit = int(np.argmax(cum >= 0.8 * D)) if cum[-1] >= 0.8 * D else len(ev) - 1
tSplit = ev[iSplit, 0]
early = final[ev[:, 0] <= tSplit]
diameterFraction = cum[-1] / D
band = (np.abs(0.5 * (early[:, 0] + early[:, 2])) < 0.1 * D)
bandFraction = length(early[band]).sum() / max(length(early).sum(), 1e-30)

e = np.loadtxt(f"{post}/energy.dat")
inputWork = e[-1, 7] + e[-1, 8] + e[-1, 9]
closure = abs(e[-1, 10]) / inputWork

fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
a1.plot(time * 1e3, sigma / 1e6, label=r"$2P/(\pi D t)$")
a1.axhline(ft / 1e6, color="k", ls="--", label=r"$f_t$")
a1.axhspan(0.85 * ft / 1e6, 1.15 * ft / 1e6, color="0.9", label=r"$f_t \pm 15\%$")
a1.plot(tPeak * 1e3, peak / 1e6, "ro")
a1.set_xlabel("time [ms]")
a1.set_ylabel("indirect tensile stress [MPa]")
a1.legend()
a1.set_title(f"peak {peak/1e6:.2f} MPa = {peak/ft:.3f} $f_t$")
th = np.linspace(0, 2 * math.pi, 200)
a2.plot(D / 2 * np.cos(th) * 1e3, D / 2 * np.sin(th) * 1e3, "k-", lw=0.8)
for c in final:
    a2.plot([c[0] * 1e3, c[2] * 1e3], [c[1] * 1e3, c[3] * 1e3], "0.6", lw=0.8)
for c in early:
    a2.plot([c[0] * 1e3, c[2] * 1e3], [c[1] * 1e3, c[3] * 1e3], "r-", lw=1.5)
a2.set_aspect("equal")
a2.set_xlabel("x [mm]")
a2.set_ylabel("y [mm] (load along y)")
a2.set_title(f"broken joints: red at the split ({tSplit*1e3:.3f} ms), grey end")
fig.tight_layout()
fig.savefig("brazilianDisc.png", dpi=120)

figures = [
    {"name": "indirectTensileStrength_MPa", "value": peak / 1e6, "reference": ft / 1e6,
     "error": abs(peak - ft) / ft, "tolerance": 0.15, "pass": abs(peak - ft) / ft <= 0.15},
    {"name": "loadedDiameterCrackedFraction", "value": diameterFraction, "reference": 1.0,
     "tolerance": 0.2, "pass": diameterFraction >= 0.8},
    {"name": "crackLengthWithin0.1DOfDiameterAtSplit", "value": bandFraction, "reference": 1.0,
     "tolerance": 0.5, "pass": bandFraction >= 0.5},
    {"name": "energyBudgetResidualOverInput", "value": closure, "reference": 0.0,
     "tolerance": 0.01, "pass": closure <= 0.01},
]
for f in figures:
    f["pass"] = bool(f["pass"])
    f["value"] = float(f["value"])
json.dump({"case": "femdemFoam/brazilianDisc", "figures": figures},
          open("summary.json", "w"), indent=1)
for f in figures:
    print(f"{f['name']}: {f['value']:.4g} ({'pass' if f['pass'] else 'FAIL'})")
