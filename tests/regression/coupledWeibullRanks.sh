#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks)
# Regression (coupled, issue 16): random joint strengths (strengthDistribution
# Weibull) are the same serial and on 2 ranks, and they are the ones the
# solid breaks by. The crackVenting plate (1 MPa driver gas, it cracks from
# about 46 us) with Weibull strengths, two parameter sets (modulus 4 seed 7,
# modulus 12 seed 2024), serial and on 2 ranks (simple 2 x 1, the cut
# through the plate) to 0.1 ms. Checks, per set:
# - the solver's strength report (jwlIbFoam log: joints, mean, coefficient
#   of variation, min, max, a digest of every factor's bits) is the same
#   serial and on 2 ranks, where every rank computed its own and the master
#   found them equal ('the same on all 2 ranks');
# - the sample's mean and coefficient of variation within 4 standard errors
#   of the Weibull law's (mean 1, CoV sqrt(G(1+2/m)/G(1+1/m)^2 - 1));
# - the broken joints at 0.1 ms: serial = rank 0 = rank 1 (femdemState);
# - the strengths are the ones used: the broken joints' mean factor
#   (VTK/cracks_*.vtp CellData strengthFactor) is below the sample's mean,
#   and the two sets break different joints.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData/crackVenting
for set in "4 7" "12 2024"; do
    read -r m seed <<< "$set"
    case=weibull_m${m}_s${seed}
    rm -rf "$case" && cp -r "$data" "$case" && cd "$case" || exit 1
    sed -i "s/GI 20; GII 100; dampingRatio 0.2;/&\n        strengthDistribution { type Weibull; modulus $m; seed $seed; }/" constant/femdemProperties
    grep -q "modulus $m;" constant/femdemProperties || { echo ">> could not set the strength distribution  <-- FAIL"; exit 1; }
    sed -i 's/^endTime .*/endTime 1e-4;/; s/^writeInterval .*/writeInterval 5e-5;/' system/controlDict
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n' > system/decomposeParDict
    blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 && setFields > log.setFields 2>&1 || exit 1
    rm -rf ../"$case"_np2 && cp -r . ../"$case"_np2
    start=$(date +%s)
    jwlIbFoam > log.jwlIbFoam 2>&1 || { tail -5 log.jwlIbFoam; echo ">> $case serial: jwlIbFoam failed  <-- FAIL"; exit 1; }
    cd ../"$case"_np2 || exit 1
    decomposePar > log.decomposePar 2>&1 || exit 1
    timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 jwlIbFoam -parallel > log.jwlIbFoam 2>&1 \
        || { tail -5 log.jwlIbFoam; echo ">> $case 2 ranks: jwlIbFoam failed  <-- FAIL"; exit 1; }
    echo ">> $case: serial and 2 ranks to 0.1 ms in $(( $(date +%s) - start )) s wall"
    cd ..
done

/usr/bin/python3 - <<'PY'
import glob, math, os, re, sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_PROJECT"], "tests", "regression", "coupledData"))
sys.path.insert(0, os.path.join(os.environ["JWLIBFOAM_TUTORIALS"], "jwlIbFoam", "common"))
import budget as budgetFile
import blastVtk

def report_line(log):
    for line in open(log):
        if line.startswith("Joint strengths"):
            return line.strip()
    return None

def numbers(line):
    m = re.search(r": (\d+) joints, factor mean (\S+), coefficient of variation (\S+),"
                  r" min (\S+), max (\S+), digest ([0-9a-f]{16})", line)
    return (int(m.group(1)), float(m.group(2)), float(m.group(3)), float(m.group(4)),
            float(m.group(5)), m.group(6)) if m else None

def broken(state):
    """The broken list of a femdemState (0/1 per joint)"""
    text = open(state).read()
    m = re.search(r"\nbroken\s+(?:List<bool>\s+)?(\d+)\s*\(([^)]*)\)", text)
    if m:
        return np.array([int(t) for t in m.group(2).split()], dtype=int)
    m = re.search(r"\nbroken\s+(?:List<bool>\s+)?(\d+)\s*\{\s*(\d)\s*\}", text)   # uniform list
    return np.full(int(m.group(1)), int(m.group(2))) if m else None

res, sets = [], {}
for m, seed in ((4, 7), (12, 2024)):
    case = f"weibull_m{m}_s{seed}"
    s, p = report_line(f"{case}/log.jwlIbFoam"), report_line(f"{case}_np2/log.jwlIbFoam")
    print(f">> {case} serial:  {s}")
    print(f">> {case} 2 ranks: {p}")
    ok = s is not None and p is not None and numbers(s) is not None
    res.append((f"{case}: strength reports missing or unreadable", 0 if ok else 1, 0, "<="))
    if not ok:
        continue
    same = p.startswith(s + ";") and p.endswith("the same on all 2 ranks")
    res.append((f"{case}: serial report differs from the 2 ranks' (both ranks checked by the master)",
                0 if same else 1, 0, "<="))
    n, mean, cv, lo, hi, digest = numbers(s)
    g1, g2 = math.gamma(1 + 1 / m), math.gamma(1 + 2 / m)
    cvLaw = math.sqrt(g2 / g1 ** 2 - 1)
    res.append((f"{case}: |sample mean - 1| / standard error ({n} joints)",
                abs(mean - 1) / (cvLaw / math.sqrt(n)), 4, "<="))
    res.append((f"{case}: |sample CoV - {cvLaw:.4f}| / standard error",
                abs(cv - cvLaw) / (cvLaw * math.sqrt((1 + 2 * cvLaw ** 2) / (2 * n))), 4, "<="))
    bs = broken(f"{case}/0.0001/uniform/femdemState")
    diffs = 0 if bs is not None else 1
    for r in (0, 1):
        bp = broken(f"{case}_np2/processor{r}/0.0001/uniform/femdemState")
        diffs += 1 if bp is None or bs is None or bp.shape != bs.shape else int((bp != bs).sum())
    res.append((f"{case}: broken joints at 0.1 ms serial", int(bs.sum()) if bs is not None else 0, 1, ">="))
    res.append((f"{case}: joints broken differently on rank 0 or 1 than serial", diffs, 0, "<="))
    vtp = sorted(glob.glob(f"{case}/VTK/cracks_*.vtp"), key=lambda f: int(re.findall(r"\d+", f)[-1]))[-1]
    w = blastVtk.read_vtp_line_fields(vtp).get("strengthFactor", np.zeros(0))
    res.append((f"{case}: crack lines with strengthFactor in {os.path.basename(vtp)}", w.size, 1, ">="))
    if w.size:
        res.append((f"{case}: broken joints' mean factor / all joints' (weak joints break first)",
                    w.mean() / mean, 1, "<="))
    sets[(m, seed)] = bs
a, b = sets.get((4, 7)), sets.get((12, 2024))
if a is not None and b is not None:
    res.append(("joints broken differently by the two strength sets at 0.1 ms", int((a != b).sum()), 1, ">="))
sys.exit(1 if budgetFile.report(res) else 0)
PY
