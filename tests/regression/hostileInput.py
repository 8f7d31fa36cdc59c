#!/usr/bin/python3
"""Generated hostile-input suite (issue 17): mutate every input file of the
bad-input base cases and judge what the program that reads it does.

    hostileInput.py run BASES WORK [-j 2] [-timeout 20] [-json FILE]
    hostileInput.py doc JSON DOCFILE

run: for each target (base case, input file, program) of TARGETS, generate
the mutations of the file (MUTATION KINDS below), apply each to a fresh copy
of the base case in WORK, run the program with a time limit, 2 at a time,
and judge the outcome (JUDGEMENT below). Prints '>>' lines: mutations per
kind, outcomes per kind and program, every failure, a summary; exit status 1
if any mutation failed or a base case does not run. doc: rewrites the
generated section of doc/badInput.md from the JSON written by run.

MUTATION KINDS (per file; entries at every level except inside FoamFile)
  empty           the file with 0 bytes
  headerOnly      only the FoamFile header left
  truncated       the file cut at 1/5, 2/5, 3/5 and 4/5 of its length
  removeEntry     each entry removed (FoamFile too)
  number=V        the first number of each entry (and the first inside its
                  list when that is another one, e.g. a list size and its
                  first element) set to V = 0, -1, NaN, 1e300 and a word
  unknownWord     an entry whose value is one word set to an unknown word
  shortenList     the first list of each entry loses its last element (its
                  size, if given, is decremented to match)
  duplicateEntry  each entry repeated (same keyword, same value)
  duplicateName   the first word of each list of words repeated
A gmsh file (not a dictionary) gets empty, truncated, each line removed
(removeLine) and the first number of each line set to V (number=V).

JUDGEMENT (a mutation passes when every point holds)
  - the program ends within the time limit (else 'hang'), except a run
    whose endTime was made larger: still advancing in time after 4 s is a
    pass ('long run');
  - no signal, no 'Segmentation'/'Floating point exception'/stack trace;
  - exit 0: then no nan/inf in the files it wrote, and a word or NaN in
    place of a number must not have been accepted ('silent': the entry was
    not read, or read as something else); a duplicated entry is accepted
    only in files read by OpenFOAM itself (controlDict, fvSchemes,
    fvSolution, decomposeParDict, fields), where OpenFOAM merges repeated
    keywords, and for a second FoamFile header (OpenFOAM ignores it); the
    project's own dictionaries refuse them;
  - exit != 0: a FOAM FATAL (IO) ERROR whose text names the file (its path
    relative to the case, or its name and its directory as words) and, for
    a mutation of one entry, the entry: its keyword, the duplicated name,
    'header' for FoamFile, for a removed entry its parent's or one of its
    own entries' keywords, or a line of the entry ('at line N', OpenFOAM's
    reader); for the gmsh file the section of the line;
  - files of the case that existed before (inputs, written time
    directories) are unchanged; on success the program may rewrite only the
    files it rewrites on the unbroken base (its outputs, found by a run of
    the base).
Findings of OpenFOAM's own programs (decomposePar) are printed as OpenFOAM
limitations and not counted; every other finding fails the test.
"""
import concurrent.futures as cf
import hashlib, json, os, re, shutil, signal, subprocess, sys, time
from collections import Counter, defaultdict

def each(base, cmd, *files):
    """(base case, file relative to the case, program command) targets."""
    return [(base, f, cmd.split()) for f in files]


