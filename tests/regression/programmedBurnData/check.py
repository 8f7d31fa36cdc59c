#!/usr/bin/python3
"""Programmed-burn detonation of a 1D charge from the closed wall x = 0
(tests gasProgrammedBurn*): figures against the exact solution, '>>' lines.

The exact solution is computed here from the JWL coefficients the solver
reports (log.jwlIbFoam): the CJ point (the Rayleigh line tangent to the
products' Hugoniot from the unreacted state rho0, e0 = E0/rho0, p0) and the
Taylor wave behind it on the isentrope through the CJ point,
    p_s(V) = A exp(-R1 V) + B exp(-R2 V) + C V^-(1 + omega),   V = rho0/rho,
a centred simple wave x/t = u + c with u = u_CJ - int_{V_CJ}^{V} c/V' dV',
then the plateau u = 0 from the wall to x = c_p t.

    check.py [--t0 T] [--inert] [--refinement] case [case ...]
    --t0: initiation time; --inert: the charge's pressure until t0;
    --refinement: the cases are one problem, coarse to fine (errors must fall)
Exit status 1 if a figure fails."""
import re, sys, os, glob
import numpy as np
from scipy.optimize import minimize_scalar, brentq
from scipy.integrate import quad

TOL_D, TOL_PCJ, TOL_PLATEAU, TOL_INERT = 0.01, 0.10, 0.03, 1e-6
failed = 0


def figure(name, value, reference=None, tol=None, err=None, ok=True):
    global failed
    s = f">> {name} = {value:.6g}"
    if reference is not None:
        s += f", reference {reference:.6g}"
    if err is not None:
        s += f", error {err:.3g}"
    if tol is not None:
        s += f", tolerance {tol:.3g}"
    if not ok:
        s += "  <-- FAIL"
        failed += 1
    print(s)


def jwl_from_log(case):
    text = open(os.path.join(case, "log.jwlIbFoam")).read()
    m = re.search(r": JWL rho0 (\S+) A (\S+) B (\S+) R1 (\S+) R2 (\S+) omega (\S+) E0 (\S+)", text)
    return dict(zip(["rho0", "A", "B", "R1", "R2", "omega", "E0"], map(float, m.groups())))


def detonation_velocity(case):
    text = open(os.path.join(case, "log.setCharge")).read()
    return float(re.search(r"D = (\S+) m/s", text).group(1))


