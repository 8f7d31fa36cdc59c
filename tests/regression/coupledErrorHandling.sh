#!/bin/bash
# Regression: the coupled solver (jwlIbFoam with an immersed FEMDEM solid)
# stops cleanly. Case: tests/regression/coupledData/closedBoxSolid (free
# rock disc thrown through air at rest in a periodic box) on 20x20 cells,
# 38 triangles, adjustTimeStep no.
#  0. steps in parts: deltaT 5e-5 to 1e-3 with the default maxStepHalvings
#     5: the steps the gas cannot take whole are taken in parts; the run
#     reaches its end on its time schedule, mass and gas + solid energy
#     conserved.
#     maxStepHalvings -1: a FatalIOError naming controlDict and the entry.
#  1. divergence (maxStepHalvings 0): deltaT 5e-5 (gas Courant number about 3.4; the cut-cell
#     step still runs at 1.4, deltaT 2e-5; the solid sub-cycles with its
#     own stable step) written every 5 steps: the run stops at step 11
#     (t = 5.5e-4) with exit status 1 and a message naming the time, the
#     cell and its centre; 5.5e-4 is not written; the last written time
#     5e-4 holds the gas fields,
#     alpha.solid, fluidFraction and uniform/femdemState, and a restart
#     from it (adjustTimeStep yes) reads gas and solid and runs to 6e-4.
#     alpha.solid or U.solid of that time with other dimensions (a length):
#     a FatalIOError naming the file and the entry 'dimensions'.
#  2. SIGTERM and SIGINT during a run (deltaT 2e-6, no write time before
#     endTime): exit status 0, 'Signal SIG<x> received at time t', the
#     step t is written (gas fields, alpha.solid, fluidFraction,
#     uniform/femdemState) and equals an uninterrupted run ending at t
#     (compareCases.py: max relative difference 0); a restart from t for
#     10 steps equals an uninterrupted run to t + 10 steps (1e-12).
set -u
cd "$JWLIBFOAM_TEST_DIR" || exit 1
data=$JWLIBFOAM_PROJECT/tests/regression/coupledData
compare=$data/compareCases.py
fail() { echo ">> $*  <-- FAIL"; exit 1; }
setEntry() {  # case key value: replace the line 'key ...;' of controlDict
    sed -i "s/^$2 .*/$2 $3;/" "$1/system/controlDict"
}
timeDirs() {  # case: its time directories, sorted
    (cd "$1" && ls -d [0-9]* 2> /dev/null | sort -g | tr '\n' ' ')
}
stateFiles="p U rho rhoU rhoE alpha.solid U.solid fluidFraction uniform/femdemState"
complete() {  # time directory: every state file is there and not empty
    local f
    for f in $stateFiles; do [ -s "$1/$f" ] || return 1; done
}

# Base: the small closed box, meshed once
rm -rf base && cp -r "$data/closedBoxSolid" base
sed -i 's/(80 80 1)/(20 20 1)/' base/system/blockMeshDict
sed -i 's/^targetSize .*/targetSize 0.02;/; s/nSegments 48/nSegments 12/' base/system/femdemMeshDict
(cd base && blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1) \
    || fail "blockMesh/femdemMesh on the base case"

# ------------------------------------------------------ steps in parts
# The same too-large step with the default maxStepHalvings 5: each step
# the gas cannot take whole is restored and taken in halves (each part with
# its own geometry and solid step): the run reaches its end, every step
# ends on the schedule, mass and gas + solid energy stay conserved
rm -rf halved && cp -r base halved
setEntry halved deltaT 5e-5
setEntry halved endTime 1e-3
setEntry halved writeInterval 1000
(cd halved && jwlIbFoam > log.jwlIbFoam 2>&1) || { tail -5 halved/log.jwlIbFoam; fail "steps in parts: the run stopped"; }
/usr/bin/python3 - halved "$data" <<'PY' || fail "steps in parts: not taken in parts, off schedule or not conservative"
import re, sys
case = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import budget  # columns of budget.dat by their header names
log = open(f"{case}/log.jwlIbFoam").read()
parts = len(re.findall(r"^jwlIbFoam: the step to \S+ is taken in parts", log, re.M))
nSteps = int(re.search(r"^Coupled steps taken in parts .*?whole\): (\d+)", log, re.M).group(1))
times = [float(m.group(1)) for m in re.finditer(r"^Time = (\S+)", log, re.M)]
offSchedule = max(abs(t - 5e-5*(k + 1)) for k, t in enumerate(times))/5e-5
dE, dP, dm = budget.drifts(budget.load(f"{case}/postProcessing/jwlIbFoam/0/budget.dat"))
print(f">> steps in parts: {len(times)} steps to {times[-1]:.6g} s, {nSteps} taken in parts "
      f"({parts} halvings); time off the 5e-5 schedule {offSchedule:.1e} of a step (tolerance 1e-9); "
      f"gas mass drift {dm:.1e} (tolerance 1e-12), gas + solid energy {dE:.1e} (tolerance 1e-6), "
      f"momentum {dP:.1e} (tolerance 1e-8)")