TARGETS = (
    each("sod", "jwlIbFoam", "system/controlDict",
         "system/blastFluidProperties", "system/fvSchemes", "system/fvSolution",
         "constant/thermophysicalProperties", "0/U", "0/p", "0/rho")
    + each("sod", "exactRiemann", "system/exactRiemannDict")
    + each("restart", "jwlIbFoam", "0.02/rhoU", "0.02/rhoE", "0.02/rho",
           "0.02/p", "0.02/U")
    + each("tnt", "setCharge", "system/setChargeDict",
           "constant/thermophysicalProperties")
    + each("tntCharged", "jwlIbFoam", "constant/thermophysicalProperties",
           "0/alpha.products", "0/rho.air", "0/rho.products", "0/p", "0/U")
    + each("tntCharged", "decomposePar", "system/decomposeParDict")
    + each("box", "femdemMesh", "system/femdemMeshDict")
    + each("box", "jwlIbFoam", "constant/femdemProperties",
           "constant/immersedBodyProperties", "constant/solidMesh",
           "system/controlDict")
    + each("boxRestart", "jwlIbFoam", "4e-06/uniform/femdemState",
           "4e-06/fluidFraction", "4e-06/alpha.solid")
    + each("bar", "femdemMesh", "system/femdemMeshDict")
    + each("bar", "femdemFoam", "constant/femdemProperties",
           "system/controlDict", "constant/solidMesh")
    + each("bar", "femdemMeshCheck", "constant/solidMesh")
    + each("barRestart", "femdemFoam", "4e-06/femdemState")
    + each("square", "gmshToFemdem square.msh", "square.msh")
)

# Files read by OpenFOAM's own classes, where a repeated keyword is merged
OPENFOAM_FILES = re.compile(
    r"(controlDict|fvSchemes|fvSolution|decomposeParDict)$|^[0-9.e+-]+/[^/]+$")
# OpenFOAM's own programs among the targets: their findings are printed
# and documented as OpenFOAM limitations, not counted (the project cannot
# change them; doc/badInput.md lists them)
OPENFOAM_PROGRAMS = {"decomposePar"}
# Entries whose larger value only makes the run longer
RUN_LENGTH = {"endTime"}
VALUES = ["0", "-1", "NaN", "1e300", "foo"]

# ------------------------------------------------------------------ parser
TOKEN = re.compile(r'''
    (?P<ws>\s+) | (?P<lc>//[^\n]*) | (?P<bc>/\*.*?\*/) |
    (?P<str>"(?:[^"\\]|\\.)*") | (?P<punct>[(){}\[\];]) |
    (?P<dir>\#[A-Za-z]+) | (?P<word>[^\s(){}\[\];"]+)''', re.X | re.S)


def tokenize(text):
    toks, pos = [], 0
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:          # unterminated string or comment: rest is a word
            toks.append(("word", text[pos:], pos, len(text)))
            break
        kind = m.lastgroup
        if kind not in ("ws", "lc", "bc"):
            s = m.group()
            if kind == "word" and is_number(s):
                kind = "num"
            toks.append((kind, s, m.start(), m.end()))
        pos = m.end()
    return toks


def is_number(s):
    try:
        float(s)
    except ValueError:
        return False
    return s.lower().lstrip("+-") not in ("nan", "inf", "infinity")


class Entry:
    def __init__(self, path, key, start):
        self.path, self.key, self.start = path, key, start
        self.end, self.kind, self.vtoks, self.children = start, "prim", [], []


def parse(toks, i=0, prefix="", closer=None):
    """Entries from toks[i] up to the closing '}' (closer) or the end."""
    entries = []
    while i < len(toks):
        kind, s, a, b = toks[i]
        if kind == "punct" and s == "}" and closer:
            return entries, i
        if kind == "dir":          # '#include "file"' and the like
            i += 2
            continue
        if kind not in ("word", "str"):
            i += 1
            continue
        e = Entry(prefix + s, s, a)
        if i + 1 < len(toks) and toks[i + 1][1] == "{":
            e.kind = "dict"
            e.children, j = parse(toks, i + 2, e.path + ".", "}")
            e.end = toks[j][3] if j < len(toks) else toks[-1][3]
            entries.append(e)
            i = j + 1
            continue
        i = parse_value(toks, i + 1, e)
        entries.append(e)
    return entries, i


def parse_value(toks, i, e):
    """The tokens of a primitive entry up to its ';' (dicts in lists are
    children: 'charges ( circle { ... } );')."""
    depth = 0
    while i < len(toks):
        kind, s, a, b = toks[i]
        if kind == "punct":
            if s == ";" and depth == 0:
                e.end = b
                return i + 1
            if s in "([{":
                depth += 1
            elif s in ")]}":
                if depth == 0:           # unbalanced: end of the entry
                    e.end = a
                    return i
                depth -= 1
        elif (kind in ("word", "str") and depth > 0 and i + 1 < len(toks)
              and toks[i + 1][1] == "{"):
            c = Entry(e.path + "." + s, s, a)
            c.kind = "dict"
            c.children, j = parse(toks, i + 2, c.path + ".", "}")
            c.end = toks[j][3] if j < len(toks) else toks[-1][3]
            e.children.append(c)
            i = j + 1
            continue
        e.vtoks.append(toks[i])
        e.end = b
        i += 1
    return i


