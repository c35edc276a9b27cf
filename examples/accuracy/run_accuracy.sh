#!/usr/bin/env bash
# Accuracy study: builds accuracy_cases if needed, runs every case on one core, and writes
#   <out_dir>/accuracy.csv                  one row per run (error, reference, wall seconds)
#   <out_dir>/accuracy_error_vs_time.png    error against wall-clock time, one curve per option
#   <out_dir>/accuracy_table.md             Markdown tables
# Usage: examples/accuracy/run_accuracy.sh [build_dir (default: build)] [out_dir (default:
#        <build_dir>/accuracy_output)] [extra accuracy_cases arguments, e.g. --quick]
# A few minutes on one core. The PNG needs python3 with matplotlib (Debian: python3-matplotlib).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-$root/build}"
out="${2:-$build/accuracy_output}"
shift $(( $# < 2 ? $# : 2 ))

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target accuracy_cases -j"$(nproc)"
mkdir -p "$out"

start=$(date +%s)
# One thread: the wall times are those of a single core, comparable between runs.
OMP_NUM_THREADS=1 "$build/examples/accuracy/accuracy_cases" --check --csv "$out/accuracy.csv" "$@" \
  2> >(tee "$out/accuracy_log.txt" >&2) || status=$?
end=$(date +%s)
echo "accuracy study: $((end - start)) s wall-clock; CSV: $out/accuracy.csv"

# A python3 with matplotlib: the one on PATH, else Debian's.
python=""
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" 2>/dev/null; then
    python="$candidate"
    break
  fi
done
if [ -n "$python" ]; then
  "$python" "$here/plot_accuracy.py" "$out/accuracy.csv" --png "$out/accuracy_error_vs_time.png" \
    --markdown "$out/accuracy_table.md"
  echo "plot: $out/accuracy_error_vs_time.png; table: $out/accuracy_table.md"
else
  python3 "$here/plot_accuracy.py" "$out/accuracy.csv" --markdown "$out/accuracy_table.md"
  echo "no python3 with matplotlib (apt-get install python3-matplotlib): table only, $out/accuracy_table.md" >&2
fi
exit "${status:-0}"