sys.exit(0 if nSteps > 0 and parts >= nSteps and times[-1] > 0.999e-3
         and offSchedule < 1e-9 and dm < 1e-12 and dE < 1e-6 and dP < 1e-8 else 1)
PY

# A negative maxStepHalvings: a FatalIOError naming controlDict and the
# entry, no signal
rm -rf badHalvings && cp -r base badHalvings
echo "maxStepHalvings -1;" >> badHalvings/system/controlDict
(cd badHalvings && jwlIbFoam > log.jwlIbFoam 2>&1) && fail "maxStepHalvings -1: accepted"
grep -q "FOAM FATAL IO ERROR" badHalvings/log.jwlIbFoam && grep -q "badHalvings/system/controlDict" badHalvings/log.jwlIbFoam \
    && grep -q "maxStepHalvings -1: must be 0 to 30" badHalvings/log.jwlIbFoam \
    && ! grep -v '^trapFpe' badHalvings/log.jwlIbFoam | grep -qiE 'segmentation|sigfpe|stack trace' \
    || { tail -6 badHalvings/log.jwlIbFoam; fail "maxStepHalvings -1: no FatalIOError naming controlDict and the entry"; }
echo ">> maxStepHalvings -1: rejected ($(grep -m1 -o 'maxStepHalvings -1: must be 0 to 30' badHalvings/log.jwlIbFoam))"

# ------------------------------------------------------------- divergence
# (maxStepHalvings 0: the step the gas cannot take whole stops the run)
rm -rf diverge && cp -r base diverge
setEntry diverge deltaT 5e-5
setEntry diverge endTime 1e-2
setEntry diverge writeInterval 5
echo "maxStepHalvings 0;" >> diverge/system/controlDict
(cd diverge && jwlIbFoam > log.jwlIbFoam 2>&1)
rc=$?
log=diverge/log.jwlIbFoam
[ $rc = 0 ] && fail "divergence: the run did not stop"
{ [ $rc -ge 128 ] || grep -v '^trapFpe' $log | grep -qiE 'segmentation|sigfpe|floating point exception|stack trace'; } \
    && fail "divergence: crashed (exit $rc)"
msg=$(sed -n '/FOAM FATAL ERROR/{n;p;q}' $log)
t=$(echo "$msg" | sed -n 's/.*non-physical state at time \([^ ]*\) in cell [0-9]* (centre (.*/\1/p')
[ -n "$t" ] || fail "divergence: message does not name the time, a cell and its centre: $msg"
echo ">> divergence stopped (exit $rc): ${msg:0:150}"
[ -d diverge/$t ] && fail "divergence: the failed time $t was written"
last=$(timeDirs diverge | awk '{print $NF}')
/usr/bin/python3 -c "import sys; sys.exit(0 if 0 < float('$last') < float('$t') else 1)" \
    || fail "divergence: last written time '$last' is not before the failed time $t"
complete diverge/$last || fail "divergence: $last lacks one of: $stateFiles"
echo ">> no time directory for the failed time $t; last written $last complete ($stateFiles)"
# The budget keeps every step done before the stop, each row whole (a
# FatalError exits without unwinding: unflushed rows were lost, the file
# cut mid-row)
/usr/bin/python3 - diverge <<'PY' || fail "divergence: budget.dat lost rows or was cut"
import re, sys
case = sys.argv[1]
rows = [l.split() for l in open(f"{case}/postProcessing/jwlIbFoam/0/budget.dat") if not l.startswith("#")]
names = open(f"{case}/postProcessing/jwlIbFoam/0/budget.dat").readline().split(":")[1].split()
steps = [float(m.group(1)) for m in re.finditer(r"^Time = (\S+)", open(f"{case}/log.jwlIbFoam").read(), re.M)]
whole = all(len(r) == len(names) for r in rows)
err = abs(float(rows[-1][0]) - steps[-1]) / steps[-1]
print(f">> divergence: budget.dat rows {len(rows)}, all with {len(names)} columns: {whole}; "
      f"last row t = {rows[-1][0]} vs the last step done {steps[-1]} (relative {err:.1e}, tolerance 1e-6)")