def walk(entries):
    for e in entries:
        yield e
        if e.key != "FoamFile":
            yield from walk(e.children)


# --------------------------------------------------------------- mutations
def splice(text, a, b, new):
    return text[:a] + new + text[b:]


def list_elements(vtoks, k):
    """(first, last token index) of the elements of the list opened at
    vtoks[k], and the index of its closer."""
    elems, depth, start = [], 0, None
    for j in range(k + 1, len(vtoks)):
        s = vtoks[j][1]
        if vtoks[j][0] == "punct" and s in "([{":
            if depth == 0:
                start = j
            depth += 1
        elif vtoks[j][0] == "punct" and s in ")]}":
            if depth == 0:
                return elems, j
            depth -= 1
            if depth == 0:
                elems.append((start, j))
        elif depth == 0:
            elems.append((j, j))
    return elems, len(vtoks)


def entry_mutations(text, e):
    """(kind, entry path, new text) for one entry."""
    out = [("removeEntry", e.path, splice(text, e.start, e.end, ""))]
    copy = text[e.start:e.end]
    out.append(("duplicateEntry", e.path,
                splice(text, e.end, e.end, "\n" + copy)))
    if e.key == "FoamFile":
        return out
    v = e.vtoks
    nums = [t for t in v if t[0] == "num"]
    opener = next((k for k, t in enumerate(v)
                   if t[0] == "punct" and t[1] in "(["), None)
    targets = nums[:1]
    if opener is not None:
        inner = next((t for t in v[opener:] if t[0] == "num"), None)
        if inner and inner not in targets:
            targets.append(inner)
    for t in targets:
        for val in VALUES:
            out.append(("number=" + val, e.path, splice(text, t[2], t[3], val)))
    if len(v) == 1 and v[0][0] == "word":
        out.append(("unknownWord", e.path,
                    splice(text, v[0][2], v[0][3], "hostileWord")))
    if opener is not None:
        elems, close = list_elements(v, opener)
        count = v[opener - 1] if opener > 0 and v[opener - 1][0] == "num" \
            and re.fullmatch(r"\d+", v[opener - 1][1]) else None
        if elems:
            a, b = v[elems[-1][0]][2], v[elems[-1][1]][3]
            if len(elems) > 1:
                a = v[elems[-2][1]][3]
            new = splice(text, a, b, "")
            if count:
                new = splice(new, count[2], count[3], str(int(count[1]) - 1))
            out.append(("shortenList", e.path, new))
            words = [v[x] for x, y in elems if x == y and v[x][0] == "word"]
            if len(words) == len(elems):
                w = words[0]
                new = splice(text, w[3], w[3], " " + w[1])
                if count:
                    new = splice(new, count[2], count[3],
                                 str(int(count[1]) + 1))
                out.append(("duplicateName", e.path + ":" + w[1], new))
    # a uniform list 'N{v}' of a size N: shortened by its size
    for k in range(len(v) - 1):
        if v[k][0] == "num" and v[k + 1][1] == "{" and opener is None:
            out.append(("shortenList", e.path, splice(
                text, v[k][2], v[k][3], str(max(int(float(v[k][1])) - 1, 0)))))
            break
    return out