def read_field(case, time, name, n):
    text = open(os.path.join(case, time, name)).read()
    body = text[text.index("internalField"):]
    m = re.match(r"internalField\s+uniform\s+([^;]+);", body)
    if m:
        return np.full(n, float(m.group(1)))
    m = re.match(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", body)
    vals = body[m.end():body.index(")", m.end())].split()
    return np.array(vals, dtype=float)


class Exact:
    """CJ state and Taylor wave of a JWL detonation from a closed wall."""

    def __init__(s, j, D, p0=101325.0):
        s.__dict__.update(j)
        s.D, s.p0 = D, p0
        v0 = 1/s.rho0
        e0 = s.E0/s.rho0

        def pref(V):
            w = s.omega
            return (s.A*(1 - w/(s.R1*V))*np.exp(-s.R1*V)
                    + s.B*(1 - w/(s.R2*V))*np.exp(-s.R2*V))

        def hugoniot(V):   # p on the products' Hugoniot at V = v/v0
            v, w = V*v0, s.omega
            return ((w/v*e0 + w*p0*(v0 - v)/(2*v) + pref(V))
                    / (1 - w*(v0 - v)/(2*v)))

        def D2(V):
            return (hugoniot(V) - p0)/(s.rho0**2*(v0 - V*v0))

        r = minimize_scalar(D2, bounds=(0.5, 0.99), method="bounded",
                            options={"xatol": 1e-12})
        s.VCJ, s.DCJ, s.pCJ = r.x, np.sqrt(D2(r.x)), hugoniot(r.x)
        # A burn faster than D_CJ drives a weak detonation: the lower
        # intersection of its Rayleigh line with the Hugoniot
        s.weak = D > s.DCJ*(1 + 1e-3)
        s.pFront = s.pCJ
        if s.weak:
            Vw = brentq(lambda V: D2(V) - D**2, s.VCJ, 0.9999)
            s.pFront = hugoniot(Vw)
        s.uCJ = s.DCJ*(1 - s.VCJ)
        s.C = (s.pCJ - s.A*np.exp(-s.R1*s.VCJ) - s.B*np.exp(-s.R2*s.VCJ)) \
            * s.VCJ**(1 + s.omega)
        s.Vp = brentq(s.u, s.VCJ, 10*s.VCJ)
        s.pp, s.cp = s.ps(s.Vp), s.c(s.Vp)

    def ps(s, V):
        return (s.A*np.exp(-s.R1*V) + s.B*np.exp(-s.R2*V)
                + s.C*V**(-1 - s.omega))

    def c(s, V):
        dp = (-s.A*s.R1*np.exp(-s.R1*V) - s.B*s.R2*np.exp(-s.R2*V)
              - (1 + s.omega)*s.C*V**(-2 - s.omega))
        return np.sqrt(-V*V*dp/s.rho0)

    def u(s, V):
        return s.uCJ - quad(lambda W: s.c(W)/W, s.VCJ, V)[0]

    def p(s, x, t):
        """Pressure at x, t after initiation at the wall."""
        xi = x/t
        if xi <= s.cp:
            return s.pp
        if xi >= s.D:
            return s.p0
        V = brentq(lambda V: s.u(V) + s.c(V) - xi, s.VCJ, s.Vp)
        return s.ps(V)


def analyse(case, t0, inert):
    j = jwl_from_log(case)
    D = detonation_velocity(case)
    ex = Exact(j, D)
    nx = int(re.search(r"nx\s+(\d+);",
                       open(os.path.join(case, "system/blockMeshDict")).read()).group(1))
    L = 0.12
    dx = L/nx
    x = (np.arange(nx) + 0.5)*dx
    times = sorted((d for d in os.listdir(case) if re.match(r"^[0-9.e+-]+$", d)
                    and d != "0" and os.path.isdir(os.path.join(case, d))), key=float)
    tag = f"{os.path.basename(case.rstrip('/'))} ({nx} cells)"
    print(f"{tag}: JWL CJ point D_CJ {ex.DCJ:.1f} m/s, p_CJ {ex.pCJ/1e9:.4f} GPa,"
          f" burn D {D:.1f} m/s; Taylor plateau p {ex.pp/1e9:.4f} GPa, c {ex.cp:.1f} m/s")
    if ex.weak:
        print(f"{tag}: burn D above D_CJ: weak detonation, front pressure "
              f"{ex.pFront/1e9:.4f} GPa; the Taylor wave below is the CJ "
              "isentrope's, printed but not checked")
    charge = x < 0.1
    p0 = read_field(case, "0", "p", nx)
    if inert:
        before = [t for t in times if float(t) <= t0 + 1e-12]
        dev = max(np.max(np.abs(read_field(case, t, "p", nx)[charge]/p0[charge] - 1))
                  for t in before)
        figure(f"{tag} charge pressure change until t0 = {t0:g} s "
               f"({len(before)} times, max |p/p0 - 1|)", dev, tol=TOL_INERT,
               ok=len(before) >= 3 and dev < TOL_INERT)
    after = [t for t in times if float(t) - t0 > 0.3*(float(times[-1]) - t0)]
    tf, xf = [], []
    for t in after:
        p = read_field(case, t, "p", nx)
        half = 0.5*ex.pFront
        i = np.nonzero(p > half)[0][-1]      # last cell above p_CJ/2
        xf.append(x[i] + (p[i] - half)/(p[i] - p[i + 1])*dx)
        tf.append(float(t) - t0)
    Dnum = np.polyfit(tf, xf, 1)[0]
    figure(f"{tag} detonation velocity (m/s)", Dnum, D, TOL_D, abs(Dnum/D - 1),
           abs(Dnum/D - 1) < TOL_D)
    t = float(after[-1]) - t0
    p = read_field(case, after[-1], "p", nx)
    peak = p.max()
    ePeak = abs(peak/ex.pFront - 1)
    figure(f"{tag} peak pressure behind the front (Pa)"
           + (" vs weak detonation" if ex.weak else " vs p_CJ"), peak,
           ex.pFront, TOL_PCJ, ePeak, ePeak < TOL_PCJ)
    wall = x < 0.5*ex.cp*t
    pPl = p[wall].mean()
    ePl = abs(pPl/ex.pp - 1)
    nc = " (not checked: weak)" if ex.weak else ""
    figure(f"{tag} Taylor-wave plateau pressure (Pa){nc}", pPl, ex.pp,
           TOL_PLATEAU, ePl, ex.weak or ePl < TOL_PLATEAU)
    # Extent: where p first rises 5 % above the plateau, numerical and exact
    rise = 1.05
    iN = np.nonzero(p > rise*pPl)[0][0]
    xN = x[iN - 1] + (rise*pPl - p[iN - 1])/(p[iN] - p[iN - 1])*dx
    Vr = brentq(lambda V: ex.ps(V) - rise*ex.pp, ex.VCJ, ex.Vp)
    xE = (ex.u(Vr) + ex.c(Vr))*t
    eX = abs(xN/xE - 1)
    figure(f"{tag} plateau extent to p = 1.05 p_plateau (m){nc}", xN, xE,
           TOL_PLATEAU, eX, ex.weak or eX < TOL_PLATEAU)
    print(f"{tag}: plateau end c_p t = {ex.cp*t:.5f} m at t - t0 = {t:.3g} s")
    inFan = x < 0.9*D*t
    pe = np.array([ex.p(xi, t) for xi in x[inFan]])
    l1 = np.abs(p[inFan] - pe).sum()/np.abs(pe).sum()
    print(f"{tag}: L1 pressure error behind the front (x < 0.9 D t) {l1:.4f}")
    return ePeak, l1


def main(args):
    t0, inert, refinement = 0.0, False, False
    while args and args[0].startswith("--"):
        a = args.pop(0)
        if a == "--t0":
            t0 = float(args.pop(0))
        elif a == "--inert":
            inert = True
        elif a == "--refinement":
            refinement = True
    results = [analyse(c, t0, inert) for c in args]
    if refinement:
        e = [r[0] for r in results]
        figure("peak pressure error fine/coarse (converging: < 1)",
               e[-1]/e[0], tol=1, ok=e[-1] < e[0])
        l = [r[1] for r in results]
        figure("L1 pressure error fine/coarse (converging: < 1)",
               l[-1]/l[0], tol=1, ok=l[-1] < l[0])
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