sys.exit(0 if whole and err < 1e-6 else 1)
PY
setEntry diverge adjustTimeStep yes
# (two failed steps on: Time stops within half a step of endTime, and the
# first step restarts with the deltaT of the last)
setEntry diverge endTime $(/usr/bin/python3 -c "print(f\"{float('$last') + 1e-4:.6g}\")")
(cd diverge && jwlIbFoam > log.restart 2>&1) || fail "divergence: restart from $last failed"
grep -q "^blastFluidSolver: restart from the conservative state of time $last" diverge/log.restart \
    && grep -q "^Solid restarted from \"$last/uniform/femdemState\"" diverge/log.restart \
    || fail "divergence: the restart did not read the gas and the solid of $last"
[ "$(grep -c '^Time = ' diverge/log.restart)" -gt 0 ] || fail "divergence: the restart from $last ran no step"
echo ">> restart from $last (adjustTimeStep yes) read gas and solid and ran" \
     "$(grep -c '^Time = ' diverge/log.restart) steps to $(grep '^Time = ' diverge/log.restart | tail -1 | awk '{print $3}')"

# ------------------------------------------- solid fields' dimensions
# A restart from $last whose alpha.solid (dimensionless) or U.solid (m/s)
# has other dimensions: a FatalIOError naming the file and the entry
# 'dimensions', as for the gas fields; no signal
solidDims() {  # field dimensions
    local c=dims${1%%.*}
    rm -rf "$c" && mkdir "$c" && cp -r diverge/0 diverge/constant diverge/system "diverge/$last" "$c/"
    sed -i "s/^dimensions .*/dimensions $2;/" "$c/$last/$1"
    (cd "$c" && jwlIbFoam > log.jwlIbFoam 2>&1) && fail "$1 with dimensions $2: accepted"
    grep -q "FOAM FATAL IO ERROR" "$c/log.jwlIbFoam" && grep -q "$c/$last/$1" "$c/log.jwlIbFoam" \
        && grep -q "entry 'dimensions'" "$c/log.jwlIbFoam" \
        && ! grep -v '^trapFpe' "$c/log.jwlIbFoam" | grep -qiE 'segmentation|sigfpe|stack trace' \
        || { tail -6 "$c/log.jwlIbFoam"; fail "$1 with dimensions $2: no FatalIOError naming the file and 'dimensions'"; }
    echo ">> $last/$1 with dimensions $2: rejected ($(grep -m1 -o "entry 'dimensions' is .*" "$c/log.jwlIbFoam" | cut -c1-90))"
}
solidDims alpha.solid "[0 1 0 0 0 0 0]"
solidDims U.solid "[0 1 0 0 0 0 0]"

# ------------------------------------------------------- solid divergence
# maxNodeSpeed 1e-9 m/s: the disc at rest starts to move as the ambient
# pressure compresses it, so the solid counts as diverging at its first
# sub-step; the run must stop cleanly (no FPE or stack trace), name the
# time, the node and its speed, and write no time directory
rm -rf solidDiverge && cp -r base solidDiverge
sed -i 's/^initialVelocity .*/initialVelocity (0 0);/' solidDiverge/constant/femdemProperties
echo "maxNodeSpeed 1e-9;" >> solidDiverge/constant/femdemProperties
setEntry solidDiverge writeInterval 5
(cd solidDiverge && jwlIbFoam > log.jwlIbFoam 2>&1)
rc=$?
log=solidDiverge/log.jwlIbFoam
[ $rc = 0 ] && fail "solid divergence: the run did not stop"
{ [ $rc -ge 128 ] || grep -v '^trapFpe' $log | grep -qiE 'segmentation|sigfpe|floating point exception|stack trace'; } \
    && fail "solid divergence: crashed (exit $rc)"
msg=$(grep -m1 "FEMDEM solid is diverging at time" $log)
[ -n "$msg" ] && echo "$msg" | grep -q "node [0-9]* at (.*) moves at .* m/s, above maxNodeSpeed" \
    || fail "solid divergence: no message naming the time, the node and its speed"
