#!/usr/bin/python3
"""Uniaxial compression post-processing: peak axial stress against the
Mohr-Coulomb strength 2 c cos(phi)/(1 - sin(phi)), energy budget; writes
uniaxialCompression.png and summary.json."""
import json, math, re
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

W, H, t = 0.05, 0.1, 1.0               # specimen width, height, thickness
props = open("constant/femdemProperties").read()
num = lambda key: float(re.search(key + r"\s+([0-9.eE+-]+)", props).group(1))
c, phi, E, nu = num("cohesion"), math.radians(num("frictionAngle")), num(r"\bE"), num(r"\bnu")
ucsMC = 2 * c * math.cos(phi) / (1 - math.sin(phi))

post = "postProcessing/femdem/0"
r = np.loadtxt(f"{post}/reactions.dat")
time = r[:, 0]
stress = 0.5 * (-r[:, 2] + r[:, 4]) / (W * t)
v = float(re.search(r"top\s*\{[^}]*value\s*\(\s*0\s+(-?[0-9.eE+-]+)", props).group(1))
strain = 2 * abs(v) * time / H         # ramp neglected in the plot only
ipk = int(np.argmax(stress))
peak = stress[ipk]
err = abs(peak - ucsMC) / ucsMC

e = np.loadtxt(f"{post}/energy.dat")
inputWork = e[-1, 7] + e[-1, 8] + e[-1, 9]
closure = abs(e[-1, 10]) / inputWork
ev = np.loadtxt(f"{post}/crackEvents.dat", ndmin=2).reshape(-1, 5)

fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.8), gridspec_kw={"width_ratios": [1.6, 1]})
a1.plot(strain * 1e3, stress / 1e6, label="axial stress")
a1.plot(strain * 1e3, E / (1 - nu**2) * strain / 1e6, "k:", lw=0.8,
        label=r"$E/(1-\nu^2)$ (plane strain, free sides)")
a1.axhline(ucsMC / 1e6, color="k", ls="--", label=r"$2c\cos\phi/(1-\sin\phi)$")
a1.axhspan(0.8 * ucsMC / 1e6, 1.2 * ucsMC / 1e6, color="0.9", label=r"$\pm 20\%$")
a1.plot(strain[ipk] * 1e3, peak / 1e6, "ro")
a1.set_ylim(0, 1.4 * max(peak, ucsMC) / 1e6)
a1.set_xlabel("nominal axial strain [1e-3]")
a1.set_ylabel("axial stress [MPa]")
a1.set_title(f"peak {peak/1e6:.1f} MPa, Mohr-Coulomb {ucsMC/1e6:.1f} MPa")
a1.legend(fontsize=8)
for x0, y0, x1, y1 in ev[:, 1:]:
    a2.plot([x0 * 1e3, x1 * 1e3], [y0 * 1e3, y1 * 1e3], "r-", lw=1)
a2.plot(np.array([-W / 2, W / 2, W / 2, -W / 2, -W / 2]) * 1e3,
        np.array([0, 0, H, H, 0]) * 1e3, "k-", lw=0.8)
a2.set_aspect("equal")
a2.set_title(f"broken joints at the end ({len(ev)})")
a2.set_xlabel("x [mm]")
a2.set_ylabel("y [mm]")
fig.tight_layout()
fig.savefig("uniaxialCompression.png", dpi=120)

figures = [
    {"name": "peakAxialStress_MPa", "value": float(peak / 1e6), "reference": ucsMC / 1e6,
     "error": float(err), "tolerance": 0.2, "pass": bool(err <= 0.2)},
    {"name": "energyBudgetResidualOverInput", "value": float(closure), "reference": 0.0,
     "tolerance": 0.01, "pass": bool(closure <= 0.01)},
    {"name": "brokenJoints", "value": int(len(ev)), "reference": None,
     "tolerance": None, "pass": bool(len(ev) > 0)},
]
json.dump({"case": "femdemFoam/uniaxialCompression", "figures": figures},
          open("summary.json", "w"), indent=1)
for f in figures:
    print(f"{f['name']}: {f['value']:.4g} ({'pass' if f['pass'] else 'FAIL'})")
