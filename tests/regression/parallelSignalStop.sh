#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 MPI ranks or 2 solvers at once)
# Exit status of mpirun after a signal-triggered clean stop (issue 17,
# item 3), coupled box (20x20 cells, 38 triangles) on 2 ranks, each way of
# stopping sent after 30 logged steps of a run far longer:
#  - SIGUSR2 to mpirun (forwarded; Grid Engine's -notify and LSF send it
#    before a kill; unhandled it killed both ranks unwritten, exit 140)
#  - SIGUSR1 to mpirun (forwarded)
#  - SIGTERM to the two ranks only (each is in its own process group)
#  - SIGTERM to a job script that runs mpirun in the background and turns
#    TERM into SIGUSR1 for it (the snippet of stopOnSignal.H and
#    doc/badInput.md)
#  - system/controlDict stopAt writeNow with runTimeModifiable true
#    (OpenFOAM's foamEndJob mechanism)
# each must give exit status 0, the log line 'Signal .. received' (not for
# writeNow), End, and the same stop time written by both ranks with the
# solid state. femdemFoam (serial only) under mpirun -np 1 with SIGUSR2 to
# mpirun likewise. SIGTERM to mpirun itself: Open MPI 4.1.4 exits 1
# whatever the ranks do (clean_abort in orte/mca/ess/hnp/ess_hnp_module.c
# sets the status before the ranks are told); the status is printed and
# both ranks must still have written the stop time.
. "$JWLIBFOAM_PROJECT/tests/regression/signalStopHelpers.bash"
steps() { grep -c '^Time = ' "$1" 2> /dev/null; }

# The job script of the documentation: mpirun's exit status, SIGTERM/SIGINT
# to the script become SIGUSR1 to mpirun
cat > jobScript <<'EOF'
#!/bin/bash
mpirun -np 2 jwlIbFoam -parallel > log.run 2>&1 &
pid=$!
trap 'kill -USR1 $pid; again=1' TERM INT
# wait returns early when the trap runs: wait again for mpirun
again=1
while [ $again = 1 ]; do again=0; wait $pid; rc=$?; done
exit $rc
EOF
chmod +x jobScript

smallBox box.base
setEntry box.base endTime 1
setEntry box.base writeInterval 1000000
setEntry box.base runTimeModifiable true
(cd box.base && blockMesh > log.blockMesh 2>&1 && femdemMesh > log.femdemMesh 2>&1 \
    && decomposePar > log.decomposePar 2>&1) || { bad "box: mesh or decomposePar"; exit 1; }

# stopRun name how: run the box on 2 ranks, stop it after 30 steps by 'how'
stopRun() {
    local c=$1 how=$2 pid rc t0 t1 tStop w0 w1
    rm -rf "$c" && cp -r box.base "$c"
    # OpenFOAM notices an edit of controlDict only if it is newer than at
    # its reading by more than fileModificationSkew (10 s)
    touch -d '-1 min' "$c/system/controlDict"
    cd "$c"
    if [ "$how" = jobScriptTERM ]; then ../jobScript & else mpirun -np 2 jwlIbFoam -parallel > log.run 2>&1 & fi
    pid=$!
    waitSteps log.run $pid 30
    t0=$(date +%s.%N)
    case $how in
        mpirun*) kill -"${how#mpirun}" $pid ;;
        ranksTERM) pkill -TERM -P $pid ;;
        jobScriptTERM) kill -TERM $pid ;;
        writeNow) sed -i 's/^stopAt .*/stopAt writeNow;/' system/controlDict ;;
    esac
    wait $pid; rc=$?
    t1=$(date +%s.%N)
    tStop=$(sed -n "s/^Signal SIG[A-Z0-9]* received at time \([^:]*\):.*/\1/p" log.run)
    # (SIGTERM to mpirun: no log after the signal; writeNow: no signal line)
    [ -n "$tStop" ] || tStop=$(cd processor0 && ls -d [0-9]* | grep -vx 0 | sort -g | tail -1)
    w0=$(cd processor0 && ls -d [0-9]* | grep -vx 0 | tr '\n' ' ')
    w1=$(cd processor1 && ls -d [0-9]* | grep -vx 0 | tr '\n' ' ')
    cd ..
    echo ">> $c: $how after $(steps $c/log.run) logged steps: exit $rc after" \
         "$(awk -v a=$t0 -v b=$t1 'BEGIN { printf "%.2f", b - a }') s; written: rank 0 $w0, rank 1 $w1"
    [ -n "$tStop" ] && [ "$w0" = "$tStop " ] && [ "$w1" = "$tStop " ] \
        && [ -s "$c/processor0/$tStop/uniform/femdemState" ] && [ -s "$c/processor1/$tStop/p" ] \
        || bad "$c: the stop time '$tStop' not written by both ranks (with the solid state)"
    [ "$how" = mpirunTERM ] && { lastRc=$rc; return; }
    [ "$rc" -eq 0 ] || bad "$c: exit status $rc (expected 0)"
    grep -q '^End' "$c/log.run" || bad "$c: the log does not end with End"
    [ "$how" = writeNow ] || grep -q "^Signal SIG" "$c/log.run" || bad "$c: no 'Signal .. received' line"
}

stopRun usr2 mpirunUSR2
stopRun usr1 mpirunUSR1
stopRun ranks ranksTERM
stopRun script jobScriptTERM
stopRun writeNow writeNow
lastRc=
stopRun term mpirunTERM
echo ">> SIGTERM to mpirun itself: mpirun exit $lastRc (Open MPI 4.1.4 sets 1 on any SIGTERM/SIGINT/SIGHUP to it)"

# ---- femdemFoam (serial) under mpirun -np 1: SIGUSR2 to mpirun
mkdir -p bar/system bar/constant
{ header controlDict; cat <<'D'; } > bar/system/controlDict
application femdemFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1; deltaT 3e-7; writeControl timeStep; writeInterval 100000000;
D
{ header femdemMeshDict; cat <<'D'; } > bar/system/femdemMeshDict
targetSize 0.0025; minAngle 20;
solids { bar { type rectangle; min (0 0); max (0.06 0.02); material rock; patches (bottom right top left); } }
D
{ header femdemProperties; cat <<'D'; } > bar/constant/femdemProperties
materials { rock { E 10e9; nu 0.25; rho 2500; tensileStrength 2e6; cohesion 8e6; frictionAngle 30; GI 20; GII 200; } }
boundaryConditions { left { type fixed; } right { type velocity; value (30 0); } }
output { vtk false; }
D
(cd bar && femdemMesh > log.femdemMesh 2>&1) || { bad "bar: mesh"; exit 1; }
(cd bar && exec mpirun -np 1 femdemFoam > log.run 2>&1) &
pid=$!
waitSteps bar/log.run $pid 30
kill -USR2 $pid
wait $pid; rc=$?
t=$(sed -n "s/^Signal SIGUSR2 received at time \([^:]*\):.*/\1/p" bar/log.run)
echo ">> femdemFoam under mpirun -np 1: SIGUSR2 to mpirun: exit $rc, stopped at '$t'," \
     "written: $(cd bar && ls -d [0-9]* 2> /dev/null | tr '\n' ' ')"
[ "$rc" -eq 0 ] && [ -n "$t" ] && [ -s "bar/$t/femdemState" ] && grep -q '^End' bar/log.run \
    || bad "femdemFoam: no clean stop with exit 0 after SIGUSR2 to mpirun"
exit $fail
