#!/bin/bash
# femdemMeshCheck rejects an inverted triangle, duplicated nodes, overlapping
# solids and a non-manifold edge with an error naming the elements, leaves the
# case directory unchanged, and accepts a valid mesh.
set -u
cd "$JWLIBFOAM_TEST_DIR"
fail=0
header='FoamFile { version 2.0; format ascii; class dictionary; object solidMesh; }'
makeCase() {  # name points triangles
    mkdir -p "$1/constant"
    printf '%s\nmaterials (rock granite);\npoints %s;\ntriangles %s;\n' "$header" "$2" "$3" > "$1/constant/solidMesh"
    n=$(echo "$3" | sed 's/^\([0-9]*\).*/\1/')
    printf 'triangleMaterials %s(%s);\nboundary {}\n' "$n" "$(for ((i=0;i<n;i++)); do printf '0 '; done)" >> "$1/constant/solidMesh"
}
expectRejected() {  # name pattern...
    local name=$1; shift
    local before after
    before=$(cd "$name" && find . -type f -exec md5sum {} + | sort | md5sum)
    if femdemMeshCheck -case "$name" > "log.$name" 2>&1; then
        echo ">> $name: ACCEPTED (should be rejected)"; fail=1; return
    fi
    after=$(cd "$name" && find . -type f -exec md5sum {} + | sort | md5sum)
    for pattern in "$@"; do
        if ! grep -q -- "$pattern" "log.$name"; then
            echo ">> $name: error does not say '$pattern'"; fail=1
            sed -n '/FATAL/,/From function/p' "log.$name"
        fi
    done
    [ "$before" = "$after" ] || { echo ">> $name: case directory changed"; fail=1; }
    echo ">> $name: rejected: $(sed -n '/FATAL/{n;p}' "log.$name" | head -1 | sed 's/^Solid mesh .* rejected:$//')$(grep -m1 -E '^ +(points|triangles) [0-9]' "log.$name" | sed 's/^ *//')"
}
# Unit square, two triangles
makeCase valid '4((0 0) (1 0) (1 1) (0 1))' '2((0 1 2) (0 2 3))'
makeCase inverted '4((0 0) (1 0) (1 1) (0 1))' '2((0 1 2) (0 3 2))'
makeCase duplicate '5((0 0) (1 0) (1 1) (0 1) (0 0))' '2((0 1 2) (4 2 3))'
makeCase overlap '6((0 0) (1 0) (1 1) (0.2 0.1) (1.2 0.1) (1.2 1.1))' '2((0 1 2) (3 4 5))'
makeCase nonManifold '5((0 0) (1 0) (0.5 1) (0.5 -1) (0.6 -2))' '3((0 1 2) (1 0 3) (1 0 4))'

expectRejected inverted "triangle 1" "inverted" "solidMesh"
expectRejected duplicate "points 0 and 4" "triangles (0) and (1)"
expectRejected overlap "overlapping" "triangles 0 (rock) and 1 (rock)"
expectRejected nonManifold "Non-manifold edge" "triangle 2"

if femdemMeshCheck -case valid -vtk > log.valid 2>&1 && grep -q "Mesh OK" log.valid \
   && [ -f valid/VTK/solidMeshCheck_0.vtu ]; then
    echo ">> valid: accepted ($(grep -m1 'joints:' log.valid | sed 's/^ *//'))"
else
    echo ">> valid: REJECTED"; tail -20 log.valid; fail=1
fi
exit $fail
