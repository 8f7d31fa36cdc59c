#!/bin/bash
# femdemFoam stopped by SIGTERM and by SIGINT (stopOnSignal, librunControl):
# the run ends cleanly (exit status 0) at the step the signal arrived, with
# the log line naming the signal; that step is written although it is not a
# write time (writeInterval > endTime): its femdemState is byte-identical to
# the one of an uninterrupted run ending at that time, and a run restarted
# from it (startFrom latestTime) continues for 10 steps. Progress lines
# (runProgress) must appear before the signal is sent.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$JWLIBFOAM_TEST_DIR" || exit 1
tut=$root/tutorials/femdemFoam/brazilianDisc
fail() { echo ">> $*  <-- FAIL"; exit 1; }
setEntry() { sed -i "s/^$2 .*/$2 $3;/" "$1/system/controlDict"; }

# Base case: the quick brazilianDisc mesh; 1000 steps (far more than are
# run before the signal); no write time before endTime
rm -rf base && mkdir -p base/constant
cp -r "$tut/system" "$tut/makeMeshDict.py" base/
cp "$tut/constant/femdemProperties" base/constant/
setEntry base endTime 2e-3
setEntry base writeInterval 1
(cd base && /usr/bin/python3 makeMeshDict.py 0.05 0.0025 72 10 split > log.makeMeshDict \
    && femdemMesh > log.femdemMesh 2>&1) || fail "mesh generation (see base/log.femdemMesh)"

stopWith() {  # signal name (TERM or INT)
    local sig=$1 c=sig$1 pid n rc t
    rm -rf "$c" && cp -r base "$c"
    cd "$c"
    femdemFoam > log.femdemFoam 2>&1 &
    pid=$!
    # Wait for a progress line (default interval 5 s) and a few steps
    for ((n = 0; n < 240; n++)); do
        grep -q '^Progress: ' log.femdemFoam \
            && [ "$(grep -c '^Time = ' log.femdemFoam)" -ge 3 ] && break
        kill -0 $pid 2> /dev/null || break
        sleep 0.5
    done
    if ! kill -0 $pid 2> /dev/null; then
        wait $pid; fail "SIG$sig: femdemFoam ended (exit $?) before the signal"
    fi
    grep -q '^Progress: ' log.femdemFoam || { kill -KILL $pid; fail "SIG$sig: no progress line within 120 s"; }
    kill -"$sig" $pid
    wait $pid; rc=$?
    [ $rc -eq 0 ] || fail "SIG$sig: exit status $rc (expected 0)"
    grep -q '^End' log.femdemFoam || fail "SIG$sig: log does not end with End"
    grep -q "^Signal SIG$sig received at time " log.femdemFoam \
        || fail "SIG$sig: no 'Signal SIG$sig received' line"
    t=$(sed -n "s/^Signal SIG$sig received at time \([^:]*\):.*/\1/p" log.femdemFoam)
    local last=$(grep '^Time = ' log.femdemFoam | tail -1 | awk '{print $3}')
    [ "$t" = "$last" ] || fail "SIG$sig: stopped at $t but the last step is $last"
    [ -s "$t/femdemState" ] || fail "SIG$sig: no $t/femdemState"
    [ "$(ls -d [0-9]* | wc -l)" -eq 1 ] || fail "SIG$sig: time directories: $(ls -d [0-9]*)"
    local index=$(awk '/^index/ {print $2+0}' "$t/uniform/time")
    local progress=$(grep -c '^Progress: ' log.femdemFoam)
    cd ..

    # Reference: uninterrupted run ending (and writing) at the same step
    rm -rf "ref$sig" && cp -r base "ref$sig"
    setEntry "ref$sig" endTime "$t"
    setEntry "ref$sig" writeControl timeStep
    setEntry "ref$sig" writeInterval "$index"
    (cd "ref$sig" && femdemFoam > log.femdemFoam 2>&1) || fail "SIG$sig: reference run"
    local same=no
    cmp -s "ref$sig/$t/femdemState" "$c/$t/femdemState" && same=yes

    # Restart from the written state for 10 steps
    local tEnd=$(awk -v t="$t" 'BEGIN { printf "%.8g", t + 10*2e-6 }')
    setEntry "$c" endTime "$tEnd"
    (cd "$c" && femdemFoam > log.restart 2>&1) || fail "SIG$sig: restart from $t failed"
    grep -q "^Restarted from .*$t/femdemState\" (solid time $t," "$c/log.restart" \
        || fail "SIG$sig: restart did not read $t/femdemState"
    local steps=$(grep -c '^Time = ' "$c/log.restart")
    local lastR=$(grep '^Time = ' "$c/log.restart" | tail -1 | awk '{print $3}')
    echo ">> SIG$sig: exit 0 after step $index (t = $t, $progress progress line(s) before);" \
         "$t/femdemState identical to an uninterrupted run: $same;" \
         "restart ran $steps steps to t = $lastR"
    [ "$same" = yes ] && [ "$steps" -eq 10 ] && [ "$lastR" = "$tEnd" ]
}

stopWith TERM || exit 1
stopWith INT || exit 1
grep '^Progress: ' sigTERM/log.femdemFoam | tail -1 | sed 's/^/>> /'
