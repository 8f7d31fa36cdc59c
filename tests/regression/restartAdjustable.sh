#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# Restart equality with the tutorials' own write settings (issue 17, item 3):
# writeControl adjustableRunTime (+ adjustTimeStep for jwlIbFoam). A run
# stopped by a signal at some step (SIGTERM/SIGINT serial; SIGTERM and
# SIGUSR1 and SIGUSR2 to mpirun on 2 ranks), then restarted with startFrom latestTime,
# must equal the uninterrupted run:
#  - the same write times (plus the signal's own time directory), endTime
#    written;
#  - every write time after the stop byte-identical (diff -r: fields at
#    writePrecision 17, uniform/time, femdemState);
#  - every step line of the log ("Time = .. dt = .. maxP .. mass ..
#    energy" at 17 digits) of the two pieces = the uninterrupted run's.
# Cases: gas only (tntCharge2D, 40x40, two materials), coupled gas + solid
# (the coupled box of solidRestartOutput, 20x20 cells) serial and on 2 ranks,
# femdemFoam (a bar, deltaT that does not divide writeInterval, so the steps
# are clipped to the write times). The stop step is wherever the signal
# lands (after a given number of logged steps); mpirun's exit status is
# printed (Open MPI 4.1 exits 1 after SIGTERM/SIGINT to mpirun whatever the
# ranks do, 0 after SIGUSR1/SIGUSR2; see README "Running in parallel" and
# test parallelSignalStop).
. "$JWLIBFOAM_PROJECT/tests/regression/signalStopHelpers.bash"
launch() {  # np app: serial or 2-rank run in the current directory
    if [ "$1" = 1 ]; then exec "$2"; else exec mpirun -np "$1" "$2" -parallel; fi
}
writeTimes() {  # dir: the time directories but 0, in time order
    (cd "$1" && ls -d [0-9]* 2> /dev/null | grep -vx 0 | sort -g | tr '\n' ' ')
}

# interrupt ref case sig nSteps np app: copies the base case $ref.base to
# $case, runs it, sends the signal after nSteps logged steps, restarts to
# endTime and compares with the uninterrupted run $ref
interrupt() {
    local ref=$1 c=$2 sig=$3 n=$4 np=$5 app=$6 pid rc
    rm -rf "$c" && cp -r "$ref.base" "$c"
    (cd "$c" && launch "$np" "$app" > log.run 2>&1) &
    pid=$!
    waitSteps "$c/log.run" $pid "$n"
    # The subshell exec'd the solver (or mpirun): $pid is its process
    kill -"$sig" $pid 2> /dev/null
    wait $pid; rc=$?
    # The stop time: the signal's log line, or (SIGTERM to mpirun, which
    # drops the ranks' output from then on) the last time directory
    local sub=.; [ "$np" = 1 ] || sub=processor0
    local tStop=$(sed -n "s/^Signal SIG[A-Z0-9]* received at time \([^:]*\):.*/\1/p" "$c/log.run")
    [ -n "$tStop" ] || [ "$np" = 1 ] || tStop=$(writeTimes "$c/$sub" | awk '{print $NF}')
    local eT=$(sed -n 's/^endTime *\([^;]*\);.*/\1/p' "$c/system/controlDict")
    if [ -z "$tStop" ] || awk -v a="$tStop" -v b="$eT" 'BEGIN { exit !(a >= b) }'; then
        bad "$c: no stop before endTime (the run ended before the signal?)"; return
    fi
    [ -d "$c/$sub/$tStop" ] || bad "$c: the stop time $tStop was not written"
    [ "$np" = 1 ] || [ -d "$c/processor1/$tStop" ] || bad "$c: rank 1 did not write the stop time $tStop"
    [ "$np" != 1 ] || grep -q '^End' "$c/log.run" || bad "$c: the stopped run did not end cleanly"
    (cd "$c" && launch "$np" "$app" > log.restart 2>&1) || bad "$c: restart failed"

    # Write times, files, step lines
    local wRef wCut
    wRef=$(writeTimes "$ref/$sub" | sed 's/ $//')
    wCut=$(writeTimes "$c/$sub" | sed 's/ $//')
    # The stop's own directory is extra, unless the signal landed on a write time
    case " $wRef " in
        *" $tStop "*) ;;
        *) wCut=$(echo " $wCut " | sed "s/ $tStop / /; s/^ //; s/ $//") ;;
    esac
    [ "$wRef" = "$wCut" ] || bad "$c: write times '$wCut' (+ $tStop), uninterrupted '$wRef'"
    local nSame=0 nDiff=0 t d
    for t in $wRef; do
        awk -v a="$t" -v b="$tStop" 'BEGIN { exit !(a > b) }' || continue
        for d in "$ref"/$sub "$ref"/processor1; do
            [ -d "$d/$t" ] || continue
            if diff -rq "$d/$t" "$c/${d#$ref/}/$t" > /dev/null; then
                nSame=$((nSame + 1))
            else
                nDiff=$((nDiff + 1))
            fi
        done
    done
    # Step lines: the stopped run's up to the stop (all it printed) and the
    # restart's must be the uninterrupted run's
    local nSteps=$(grep -c '^Time = ' "$ref/log.run")
    local stopStep=$(grep -c '^Time = ' "$c/log.run")
    local atStop=$(grep '^Time = ' "$ref/log.run" | grep -n "^Time = $tStop " | cut -d: -f1)
    local linesSame=no
    cmp -s <(grep '^Time = ' "$ref/log.run" | head -n "$stopStep") \
        <(grep '^Time = ' "$c/log.run") \
    && cmp -s <(grep '^Time = ' "$ref/log.run" | tail -n +$((${atStop:-0} + 1))) \
        <(grep '^Time = ' "$c/log.restart") \
    && [ "$(grep -c '^Time = ' "$c/log.restart")" -gt 0 ] && linesSame=yes
    echo ">> $c: SIG$sig, stopped at step ${atStop:-?} of $nSteps (t = $tStop), exit $rc;" \
         "write times $wCut; identical after the stop: $nSame, differing: $nDiff;" \
         "step lines identical: $linesSame"
    [ "$nDiff" -eq 0 ] && [ "$nSame" -gt 0 ] && [ "$linesSame" = yes ] \
        || bad "$c: restarted run differs from the uninterrupted one"
    [ "$np" != 1 ] || [ "$rc" -eq 0 ] || bad "$c: exit status $rc (expected 0)"
    [ "$np" = 1 ] || [ "${sig#USR}" = "$sig" ] || [ "$rc" -eq 0 ] || bad "$c: mpirun exit status $rc after SIG$sig (expected 0)"
    awk -v a="${wCut##* }" -v b="$eT" 'BEGIN { exit !(a == b) }' \
        || bad "$c: endTime $eT not written (last write time ${wCut##* })"
}

