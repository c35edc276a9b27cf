// VTK series on 2 ranks: the .pvti read back through vtkXMLPImageDataReader is the whole
// lattice, gap-free (pieces share their boundary points) and equal to the fields of a
// serial run; the .pvd lists the .pvti files with their times.
#include <gtest/gtest.h>
#include <mpi.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "flow_setup.h"
#include "lbm/decomposition.h"
#include "lbm/macroscopic.h"
#include "lbm/vtk_output.h"

#ifdef LBM_PORE_HAVE_VTK
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLPImageDataReader.h>

namespace {
using namespace lbm_parallel_test;

void write_and_check(int split, const std::string& name) {
  const lbm::Communicator world(MPI_COMM_WORLD);
  const FlowCase c = body_force_channel();
  lbm::Box global;
  global.hi = c.geometry.dims();
  std::array<int, 3> procs{1, 1, 1};
  procs[split] = 2;
  lbm::FluidSolver parallel(c.geometry, c.parameters, c.drive,
                            lbm::Decomposition::grid(global, c.parameters.periodic, procs, world));
  lbm::FluidSolver serial(c.geometry, c.parameters, c.drive, serial_decomposition(c));
  start(parallel);
  start(serial);
  for (int s = 0; s < 30; ++s) {
    parallel.step();
    serial.step();
  }
  const std::filesystem::path dir = "vtk_mpi_out_" + name;
  if (world.rank() == 0) std::filesystem::remove_all(dir);
  world.barrier();
  lbm::VtkSeriesWriter writer(dir.string(), "flow");
  writer.write(parallel, 1.5);
  parallel.step();
  writer.write(parallel, 1.55);

  // Each piece: owned nodes plus the first layer of the rank above along the split, in
  // global indices (its WholeExtent is the global one, as in VTK's own parallel files).
  const auto& owned = parallel.decomposition().owned;
  {
    std::ifstream in(dir / ("flow_000030_" + std::to_string(world.rank()) + ".vti"));
    std::string header(4096, '\0');
    in.read(&header[0], std::streamsize(header.size()));
    const std::size_t at = header.find("<Piece Extent=\"");
    ASSERT_NE(at, std::string::npos);
    std::istringstream numbers(header.substr(at + 15));
    int piece[6];
    for (int& e : piece) numbers >> e;
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(piece[2 * a], owned.lo[a]);
      EXPECT_EQ(piece[2 * a + 1], owned.hi[a] - (owned.hi[a] < global.hi[a] ? 0 : 1))
          << "axis " << a;
    }
    EXPECT_NE(header.find("WholeExtent=\"0 11 0 9 0 5\""), std::string::npos);
  }
  int extent[6];
  world.barrier();
  if (world.rank() != 0) return;

  vtkNew<vtkXMLPImageDataReader> reader;
  reader->SetFileName((dir / "flow_000030.pvti").string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  image->GetExtent(extent);
  const int whole[6] = {0, 11, 0, 9, 0, 5};
  for (int e = 0; e < 6; ++e) EXPECT_EQ(extent[e], whole[e]);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(origin[a], c.geometry.origin()[a]);
    EXPECT_DOUBLE_EQ(spacing[a], c.geometry.spacing());
  }
  const lbm::MacroscopicFields expected = lbm::compute_fields(serial);
  vtkDataArray* density = image->GetPointData()->GetArray("density");
  vtkDataArray* pressure = image->GetPointData()->GetArray("pressure");
  vtkDataArray* velocity = image->GetPointData()->GetArray("velocity");
  vtkDataArray* node_type = image->GetPointData()->GetArray("node_type");
  ASSERT_TRUE(density && pressure && velocity && node_type);
  ASSERT_EQ(density->GetNumberOfTuples(), vtkIdType(expected.density.size()));
  double worst = 0.0;
  long long wrong_types = 0;
  for (vtkIdType n = 0; n < density->GetNumberOfTuples(); ++n) {
    worst = std::max(worst, std::abs(density->GetTuple1(n) - expected.density[n]));
    worst = std::max(worst, std::abs(pressure->GetTuple1(n) - expected.density[n] / 3.0));
    for (int a = 0; a < 3; ++a)
      worst =
          std::max(worst, std::abs(velocity->GetComponent(n, a) - expected.velocity[3 * n + a]));
    wrong_types += node_type->GetTuple1(n) != expected.node_type[n];
  }
  EXPECT_LT(worst, 1e-12) << name;
  EXPECT_EQ(wrong_types, 0) << name;

  std::ifstream in(dir / "flow.pvd");
  std::stringstream pvd;
  pvd << in.rdbuf();
  EXPECT_NE(pvd.str().find("timestep=\"1.5\" group=\"\" part=\"0\" file=\"flow_000030.pvti\""),
            std::string::npos)
      << pvd.str();
  EXPECT_NE(pvd.str().find("timestep=\"1.55\" group=\"\" part=\"0\" file=\"flow_000031.pvti\""),
            std::string::npos)
      << pvd.str();
}

TEST(VtkSeriesOnTwoRanks, SplitAlongX) { write_and_check(0, "x"); }
TEST(VtkSeriesOnTwoRanks, SplitAlongY) { write_and_check(1, "y"); }
TEST(VtkSeriesOnTwoRanks, SplitAlongZ) { write_and_check(2, "z"); }

}  // namespace
#endif
