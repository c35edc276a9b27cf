#!/usr/bin/env bash
# Installs what is missing, builds lbm-pore in ./build and runs the main example.
# Output goes to ./example_output (open the .pvd files in ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
mkdir -p example_output
build/examples/pore_fluid/pore_fluid steps=3000 output_every=500 print_every=250 \
  output=example_output/pore_fluid
