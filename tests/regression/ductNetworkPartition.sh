#!/bin/bash
# testCores: 2   (tests/run.py: runs only with 2 cores free: 2 and 3 MPI ranks)
# The crack network's gas step shared by the MPI ranks (ductNetwork::
# distribute / collect, ductPartition; issue 15): each rank updates its own
# control volumes from the interfaces with an own end, the ghosts' contents
# come from their owners after every Runge-Kutta stage, the sub-step is a
# min-reduction. ductNetworkPartitionCheck runs a grid network with junction
# voids, long links, mouths in (products at 1e8 Pa, some capped) and out
# (air), and breathing walls, on every rank whole (serial reference) and
# distributed, and compares every volume after every step. Cases (owners by
# stripes, blocks and at random; one and two materials; HLLC and
# Kurganov-Tadmor; RK1/2/3; friction; Kapila term off; 2 and 3 ranks), each
# must give:
# - bitwise the serial network: max relative difference 0, no differing
#   volume, mouth inflow or sub-step;
# - a network that did something: more sub-steps than steps and a mass
#   change through the mouths of at least 1e-3.
cd "$JWLIBFOAM_TEST_DIR" || exit 1
mkdir -p system
fail=0
run() {  # name ranks args...
    local name=$1 np=$2; shift 2
    mpirun -np "$np" ductNetworkPartitionCheck -parallel "$@" > "log.$name" 2>&1 \
        || { tail -5 "log.$name"; echo ">> $name: ductNetworkPartitionCheck failed  <-- FAIL"; fail=1; return; }
    local last ranks
    last=$(grep '^max relative difference' "log.$name")
    ranks=$(grep -o 'rank [0-9]*: own volumes.*' "log.$name" | sort | tr '\n' ';')
    echo ">> $name ($np ranks; $*): $last; $ranks"
    local steps
    steps=$(echo "$*" | sed -n 's/.*-steps \([0-9]*\).*/\1/p')
    python3 - "$last" "$name" "$steps" <<'PY' || fail=1
import re, sys
last, name, steps = sys.argv[1], sys.argv[2], float(sys.argv[3])
v = dict((k.strip(), float(x)) for k, x in re.findall(r'([a-z \-]+?) ([-+0-9.e]+)(?:,|$)', last))
bad = []
for k in ("max relative difference", "differing volumes", "differing mouths", "differing sub-steps"):
    if v.get(k) != 0: bad.append("%s %s (must be 0)" % (k, v.get(k)))
if not v.get("sub-steps", 0) > steps: bad.append("%s sub-steps for %d steps: one per step tests no sub-cycling" % (v.get("sub-steps"), steps))
if abs(v.get("mass change through the mouths", 0)) < 1e-3: bad.append("mass change through the mouths below 1e-3")
for b in bad: print(">> %s: %s  <-- FAIL" % (name, b))
sys.exit(1 if bad else 0)
PY
}
run stripesTwo     2 -owner stripes -steps 30
run randomTwo      2 -owner random -steps 30 -RKorder 3
run blocksOne      2 -owner blocks -steps 30 -materials one -friction 0.02
run randomKT       2 -owner random -steps 20 -flux KurganovTadmor -RKorder 1
run randomFrozen   2 -owner random -steps 20 -kapila false -amplitude 0.1
run stripes3       3 -owner stripes -steps 30 -nx 30
run random3        3 -owner random -steps 30 -RKorder 3 -friction 0.01
exit $fail
