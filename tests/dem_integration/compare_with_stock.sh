#!/bin/bash
# Runs a stock LIGGGHTS tutorial (Debian liggghts-doc, packing) with Debian's `liggghts` and
# with `liggghts-lbm` and requires identical thermo lines: the driver must be a drop-in.
# usage: compare_with_stock.sh <liggghts> <liggghts-lbm> <ranks>
set -euo pipefail
stock=$1 driver=$2 ranks=$3
tutorial=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/packing/in.packing
[ -f "$tutorial" ] || { echo "SKIP: $tutorial missing (install liggghts-doc)"; exit 0; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir -p post
# Same script, shorter growth and relaxation phases (the tutorial runs 70000 steps).
sed -e 's/growts equal 50000/growts equal 3000/' -e 's/relaxts equal 20000/relaxts equal 2000/' \
  "$tutorial" > in.packing
launch=()
if [ "$ranks" -gt 1 ]; then launch=(mpirun --allow-run-as-root --oversubscribe -np "$ranks"); fi
"${launch[@]}" "$stock" -in in.packing -log log.stock > screen.stock 2>&1
"${launch[@]}" "$driver" -in in.packing -log log.lbm > screen.lbm 2>&1
# Thermo rows: lines of numbers only (step atoms ke c_1 vol).
thermo() { grep -E '^[[:space:]]*[0-9]+([[:space:]]+[-+0-9.eE]+)+[[:space:]]*$' "$1"; }
thermo log.stock > thermo.stock
thermo log.lbm > thermo.lbm
rows=$(wc -l < thermo.stock)
if [ "$rows" -lt 5 ]; then echo "FAIL: only $rows thermo rows from liggghts"; cat screen.stock; exit 1; fi
if diff thermo.stock thermo.lbm; then
  echo "PASS: $rows thermo rows identical (liggghts vs liggghts-lbm, $ranks rank(s))"
else
  echo "FAIL: thermo output differs"; exit 1
fi
