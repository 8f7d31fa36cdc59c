#!/usr/bin/python3
"""jwlIbFoam test runner.

Runs two kinds of tests and prints one line per test, then 'N passed, N failed':
  - unit tests: GoogleTest executables built from tests/unit/<name>/ into
    $FOAM_USER_APPBIN; each GoogleTest case is one test, named
    unit/<executable>/<Suite.Case>. Figures recorded with RecordProperty are
    printed under the test line.
  - regression tests: executable scripts tests/regression/<name>.sh, run from a
    scratch directory tests/results/<name>/ (environment JWLIBFOAM_TEST_DIR);
    exit status 0 passes. Output lines starting with '>>' are the figures and
    are printed under the test line; the full log is tests/results/<name>.log.
Arguments select tests whose name contains any of them; -list lists names.
"""
import json, os, shutil, subprocess, sys, time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
results = os.path.join(root, "tests", "results")
appbin = os.environ.get("FOAM_USER_APPBIN", os.path.join(root, "platforms", "bin"))


def unit_executables():
    unitdir = os.path.join(root, "tests", "unit")
    names = sorted(d for d in os.listdir(unitdir)
                   if os.path.isdir(os.path.join(unitdir, d, "Make")))
    return names


def gtest_cases(exe):
    out = subprocess.run([exe, "--gtest_list_tests"], capture_output=True,
                         text=True).stdout
    cases, suite = [], None
    for line in out.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split()[0]
        else:
            cases.append(suite + line.split()[0])
    return cases


def selected(name, words):
    return not words or any(w.lower() in name.lower() for w in words)


def report(ok, name, seconds, figures):
    print(f"{'PASS' if ok else 'FAIL'}  {name}  ({seconds:.1f} s)", flush=True)
    for f in figures:
        print(f"        {f}", flush=True)


def run_unit(name, words, tally):
    exe = os.path.join(appbin, name)
    if not os.access(exe, os.X_OK):
        report(False, f"unit/{name}", 0, [f"executable {exe} not built"])
        tally[1] += 1
        return
    cases = [c for c in gtest_cases(exe) if selected(f"unit/{name}/{c}", words)]
    if not cases:
        return
    jsonfile = os.path.join(results, f"{name}.json")
    log = os.path.join(results, f"{name}.log")
    t0 = time.time()
    with open(log, "w") as fh:
        proc = subprocess.run([exe, "--gtest_filter=" + ":".join(cases),
                               "--gtest_output=json:" + jsonfile],
                              stdout=fh, stderr=subprocess.STDOUT, cwd=results)
    elapsed = time.time() - t0
    try:
        data = json.load(open(jsonfile))
    except (OSError, ValueError):
        report(False, f"unit/{name}", elapsed,
               [f"crashed (exit {proc.returncode}), see {log}"])
        tally[1] += 1
        return
    for suite in data.get("testsuites", []):
        for case in suite.get("testsuite", []):
            ok = not case.get("failures") and case.get("result") != "SKIPPED"
            secs = float(str(case.get("time", "0s")).rstrip("s") or 0)
            figures = [f"{k} = {v}" for k, v in case.items()
                       if k not in ("name", "file", "line", "status", "result",
                                    "timestamp", "time", "classname", "failures")]
            if not ok:
                for f in case.get("failures", []):
                    figures += f.get("failure", "").splitlines()[:6]
                if case.get("result") == "SKIPPED":
                    figures.append("skipped (counts as a failure)")
            report(ok, f"unit/{name}/{suite['name']}.{case['name']}", secs, figures)
            tally[0 if ok else 1] += 1


def run_regression(script, tally):
    name = os.path.basename(script)[:-3]
    workdir = os.path.join(results, name)
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    log = os.path.join(results, name + ".log")
    env = dict(os.environ, JWLIBFOAM_TEST_DIR=workdir)
    t0 = time.time()
    with open(log, "w") as fh:
        proc = subprocess.run(["bash", script], stdout=fh, stderr=subprocess.STDOUT,
                              cwd=workdir, env=env)
    elapsed = time.time() - t0
    text = open(log, errors="replace").read().splitlines()
    figures = [l[2:].strip() for l in text if l.startswith(">>")]
    ok = proc.returncode == 0
    if not ok:
        figures += [f"exit status {proc.returncode}; last lines of {log}:"] + text[-8:]
    report(ok, name, elapsed, figures)
    tally[0 if ok else 1] += 1


def main():
    args = sys.argv[1:]
    os.makedirs(results, exist_ok=True)
    regdir = os.path.join(root, "tests", "regression")
    scripts = sorted(os.path.join(regdir, f) for f in os.listdir(regdir)
                     if f.endswith(".sh"))
    if args and args[0] == "-list":
        for u in unit_executables():
            exe = os.path.join(appbin, u)
            for c in gtest_cases(exe) if os.access(exe, os.X_OK) else []:
                print(f"unit/{u}/{c}")
        for s in scripts:
            print(os.path.basename(s)[:-3])
        return 0
    tally = [0, 0]
    for u in unit_executables():
        run_unit(u, args, tally)
    for s in scripts:
        if selected(os.path.basename(s)[:-3], args):
            run_regression(s, tally)
    if sum(tally) == 0:
        print(f"no test matches {args}")
        tally[1] += 1
    print(f"{tally[0]} passed, {tally[1]} failed")
    return 0 if tally[1] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
