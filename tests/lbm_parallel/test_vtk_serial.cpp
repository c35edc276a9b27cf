// VTK series on one rank: the image read back has the global extent, physical origin and
// spacing, and the values of compute_fields; the .pvd lists every file with its time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "flow_setup.h"
#include "lbm/decomposition.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"
#include "lbm/vtk_output.h"

#ifdef LBM_PORE_HAVE_VTK
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>
#endif

namespace {
using namespace lbm_parallel_test;

#ifdef LBM_PORE_HAVE_VTK

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(VtkSeries, SerialImageRoundTrip) {
  const FlowCase c = body_force_channel();
  lbm::FluidSolver solver(c.geometry, c.parameters, c.drive, serial_decomposition(c));
  start(solver);
  for (int s = 0; s < 10; ++s) solver.step();

  const std::filesystem::path dir = std::filesystem::path("vtk_serial_out") / "nested";
  std::filesystem::remove_all("vtk_serial_out");
  lbm::VtkSeriesWriter writer(dir.string(), "fluid");
  writer.write(solver, 0.25);
  const lbm::MacroscopicFields fields = lbm::compute_fields(solver);
  for (int s = 0; s < 5; ++s) solver.step();
  writer.write(solver, 0.375);

  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName((dir / "fluid_000010.vti").string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int extent[6];
  image->GetExtent(extent);
  EXPECT_EQ(extent[0], 0);
  EXPECT_EQ(extent[1], 11);
  EXPECT_EQ(extent[2], 0);
  EXPECT_EQ(extent[3], 9);
  EXPECT_EQ(extent[4], 0);
  EXPECT_EQ(extent[5], 5);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(origin[a], c.geometry.origin()[a]);
    EXPECT_DOUBLE_EQ(spacing[a], 0.1);
  }
  vtkDataArray* density = image->GetPointData()->GetArray("density");
  vtkDataArray* pressure = image->GetPointData()->GetArray("pressure");
  vtkDataArray* velocity = image->GetPointData()->GetArray("velocity");
  vtkDataArray* node_type = image->GetPointData()->GetArray("node_type");
  ASSERT_TRUE(density && pressure && velocity && node_type);
  ASSERT_EQ(density->GetNumberOfTuples(), vtkIdType(fields.density.size()));
  ASSERT_EQ(velocity->GetNumberOfComponents(), 3);
  int solid = 0;
  for (vtkIdType n = 0; n < density->GetNumberOfTuples(); ++n) {
    EXPECT_EQ(density->GetTuple1(n), fields.density[n]);
    EXPECT_DOUBLE_EQ(pressure->GetTuple1(n), fields.density[n] / 3.0);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(velocity->GetComponent(n, a), fields.velocity[3 * n + a]);
    EXPECT_EQ(node_type->GetTuple1(n), fields.node_type[n]);
    solid += node_type->GetTuple1(n) == lbm::kSolid;
  }
  EXPECT_EQ(solid, int(c.geometry.count_solid()));
  // The point (i,j,k) is node (i,j,k) of the geometry: spot-check a solid voxel.
  const vtkIdType voxel = image->ComputePointId(std::array<int, 3>{9, 7, 1}.data());
  EXPECT_EQ(node_type->GetTuple1(voxel), lbm::kSolid);

  const std::string pvd = read_text(dir / "fluid.pvd");
  const std::regex entry("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  std::vector<std::pair<double, std::string>> listed;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator();
       ++it)
    listed.emplace_back(std::stod((*it)[1]), (*it)[2]);
  ASSERT_EQ(listed.size(), 2u) << pvd;
  EXPECT_EQ(listed[0], (std::pair<double, std::string>{0.25, "fluid_000010.vti"}));
  EXPECT_EQ(listed[1], (std::pair<double, std::string>{0.375, "fluid_000015.vti"}));
  EXPECT_TRUE(std::filesystem::exists(dir / "fluid_000015.vti"));
}

std::vector<std::pair<double, std::string>> pvd_entries(const std::filesystem::path& pvd) {
  const std::string text = read_text(pvd);
  const std::regex entry("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  std::vector<std::pair<double, std::string>> listed;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    listed.emplace_back(std::stod((*it)[1]), (*it)[2]);
  return listed;
}

// A writer created after a restart continues the series; a fresh run (time 0) restarts it.
TEST(VtkSeries, ResumedRunContinuesTheSeries) {
  const FlowCase c = body_force_channel();
  lbm::FluidSolver solver(c.geometry, c.parameters, c.drive, serial_decomposition(c));
  const std::filesystem::path dir = "vtk_resume_out";
  std::filesystem::remove_all(dir);
  {
    lbm::VtkSeriesWriter first(dir.string(), "fluid");
    for (int s = 0; s < 3; ++s) {
      first.write(solver, 0.5 * s);
      solver.step();
    }
  }
  solver.set_time_step(1);  // resumed from a checkpoint at step 1 (time 0.5)
  lbm::VtkSeriesWriter resumed(dir.string(), "fluid");
  resumed.write(solver, 0.5);
  using Entries = std::vector<std::pair<double, std::string>>;
  EXPECT_EQ(pvd_entries(dir / "fluid.pvd"),
            (Entries{{0.0, "fluid_000000.vti"}, {0.5, "fluid_000001.vti"}}));
  lbm::VtkSeriesWriter fresh(dir.string(), "fluid");
  solver.set_time_step(0);
  fresh.write(solver, 0.0);
  EXPECT_EQ(pvd_entries(dir / "fluid.pvd"), (Entries{{0.0, "fluid_000000.vti"}}));
}

TEST(VtkSeries, AvailableWithVtk) { EXPECT_TRUE(lbm::VtkSeriesWriter::available()); }

#else

TEST(VtkSeries, ConstructorSaysVtkIsNeeded) {
  EXPECT_FALSE(lbm::VtkSeriesWriter::available());
  try {
    lbm::VtkSeriesWriter writer("out", "fluid");
    FAIL() << "no exception";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs VTK"), std::string::npos);
  }
}

#endif

}  // namespace