reference() {  # ref np app: the uninterrupted run of $ref.base
    rm -rf "$1" && cp -r "$1.base" "$1"
    (cd "$1" && launch "$2" "$3" > log.run 2>&1) || { bad "$1: uninterrupted run failed"; tail "$1/log.run"; }
}

# ---- gas only: tntCharge2D, 40x40 cells, maxCo 0.1
tut=$root/tutorials/jwlIbFoam/tntCharge2D
rm -rf gas.base && mkdir gas.base
cp -r "$tut/0.orig" gas.base/0 && cp -r "$tut/constant" "$tut/system" gas.base/
sed -i 's/^n .*/n 40;/' gas.base/system/blockMeshDict
setEntry gas.base writeInterval 1e-5
setEntry gas.base endTime 4e-5
setEntry gas.base maxCo 0.1
setEntry gas.base startFrom latestTime
(cd gas.base && blockMesh > log.blockMesh 2>&1 && setCharge > log.setCharge 2>&1) \
    || { bad "gas: mesh"; exit 1; }
reference gas 1 jwlIbFoam
interrupt gas gasTERM TERM 40 1 jwlIbFoam
interrupt gas gasINT INT 110 1 jwlIbFoam

# ---- coupled box, 20x20 cells, 38 triangles
smallBox box.base
setEntry box.base writeControl adjustableRunTime
setEntry box.base writeInterval 2e-4
setEntry box.base adjustTimeStep yes
setEntry box.base maxCo 0.2
setEntry box.base endTime 6e-4
(cd box.base && blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1) \
    || { bad "box: mesh"; exit 1; }
reference box 1 jwlIbFoam
interrupt box boxTERM TERM 70 1 jwlIbFoam

# ---- the same on 2 ranks (decomposeParDict of the box: 2 subdomains), to
# 1.2e-3 s: mpirun passes SIGTERM on to the ranks only a second later
rm -rf box2.base && cp -r box.base box2.base
setEntry box2.base endTime 1.2e-3
(cd box2.base && decomposePar > log.decomposePar 2>&1) || { bad "box2: decomposePar"; exit 1; }
reference box2 2 jwlIbFoam
interrupt box2 box2TERM TERM 60 2 jwlIbFoam
interrupt box2 box2USR1 USR1 130 2 jwlIbFoam
interrupt box2 box2USR2 USR2 100 2 jwlIbFoam

# ---- femdemFoam: a bar pulled at one end, deltaT 3e-7 (4e-5/3e-7 = 133.3)
mkdir -p bar.base/system bar.base/constant
{ header controlDict; cat <<'D'; } > bar.base/system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1.2e-4; deltaT 3e-7; writeControl adjustableRunTime; writeInterval 4e-5;
timePrecision 8;
D
{ header femdemMeshDict; cat <<'D'; } > bar.base/system/femdemMeshDict
targetSize 0.0025; minAngle 20;
solids { bar { type rectangle; min (0 0); max (0.06 0.02); material rock; patches (bottom right top left); } }
D
{ header femdemProperties; cat <<'D'; } > bar.base/constant/femdemProperties
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6; cohesion 8e6; frictionAngle 30; GI 20; GII 200; } }
boundaryConditions { left { type fixed; } right { type velocity; value (30 0); } }
output { vtk false; }
D
(cd bar.base && femdemMesh > log.femdemMesh 2>&1) || { bad "bar: mesh"; exit 1; }
reference bar 1 femdemFoam
interrupt bar barTERM TERM 60 1 femdemFoam
interrupt bar barINT INT 200 1 femdemFoam
steps=$(grep -c '^Time = ' bar/log.run)
[ "$(writeTimes bar)" = "4e-05 8e-05 0.00012 " ] \
    && echo ">> bar: uninterrupted femdemFoam writes at 4e-05 8e-05 0.00012 ($steps steps of at most 3e-7: clipped to the write times)" \
    || bad "bar: write times '$(writeTimes bar)', expected 4e-05 8e-05 0.00012"
exit $fail