def file_mutations(text):
    """Every (kind, entry or None, new text) of a dictionary file."""
    out = [("empty", None, "")]
    n = len(text)
    for k in range(1, 5):
        out.append(("truncated", None, text[:n * k // 5]))
    entries, _ = parse(tokenize(text))
    header = next((e for e in entries if e.key == "FoamFile"), None)
    if header:
        out.append(("headerOnly", None, text[:header.end] + "\n"))
    out = [o + (None, []) for o in out]
    for e in walk(entries):
        lines = (text.count("\n", 0, e.start) + 1,
                 text.count("\n", 0, e.end) + 1)
        for kind, path, new in entry_mutations(text, e):
            out.append((kind, path, new, lines, entry_names(kind, path, e)))
    return out


def entry_names(kind, path, e):
    """Words of which one names the entry in an error message: its
    keyword; the header for FoamFile; a duplicated name; for a removed
    entry also its parent's keyword ('no solids in entry solids') and its
    own entries' keywords (a required entry of it is missing)."""
    names = [e.key, "header"] if e.key == "FoamFile" else [e.key]
    if kind == "duplicateName":
        names.append(path.split(":")[-1])
    if kind == "removeEntry":
        names += path.split(".")[:-1] + [c.key for c in e.children]
    return names


def gmsh_mutations(text):
    out = [("empty", None, "", None)]
    n = len(text)
    for k in range(1, 5):
        out.append(("truncated", None, text[:n * k // 5], None))
    out = [o + ([],) for o in out]
    lines = text.splitlines(True)
    section = ""
    for i, line in enumerate(lines):
        if line.startswith("$") and not line.startswith("$End"):
            section = line.strip()
        names = [section, section[1:]]
        rest = lines[:i] + lines[i + 1:]
        out.append(("removeLine", f"line {i + 1}", "".join(rest), (i + 1,) * 2,
                    names))
        m = re.search(r"-?\d+(\.\d*)?([eE][-+]?\d+)?", line)
        if m and not line.startswith("$"):
            for val in VALUES:
                new = line[:m.start()] + val + line[m.end():]
                out.append(("number=" + val, f"line {i + 1}",
                            "".join(lines[:i] + [new] + lines[i + 1:]),
                            (i + 1,) * 2, names))
    return out


# --------------------------------------------------------------- judging
def snapshot(case, stamps=None):
    """md5 of every file of the case except logs (and their mtimes into
    stamps)."""
    sums = {}
    for root, dirs, files in os.walk(case):
        for f in files:
            if f.startswith("log."):
                continue
            p = os.path.join(root, f)
            with open(p, "rb") as fh:
                sums[os.path.relpath(p, case)] = hashlib.md5(fh.read()).hexdigest()
            if stamps is not None:
                stamps[os.path.relpath(p, case)] = os.stat(p).st_mtime_ns
    return sums


def run(cmd, case, timeout):
    """(exit status or None on time-out, log text, seconds)."""
    t0 = time.time()
    with open(os.path.join(case, "log.run"), "w") as log:
        try:
            proc = subprocess.Popen(cmd, cwd=case, stdout=log,
                                    stderr=subprocess.STDOUT,
                                    start_new_session=True)
        except OSError as e:          # counted as a failure
            return -1000, f"cannot start {cmd[0]}: {e}", 0.0
        try:
            rc = proc.wait(timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            rc = None
    with open(os.path.join(case, "log.run"), errors="replace") as fh:
        return rc, fh.read(), time.time() - t0


CRASH = re.compile(r"segmentation|sigsegv|sigfpe|floating point exception|"
                   r"core dumped|stack trace|sigabrt|terminate called", re.I)
NONFINITE = re.compile(rb"(?<![A-Za-z])(nan|-?inf)(?![A-Za-z])", re.I)


def named(text, word):
    return re.search(r"(?<![A-Za-z0-9_])" + re.escape(word)
                     + r"(?![A-Za-z0-9_])", text) is not None


def names_file(err, file):
    """The path relative to the case, or its name and its directory."""
    d, b = os.path.split(file)
    return file in err or (named(err, b) and (not d or named(err, d)))


def names_line(err, lines):
    """OpenFOAM's reader points to the entry by a line of the file."""
    if not lines:
        return False
    for a, b in re.findall(r"(?:at|on|from) line (\d+)(?: to line (\d+))?", err):
        lo, hi = int(a), int(b or a)
        if lo <= lines[1] and hi >= lines[0]:
            return True
    return False


def judge(m, rc, log, before, after, outputs, case):
    """List of problems (empty: pass) and the outcome word."""
    problems = []
    kind, file, entry = m["kind"], m["file"], m["entry"]
    key = entry.split(":")[-1].split(".")[-1] if entry else None
    if rc is None:
        steps = re.findall(r"^Time = (\S+)", log, re.M)
        if key in RUN_LENGTH and len(steps) > 2:
            return [], "long run"
        return ["hang (killed after the time limit)"], "hang"
    if rc < 0 or rc >= 128 or CRASH.search(re.sub(r"^trapFpe.*$", "", log,
                                                  flags=re.M)):
        problems.append(f"crash (exit {rc})")
    changed = [f for f in before if after.get(f) != before[f]]
    if rc == 0:
        changed = [f for f in changed if f not in outputs]
        written = [f for f in after if after[f] != before.get(f)]
        for f in written:
            p = os.path.join(case, f)
            if os.path.getsize(p) < 4e6:
                with open(p, "rb") as fh:
                    if NONFINITE.search(fh.read()):
                        problems.append(f"exit 0 with nan/inf in {f}")
                        break
        if kind in ("number=NaN", "number=foo"):
            problems.append("silent: exit 0 with a word in place of a number")
        if kind == "duplicateEntry" and not OPENFOAM_FILES.search(file) \
           and key != "FoamFile":
            problems.append("silent: exit 0 with a duplicated entry")
        if kind == "duplicateName":
            problems.append("silent: exit 0 with a duplicated name in a list")
        outcome = "runs"
    else:
        err = log[log.find("FOAM FATAL"):] if "FOAM FATAL" in log else ""
        if not err:
            problems.append(f"exit {rc} without a FOAM FATAL ERROR")
        else:
            if not names_file(err, file):
                problems.append(f"error does not name the file {file}")
            if key and not any(named(err, k) for k in m["names"]) \
               and not names_line(err, m["lines"]):
                problems.append(f"error does not name the entry '{key}'")
        outcome = "error"
    if changed:
        problems.append("changed existing files: " + " ".join(changed[:4]))
    return problems, outcome


# --------------------------------------------------------------- running
def prepare(bases, work, name, base):
    case = os.path.join(work, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(bases, base), case, symlinks=True)
    for f in os.listdir(case):
        if f.startswith("log."):
            os.remove(os.path.join(case, f))
    return case


def baseline(bases, work, timeout):
    """Outputs of each (base, program) and whether each base runs."""
    outputs, bad = {}, []
    for base, cmd in sorted({(b, tuple(c)) for b, f, c in TARGETS}):
        case = prepare(bases, work, f"baseline-{base}-{cmd[0]}", base)
        t0, t1 = {}, {}
        before = snapshot(case, t0)
        rc, log, secs = run(list(cmd), case, timeout)
        after = snapshot(case, t1)
        outputs[(base, cmd)] = {f for f in before if after.get(f) != before[f]
                                or t1.get(f) != t0[f]}
        print(f">> base {base}: {' '.join(cmd)} exit {rc} in {secs:.2f} s, "
              f"rewrites {len(outputs[(base, cmd)])} existing files", flush=True)
        if rc != 0:
            bad.append(base)
            print(log[-2000:])
        shutil.rmtree(case)
    return outputs, bad


def mutations(bases):
    ms = []
    for base, file, cmd in TARGETS:
        with open(os.path.join(bases, base, file), errors="replace") as fh:
            text = fh.read()
        gen = gmsh_mutations if file.endswith(".msh") else file_mutations
        for kind, entry, new, lines, names in gen(text):
            ms.append(dict(id=len(ms), base=base, file=file, cmd=cmd,
                           kind=kind, entry=entry, text=new, lines=lines,
                           names=names))
    return ms


def one(m, bases, work, timeout, outputs):
    case = prepare(bases, work, f"m{m['id']:05d}", m["base"])
    with open(os.path.join(case, m["file"]), "w") as fh:
        fh.write(m["text"])
    before = snapshot(case)
    # a longer run is expected: a few seconds show whether it advances
    longer = m["kind"] == "number=1e300" and \
        (m["entry"] or "").split(".")[-1] in RUN_LENGTH
    rc, log, secs = run(m["cmd"], case, min(timeout, 4) if longer else timeout)
    after = snapshot(case)
    problems, outcome = judge(m, rc, log, before, after,
                              outputs[(m["base"], tuple(m["cmd"]))], case)
    err = ""
    if "FOAM FATAL" in log:
        lines = [l.strip() for l in log[log.find("FOAM FATAL"):].splitlines()[1:]
                 if l.strip()]
        err = lines[0][:160] if lines else ""
    if not problems:
        shutil.rmtree(case)
    return dict(id=m["id"], base=m["base"], file=m["file"], prog=m["cmd"][0],
                kind=m["kind"], entry=m["entry"], rc=rc, outcome=outcome,
                problems=problems, message=err, seconds=round(secs, 3),
                case=case)


def main_run(args):
    bases, work = args[0], args[1]
    jobs = int(opt(args, "-j", 2))
    timeout = float(opt(args, "-timeout", 20))
    jsonfile = opt(args, "-json", os.path.join(work, "results.json"))
    os.makedirs(work, exist_ok=True)
    os.environ["FOAM_SIGFPE"] = "true"
    outputs, bad = baseline(bases, work, timeout)
    if bad:
        print(">> base cases do not run: " + " ".join(bad))
        return 1
    ms = mutations(bases)
    t0 = time.time()
    with cf.ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(lambda m: one(m, bases, work, timeout, outputs),
                                ms))
    report(results, time.time() - t0, jobs)
    with open(jsonfile, "w") as fh:
        json.dump(results, fh, indent=0)
    return 1 if any(counted(r) for r in results) else 0


def counted(r):
    """A failure of the project's code (not of an OpenFOAM program)."""
    return bool(r["problems"]) and r["prog"] not in OPENFOAM_PROGRAMS


def report(results, secs, jobs):
    kinds = Counter(r["kind"] for r in results)
    print(f">> {len(results)} mutations of {len(TARGETS)} (case, file, "
          f"program) targets in {secs:.0f} s ({jobs} at a time)")
    for k in sorted(kinds):
        o = Counter(r["outcome"] for r in results if r["kind"] == k)
        nf = sum(1 for r in results if r["kind"] == k and counted(r))
        print(f">> kind {k}: {kinds[k]} mutations, {o['error']} errors, "
              f"{o['runs']} runs, {o['long run']} long runs, {o['hang']} "
              f"hangs, {nf} failed")
    progs = Counter(r["prog"] for r in results)
    for p in sorted(progs):
        nf = sum(1 for r in results if r["prog"] == p and counted(r))
        print(f">> program {p}: {progs[p]} mutations, {nf} failed")
    classes = Counter()
    for r in filter(counted, results):
        for p in r["problems"]:
            classes[re.sub(r"( in | files: | the file | entry ).*", r"\1...",
                           p)] += 1
    for c, n in classes.most_common():
        print(f">> finding: {n} x {c}")
    foam = [r for r in results if r["problems"] and not counted(r)]
    for r in foam:
        print(f">> OpenFOAM limitation (not counted): {r['prog']} {r['file']} "
              f"{r['kind']} {r['entry'] or ''}: {'; '.join(r['problems'])} "
              f"[{r['message'][:100]}]")
    failed = [r for r in results if counted(r)]
    for r in failed[:300]:
        print(f">> FAIL {r['base']} {r['file']} {r['prog']} {r['kind']} "
              f"{r['entry'] or ''}: {'; '.join(r['problems'])} "
              f"[{r['message'][:100]}] ({r['case']})")
    nsig = sum(1 for r in failed if any("crash" in p for p in r["problems"]))
    nhang = sum(1 for r in failed if any("hang" in p for p in r["problems"]))
    nchg = sum(1 for r in failed if any("changed" in p for p in r["problems"]))
    print(f">> summary: {len(results)} mutations, {len(failed)} failed "
          f"({nsig} signals, {nhang} hangs, {nchg} changed files), "
          f"{len(foam)} OpenFOAM limitations not counted")


def opt(args, name, default):
    return args[args.index(name) + 1] if name in args else default


# --------------------------------------------------------------- doc
BEGIN = "<!-- hostileInput: generated by tests/regression/hostileInput.py doc -->"
END = "<!-- hostileInput: end -->"


def main_doc(args):
    results = json.load(open(args[0]))
    lines = [BEGIN, "", "## Generated hostile-input suite", ""]
    lines += doc_text(results)
    lines += ["", END]
    doc = open(args[1]).read()
    if BEGIN in doc:
        a, b = doc.index(BEGIN), doc.index(END) + len(END)
        doc = doc[:a] + "\n".join(lines) + doc[b:]
    else:
        doc = doc.rstrip("\n") + "\n\n" + "\n".join(lines) + "\n"
    open(args[1], "w").write(doc)
    return 0


def doc_text(results):
    n = len(results)
    failed = sum(1 for r in results if counted(r))
    out = [f"`tests/regression/hostileInput.sh` (`./Alltest hostileInput`) "
           f"generates {n} mutations of the input files below and runs the "
           f"program that reads each ({failed} failed in the run this table "
           f"was written from). Mutation kinds and judgement: the docstring "
           f"of `tests/regression/hostileInput.py`.", "",
           "| case | file | program | mutations | errors | runs | failed "
           "(OpenFOAM limitations) |", "|---|---|---|---|---|---|---|"]
    groups = defaultdict(list)
    for r in results:
        groups[(r["base"], r["file"], r["prog"])].append(r)
    for (b, f, p), rs in groups.items():
        o = Counter(r["outcome"] for r in rs)
        nfoam = sum(1 for r in rs if r["problems"] and not counted(r))
        out.append(f"| {b} | {f} | {p} | {len(rs)} | {o['error']} | "
                   f"{o['runs'] + o['long run']} | "
                   f"{sum(1 for r in rs if counted(r))}"
                   f"{f' ({nfoam})' if nfoam else ''} |")
    out += ["", "| mutation kind | mutations | errors | runs | failed | "
            "most frequent message |", "|---|---|---|---|---|---|"]
    kinds = defaultdict(list)
    for r in results:
        kinds[r["kind"]].append(r)
    for k in sorted(kinds):
        rs = kinds[k]
        o = Counter(r["outcome"] for r in rs)
        msg = Counter(re.sub(r"\s+", " ", re.sub(
            r"/\S*/mutations/m\d+/", "<case>/", r["message"]))[:90]
            for r in rs if r["message"]).most_common(1)
        out.append(f"| {k} | {len(rs)} | {o['error']} | "
                   f"{o['runs'] + o['long run']} | "
                   f"{sum(1 for r in rs if counted(r))} | "
                   f"{msg[0][0].replace('|', '/') if msg else ''} |")
    out += ["", POLICY]
    foam = [r for r in results if r["problems"] and not counted(r)]
    if foam:
        out += ["", f"OpenFOAM limitations ({len(foam)}, printed by the suite, "
                "not counted: OpenFOAM's own decomposePar, which the project "
                "does not build):", ""]
        out += [f"- `{r['file']}` {r['kind']} `{r['entry']}`: "
                f"{'; '.join(r['problems'])} (\"{r['message'][:70].strip()}\")"
                for r in foam]
    return out


POLICY = """Policy. A mutation passes with a successful run when the entry is
optional (removed: its default), harmless (0 or -1 where allowed, a
duplicated entry in a file OpenFOAM reads, which merges repeated keywords;
a second FoamFile header, which OpenFOAM ignores) or makes the run longer
(endTime 1e300: still advancing at the time limit). A word or NaN in place
of a number and a duplicated name in a list must be errors; a run that
exits 0 must not have written nan or inf. Errors must name the file (its
path relative to the case, or its name and directory) and the entry (its
keyword, a name duplicated, for a removed entry its parent or one of its
own entries, or a line of the entry in OpenFOAM's 'at line N'). Files read
only by OpenFOAM's own utilities (blockMeshDict, setFieldsDict,
constant/polyMesh) are not mutated; decomposeParDict is, through
decomposePar, whose findings are listed below."""


if __name__ == "__main__":
    cmd, rest = sys.argv[1], sys.argv[2:]
    sys.exit(main_run(rest) if cmd == "run" else main_doc(rest))
