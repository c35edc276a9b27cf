// pore_fluid: pure-fluid flow through the paper's pore scene (Jäger et al., Fig. 1),
// driven by an inlet velocity or a pressure loss, with VTK output for ParaView.
// Runs serial or under mpirun (the lattice is split along x).
//
//   pore_fluid [key=value ...]
//     steps=4000 output_every=500 print_every=250 output=pore_fluid_out
//     width=40 inlet=20 free=20 pore_length=30 outlet=20 pore_diameter=25   (cells)
//     tau=1.0 magic=0.1875 inlet_velocity=0.01 pressure_loss=0 (0: velocity drive)
#include <chrono>
#include <memory>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"
#include "lbm/pore_scene.h"
#include "lbm/vtk_output.h"

#ifdef LBM_PORE_HAVE_MPI
#include <mpi.h>
#endif

namespace {

struct Options {
  std::map<std::string, double> values{
      {"steps", 4000},         {"output_every", 500}, {"print_every", 250}, {"width", 40},
      {"inlet", 20},           {"free", 20},          {"pore_length", 30},  {"outlet", 20},
      {"pore_diameter", 25},   {"tau", 1.0},          {"magic", 0.1875},    {"inlet_velocity", 0.01},
      {"pressure_loss", 0.0}};
  std::string output = "pore_fluid_out";

  void parse(int argc, char** argv) {
    for (int a = 1; a < argc; ++a) {
      const std::string arg = argv[a];
      const auto eq = arg.find('=');
      if (eq == std::string::npos) throw lbm::InputError("argument '" + arg + "': expected key=value");
      const std::string key = arg.substr(0, eq), value = arg.substr(eq + 1);
      if (key == "output") {
        output = value;
        continue;
      }
      if (!values.count(key)) throw lbm::InputError("unknown keyword '" + key + "'");
      try {
        values[key] = std::stod(value);
      } catch (const std::exception&) {
        throw lbm::InputError("keyword '" + key + "': '" + value + "' is not a number");
      }
    }
    for (const char* key : {"steps", "output_every", "print_every"})
      if (values[key] < 0) throw lbm::InputError(std::string("keyword '") + key + "' must be >= 0");
  }
  int i(const std::string& key) const { return static_cast<int>(values.at(key)); }
  double d(const std::string& key) const { return values.at(key); }
};

int run(int argc, char** argv, const lbm::Communicator& comm) {
  Options o;
  o.parse(argc, argv);
  lbm::PoreSceneSpec spec;
  spec.width = o.i("width");
  spec.inlet_length = o.i("inlet");
  spec.free_length = o.i("free");
  spec.pore_length = o.i("pore_length");
  spec.outlet_length = o.i("outlet");
  spec.pore_diameter = o.d("pore_diameter");
  const lbm::VoxelGeometry geometry = lbm::make_pore_scene(spec);

  lbm::FluidParameters p;
  p.tau = o.d("tau");
  p.magic = o.d("magic");
  p.periodic = {false, true, true};
  lbm::FlowDrive drive;
  if (o.d("pressure_loss") > 0) {
    drive.kind = lbm::FlowDrive::kPressureLoss;
    drive.pressure_loss = o.d("pressure_loss");
  } else {
    drive.kind = lbm::FlowDrive::kInletVelocity;
    drive.inlet_velocity = o.d("inlet_velocity");
  }
  lbm::Box global;
  global.hi = geometry.dims();
  const auto decomposition =
      lbm::Decomposition::grid(global, p.periodic, {comm.size(), 1, 1}, comm);
  lbm::FluidSolver solver(geometry, p, drive, decomposition);
  const bool root = comm.rank() == 0;
  if (root)
    std::printf("pore_fluid: %d x %d x %d lattice, D = %.1f, L = %d cells, tau = %.3f "
                "(nu = %.4f), %d rank(s)\n",
                geometry.dims()[0], geometry.dims()[1], geometry.dims()[2], spec.pore_diameter,
                spec.pore_length, p.tau, lbm::TrtParameters::viscosity(p.tau), comm.size());

  std::unique_ptr<lbm::VtkSeriesWriter> writer;
  if (o.i("output_every") > 0) {
    if (lbm::VtkSeriesWriter::available())
      writer = std::make_unique<lbm::VtkSeriesWriter>(o.output, "fluid");
    else if (root)
      std::printf("pore_fluid: built without VTK, no fluid output\n");
  }
  const auto regions = lbm::regions_of(spec);
  const auto start = std::chrono::steady_clock::now();
  if (root) std::printf("%8s %14s %14s %14s %10s\n", "step", "pressure_loss", "flux_inlet",
                        "flux_pore", "MLUPS");
  for (int step = 0; step <= o.i("steps"); ++step) {
    if (writer && step % o.i("output_every") == 0) writer->write(solver, step);
    if (o.i("print_every") > 0 && step % o.i("print_every") == 0) {
      const double dp = lbm::pressure_loss(solver);
      const double q_in = lbm::plane_flux(solver, 0, 0);
      const double q_pore = lbm::plane_flux(solver, 0, (regions.pore_begin + regions.pore_end) / 2);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double mlups = step > 0 ? double(global.volume()) * step / seconds / 1e6 : 0.0;
      if (root) std::printf("%8d %14.6e %14.6e %14.6e %10.1f\n", step, dp, q_in, q_pore, mlups);
    }
    if (step < o.i("steps")) solver.step();
  }
  if (root && writer) std::printf("pore_fluid: open %s/fluid.pvd in ParaView\n", o.output.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef LBM_PORE_HAVE_MPI
  MPI_Init(&argc, &argv);
  lbm::Communicator comm(MPI_COMM_WORLD);
#else
  lbm::Communicator comm;
#endif
  int status = 0;
  try {
    status = run(argc, argv, comm);
  } catch (const lbm::InputError& e) {
    if (comm.rank() == 0) std::fprintf(stderr, "pore_fluid: ERROR: %s\n", e.what());
    status = 1;
  }
#ifdef LBM_PORE_HAVE_MPI
  MPI_Finalize();
#endif
  return status;
}
