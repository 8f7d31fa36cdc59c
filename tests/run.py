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

Tests run side by side on the machine's cores (JWLIBFOAM_TEST_JOBS overrides
the count; 1 runs them one after the other). A regression script that keeps
more than one core busy (mpirun -np 2, two solvers at once) says so in a
header line '# testCores: N' and runs only when N cores are free, so no run is
oversubscribed. The longest tests start first: their durations of the last
run (tests/results/durations.json) or, on a new machine, tests/durations.json.
Each test's line is printed when it ends.
"""
import json, os, shutil, subprocess, sys, threading, time

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


printLock = threading.Lock()


def report(ok, name, seconds, figures, tally):
    """One test's line and figures, printed whole; counted in tally"""
    with printLock:
        print(f"{'PASS' if ok else 'FAIL'}  {name}  ({seconds:.1f} s)", flush=True)
        for f in figures:
            print(f"        {f}", flush=True)
        tally[0 if ok else 1] += 1


def run_unit(name, words, tally):
    exe = os.path.join(appbin, name)
    if not os.access(exe, os.X_OK):
        report(False, f"unit/{name}", 0, [f"executable {exe} not built"], tally)
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
    durations[f"unit/{name}"] = elapsed
    try:
        data = json.load(open(jsonfile))
    except (OSError, ValueError):
        report(False, f"unit/{name}", elapsed,
               [f"crashed (exit {proc.returncode}), see {log}"], tally)
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
            report(ok, f"unit/{name}/{suite['name']}.{case['name']}", secs, figures,
                   tally)


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
    durations[name] = elapsed
    if not ok:
        figures += [f"exit status {proc.returncode}; last lines of {log}:"] + text[-8:]
    report(ok, name, elapsed, figures, tally)
    return elapsed


durations = {}


def script_cores(script):
    """The cores a regression script keeps busy: its '# testCores: N' line"""
    for line in open(script, errors="replace"):
        m = line.split("# testCores:")
        if len(m) == 2:
            return max(1, int(m[1].split()[0]))
    return 1


def known_durations():
    """Seconds per test of the last run here, else the tracked estimates"""
    known = {}
    for f in (os.path.join(root, "tests", "durations.json"),
              os.path.join(results, "durations.json")):
        try:
            known.update(json.load(open(f)))
        except (OSError, ValueError):
            pass
    return known


def save_durations():
    known = known_durations()
    known.update(durations)
    with open(os.path.join(results, "durations.json"), "w") as fh:
        json.dump(known, fh, indent=1, sort_keys=True)


def run_jobs(jobs, tally):
    """Run (name, cores, function) jobs on the free cores, longest first.
    A job waits until its cores are free; the others may pass it meanwhile
    only if they fit beside the jobs running (no oversubscription)"""
    slots = int(os.environ.get("JWLIBFOAM_TEST_JOBS", 0) or os.cpu_count() or 1)
    slots = max(1, slots)
    known = known_durations()
    pending = sorted(jobs, key=lambda j: -known.get(j[0], 30.0))
    free = [slots]
    cond = threading.Condition()
    threads = []

    def work(name, cores, fn):
        try:
            fn()
        except Exception as e:   # the runner's own failure: a failed test, not a hang
            report(False, name, 0, [f"test runner error: {e!r}"], tally)
        finally:
            with cond:
                free[0] += cores
                cond.notify_all()

    with cond:
        while pending:
            # the first pending job that fits the free cores
            pick = next((j for j in pending if min(j[1], slots) <= free[0]), None)
            if pick is None:
                cond.wait()
                continue
            pending.remove(pick)
            cores = min(pick[1], slots)
            free[0] -= cores
            t = threading.Thread(target=work, args=(pick[0], cores, pick[2]))
            t.start()
            threads.append(t)
    for t in threads:
        t.join()


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
    jobs = [(f"unit/{u}", 1, lambda u=u: run_unit(u, args, tally))
            for u in unit_executables()]
    jobs += [(os.path.basename(s)[:-3], script_cores(s),
              lambda s=s: run_regression(s, tally))
             for s in scripts if selected(os.path.basename(s)[:-3], args)]
    run_jobs(jobs, tally)
    save_durations()
    if sum(tally) == 0:
        print(f"no test matches {args}")
        tally[1] += 1
    print(f"{tally[0]} passed, {tally[1]} failed")
    return 0 if tally[1] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
