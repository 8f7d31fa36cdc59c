#!/bin/bash
# Acceptance: a solid mesh of about 1e5 triangles is generated (femdemMesh,
# CGAL) and converted (jointTopology + continuousView) in under 10 s; the
# figures printed are those of benchmarks/solidMesh/run, which this runs
# (it also measures the METIS renumbering on triangle and joint loops).
set -eu
cd "$JWLIBFOAM_TEST_DIR"
bash "$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/benchmarks/solidMesh/run"
