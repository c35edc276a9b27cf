#!/usr/bin/env bash
# Installs what is missing, builds lbm-pore in ./build and runs the whole test suite (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
# Open MPI refuses to run as root without these; the CI machines run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
