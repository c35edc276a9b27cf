#!/usr/bin/env bash
# Installs what is missing, builds lbm-pore in ./build and runs the main example,
# examples/pore/in.pore (the paper's pore clogging and bursting), on 2 MPI ranks.
# Output goes to ./example_output: log.liggghts; bursts.txt (one row per erosive burst);
# pressure_loss.png (P / P_out against time with the bursts marked, the deposit on a panel
# below); snapshot_peak.png (the pore at the run's highest pressure peak: the fluid's speed on a
# slice through the pore's axis, the particles coloured by drag per mass, from the VTK frame
# nearest the peak); summary.txt (the run and each burst with the deposit it tore off); and
# fluid_vtk/fluid.pvd and particles_vtk/*.vtp for ParaView (examples/pore/view_pore.py).
# The snapshot is only as near the peak as the VTK files are frequent (in.pore's vtk_every,
# in fluid steps); it says how far it lies from the peak.
# Extra arguments go to liggghts-lbm, e.g.  tools/run_example.sh -var steps 300000
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
tools/install_deps.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
# Debian's interpreter has python3-matplotlib; a python3 earlier on PATH may not.
python=/usr/bin/python3
[ -x "$python" ] || python=python3
ranks=$(( $(nproc) >= 2 ? 2 : 1 ))
# The cores shared out: one OpenMP thread per rank on 2 cores, more on larger machines (the
# results are the same bit for bit on any number of threads).
export OMP_NUM_THREADS=$(( $(nproc) / ranks ))
# mpirun binds each of up to 2 ranks to one core: a rank's threads would all share it.
bind=()
[ "$OMP_NUM_THREADS" -gt 1 ] && bind=(--bind-to none)
mkdir -p example_output
cd example_output
start=$(date +%s)
mpirun "${bind[@]}" -np "$ranks" "$root/build/liggghts_plugin/liggghts-lbm" -in "$root/examples/pore/in.pore" "$@"
echo "example: $(( $(date +%s) - start )) s on $ranks rank(s)"
"$python" "$root/examples/pore/plot_pressure.py" log.liggghts --fix pore --bursts bursts.txt --out pressure_loss.png
"$python" "$root/examples/pore/summarize_run.py" log.liggghts --fix pore --bursts bursts.txt | tee summary.txt
if ls fluid_vtk/fluid_*.*vti >/dev/null 2>&1; then
  "$python" "$root/examples/paper/render_snapshot.py" . --at peak --out snapshot_peak.png
else
  echo "no fluid_vtk/fluid_*.vti (vtk_every 0): no snapshot_peak.png"
fi