[ "$(timeDirs solidDiverge)" = "0 " ] || fail "solid divergence: time directories $(timeDirs solidDiverge)"
echo ">> solid divergence stopped (exit $rc): ${msg:0:160}"

# ------------------------------------------------------------- signals
# Far more steps than run before the signal, no write time before endTime,
# a progress line every second
setEntry base endTime 1
setEntry base writeInterval 1000000
echo "progressInterval 1;" >> base/system/controlDict

uninterrupted() {  # name endTime steps: run the base to endTime, writing it
    rm -rf "$1" && cp -r base "$1"
    setEntry "$1" endTime "$2"
    setEntry "$1" writeInterval "$3"
    (cd "$1" && jwlIbFoam > log.jwlIbFoam 2>&1)
}

stopWith() {  # TERM or INT
    local sig=$1 c=sig$1 pid n rc t last index d tEnd dR ok
    rm -rf "$c" && cp -r base "$c"
    cd "$c"
    jwlIbFoam > log.jwlIbFoam 2>&1 &
    pid=$!
    for ((n = 0; n < 240; n++)); do
        grep -q '^Progress: ' log.jwlIbFoam \
            && [ "$(grep -c '^Time = ' log.jwlIbFoam)" -ge 3 ] && break
        kill -0 $pid 2> /dev/null || break
        sleep 0.5
    done
    if ! kill -0 $pid 2> /dev/null; then
        wait $pid; fail "SIG$sig: jwlIbFoam ended (exit $?) before the signal"
    fi
    grep -q '^Progress: ' log.jwlIbFoam || { kill -KILL $pid; fail "SIG$sig: no progress line within 120 s"; }
    kill -"$sig" $pid
    wait $pid; rc=$?
    [ $rc -eq 0 ] || fail "SIG$sig: exit status $rc (expected 0)"
    grep -q '^End' log.jwlIbFoam || fail "SIG$sig: the log does not end with End"
    t=$(sed -n "s/^Signal SIG$sig received at time \([^:]*\):.*/\1/p" log.jwlIbFoam)
    [ -n "$t" ] || fail "SIG$sig: no 'Signal SIG$sig received' line"
    last=$(grep '^Time = ' log.jwlIbFoam | tail -1 | awk '{print $3}')
    [ "$t" = "$last" ] || fail "SIG$sig: stopped at $t but the last step is $last"
    [ "$(timeDirs .)" = "0 $t " ] || fail "SIG$sig: time directories $(timeDirs .)"
    complete "$t" || fail "SIG$sig: $t lacks one of: $stateFiles"
    index=$(awk '/^index/ {print $2+0}' "$t/uniform/time")
    cd ..

    # The written state equals an uninterrupted run ending at t
    uninterrupted "ref$sig" "$t" "$index" || fail "SIG$sig: reference run to $t"
    d=$(/usr/bin/python3 "$compare" "ref$sig/$t" "$c/$t" | tail -1 | awk '{print $2}')

    # Restart from t for 10 steps against an uninterrupted run
    tEnd=$(awk -v t="$t" 'BEGIN { printf "%.10g", t + 10*2e-6 }')
    setEntry "$c" endTime "$tEnd"
    setEntry "$c" writeInterval $((index + 10))
    (cd "$c" && jwlIbFoam > log.restart 2>&1) || fail "SIG$sig: restart from $t failed"
    grep -q "^Solid restarted from \"$t/uniform/femdemState\"" "$c/log.restart" \
        || fail "SIG$sig: the restart did not read $t/uniform/femdemState"
    [ -d "$c/$tEnd" ] || fail "SIG$sig: the restart did not reach $tEnd"
    uninterrupted "ref${sig}End" "$tEnd" $((index + 10)) || fail "SIG$sig: reference run to $tEnd"
    dR=$(/usr/bin/python3 "$compare" "ref${sig}End/$tEnd" "$c/$tEnd" | tail -1 | awk '{print $2}')
    ok=$(/usr/bin/python3 -c "print(int($d == 0 and $dR <= 1e-12))")
    echo ">> SIG$sig: exit 0 at step $index (t = $t); written state vs an uninterrupted run:" \
         "max relative difference $d (tolerance 0); restart +10 steps vs one run to $tEnd:" \
         "$dR (tolerance 1e-12)$([ "$ok" = 1 ] || echo '  <-- FAIL')"
    [ "$ok" = 1 ]
}

stopWith TERM || exit 1
stopWith INT || exit 1
