#!/usr/bin/env bash
# Installs the Debian 12 packages lbm-pore needs, only those that are missing.
# --no-install-recommends matters: liggghts recommends paraview, whose python3-paraview
# conflicts with python3-vtk9 (pulled in by libvtk9-dev).
set -euo pipefail
packages=(cmake g++ make pkg-config liggghts libliggghts-dev liggghts-doc libvtk9-dev libeigen3-dev
          libopenmpi-dev openmpi-bin libgtest-dev python3 python3-numpy python3-matplotlib python3-vtk9
          clang libclang-rt-14-dev  # libFuzzer for tests/fuzz (skipped without them)
          libplb-dev)               # Palabos, for bench_lbm's side-by-side figure (skipped without it)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
