#!/bin/bash
# Generated hostile-input suite (issue 17): every input file of the bad-input
# base cases (hostileInputBases.bash) mutated systematically (empty, truncated,
# each entry removed, each number set to 0, -1, NaN, 1e300 and a word, lists
# shortened, names duplicated), each mutation run by the program that reads
# the file, 2 at a time, 20 s limit each. hostileInput.py documents the
# mutation kinds and the judgement; '>>' lines give the counts per kind and
# program, every failure and a summary. doc/badInput.md's generated section:
#     tests/regression/hostileInput.py doc tests/results/hostileInput/results.json doc/badInput.md
. "$JWLIBFOAM_PROJECT/tests/regression/hostileInputBases.bash"
# barRestart: barRun continued to 8e-6 (reads 4e-06/femdemState)
cp -r bases/barRun bases/barRestart
sed -i 's/endTime 4e-6;/endTime 8e-6;/' bases/barRestart/system/controlDict
exec /usr/bin/python3 "$JWLIBFOAM_PROJECT/tests/regression/hostileInput.py" \
    run "$top/bases" "$top/mutations" -j 2 -timeout 20 -json "$top/results.json"
