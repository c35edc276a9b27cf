// bench_contact: the same dense packing run with pair_style lbm/dashdot (the paper's contact
// + cohesion) and with stock `pair_style gran model hooke tangential history`, in one
// process. Prints the per-particle-step cost of each (whole time step and pair part) and
// their ratio as `BENCH <name> <value> <unit>` lines. Goal: ratio <= 1.2.
//
// usage: bench_contact [particles_per_side (default 20)] [steps (default 2000)]
//        mpirun -np 2 bench_contact ...   (the LIGGGHTS domain decomposition)
#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "input.h"
#include "lammps.h"
#include "registry/style_registry.h"
#include "timer.h"

namespace {

struct Timing {
  double loop_seconds = 0.0;
  double pair_seconds = 0.0;
};

// The packing: a simple-cubic lattice of particles (R = 3.5, density 2.3, the paper's lattice
// units) compressed to 1.4 % overlap in a periodic box, with a shear-like velocity field so
// contacts open and close during the run.
std::vector<std::string> packing_commands(int per_side) {
  const double spacing = 6.9;
  const std::string length = std::to_string(per_side * spacing);
  return {
      "atom_style granular",
      "atom_modify map array",
      "boundary p p p",
      "newton off",
      "communicate single vel yes",
      "units si",
      "soft_particles yes",
      "region box block 0 " + length + " 0 " + length + " 0 " + length + " units box",
      "create_box 1 box",
      "lattice sc " + std::to_string(spacing),
      "create_atoms 1 box",
      "set atom * diameter 7.0",
      "set atom * density 2.3",
      "velocity all ramp vx -0.002 0.002 y 0 " + length + " sum yes units box",
      "velocity all ramp vy -0.002 0.002 z 0 " + length + " sum yes units box",
      "velocity all ramp vz -0.002 0.002 x 0 " + length + " sum yes units box",
      "neighbor 1.0 bin",
      "neigh_modify delay 0",
      "timestep 1.0",
      "fix integrate all nve/sphere",
      "thermo 0",
  };
}

Timing run_case(const std::vector<std::string>& pair_commands, int per_side, int steps) {
  char arg0[] = "bench_contact", log_flag[] = "-log", none1[] = "none", screen_flag[] = "-screen",
       none2[] = "none";
  char* argv[] = {arg0, log_flag, none1, screen_flag, none2};
  // LIGGGHTS fills a process-wide granular style table while building an instance and warns
  // on stderr (hundreds of lines) when a second instance fills it again: harmless here, so
  // keep the benchmark's output readable by muting stderr while the instance is built.
  std::fflush(stderr);
  const int saved_stderr = dup(2);
  const int null_fd = open("/dev/null", O_WRONLY);
  dup2(null_fd, 2);
  auto* lmp = new LAMMPS_NS::LAMMPS(5, argv, MPI_COMM_WORLD);
  dup2(saved_stderr, 2);
  close(null_fd);
  close(saved_stderr);
  lbm_pore::register_lbm_pore_styles(lmp);
  for (const std::string& c : packing_commands(per_side)) lmp->input->one(c.c_str());
  for (const std::string& c : pair_commands) lmp->input->one(c.c_str());
  lmp->input->one("run 100");  // warm-up: neighbour lists, contact history allocated
  // The fastest of three runs (least disturbed by other processes on the machine). One
  // LAMMPS instance per style: LIGGGHTS's granular style table warns when built twice.
  Timing best{1e300, 1e300};
  for (int repeat = 0; repeat < 3; ++repeat) {
    lmp->input->one(("run " + std::to_string(steps)).c_str());
    if (lmp->timer->array[TIME_LOOP] < best.loop_seconds) {
      best.loop_seconds = lmp->timer->array[TIME_LOOP];
      best.pair_seconds = lmp->timer->array[TIME_PAIR];
    }
  }
  delete lmp;
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int per_side = argc > 1 ? std::atoi(argv[1]) : 20;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 2000;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);

  const std::vector<std::string> dashdot = {
      "pair_style lbm/dashdot kn 0.1 kc 0.1 damping 0.25",
      "pair_coeff * *",
  };
  // Stock LIGGGHTS hooke with material constants giving a stiffness of the same order
  // (Young's modulus 0.182 -> k_n ~ 0.1 at the characteristic velocity 0.01).
  const std::vector<std::string> hooke = {
      "fix m1 all property/global youngsModulus peratomtype 0.182",
      "fix m2 all property/global poissonsRatio peratomtype 0.3",
      "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.44",
      "fix m4 all property/global coefficientFriction peratomtypepair 1 0.1",
      "fix m5 all property/global characteristicVelocity scalar 0.01",
      "pair_style gran model hooke tangential history",
      "pair_coeff * *",
  };

  // The wall fix's cost: the packing sits in the inlet region of a pore scene (no wall
  // contacts, so it measures the voxel search every particle pays each step).
  const int scene_inlet = static_cast<int>(per_side * 6.9) + 2;
  std::vector<std::string> dashdot_wall = dashdot;
  dashdot_wall.push_back("fix walls all wall/voxel pore inlet_length " +
                         std::to_string(scene_inlet) + " free_length 10 pore_length 10 " +
                         "outlet_length 10 width " + std::to_string(scene_inlet) +
                         " pore_diameter 10 origin 0 0 0");
  const Timing best_dashdot = run_case(dashdot, per_side, steps);
  const Timing best_wall = run_case(dashdot_wall, per_side, steps);
  const Timing best_hooke = run_case(hooke, per_side, steps);

  if (rank == 0) {
    const double particle_steps = double(per_side) * per_side * per_side * steps;
    const double to_ns = 1e9 * ranks / particle_steps;  // core-nanoseconds per particle-step
    std::printf("BENCH particles %d count\n", per_side * per_side * per_side);
    std::printf("BENCH steps %d count\n", steps);
    std::printf("BENCH ranks %d count\n", ranks);
    std::printf("BENCH lbm_dashdot_step %.2f ns/particle-step\n", best_dashdot.loop_seconds * to_ns);
    std::printf("BENCH gran_hooke_step %.2f ns/particle-step\n", best_hooke.loop_seconds * to_ns);
    std::printf("BENCH lbm_dashdot_pair %.2f ns/particle-step\n", best_dashdot.pair_seconds * to_ns);
    std::printf("BENCH gran_hooke_pair %.2f ns/particle-step\n", best_hooke.pair_seconds * to_ns);
    std::printf("BENCH wall_voxel_search %.2f ns/particle-step\n",
                (best_wall.loop_seconds - best_dashdot.loop_seconds) * to_ns);
    std::printf("BENCH contact_vs_gran_hooke %.3f ratio\n",
                best_dashdot.loop_seconds / best_hooke.loop_seconds);
    std::printf("BENCH contact_vs_gran_hooke_pair_only %.3f ratio\n",
                best_dashdot.pair_seconds / best_hooke.pair_seconds);
  }
  MPI_Finalize();
  return 0;
}
