// Memory estimates (lbm/memory_estimate.h): a lattice that does not fit is refused with its size
// and the memory available, before it is allocated.
#include <gtest/gtest.h>

#include <string>

#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"
#include "lbm/population_field.h"
#include "lbm/pore_scene.h"
#include "lbm/real.h"

TEST(MemoryEstimate, LatticeBytesCountThePopulationFieldNodeTypesAndTheGeometry) {
  // 4 x 5 x 6 owned nodes, one ghost layer: 6 x 7 x 8 = 336 cells. One population field
  // streamed in place: 19 arrays of the 336 cells and a padding of 6 x 7 + 6 = 48 values
  // (whole lines: 48 doubles, 48 floats) at both ends; a type byte per cell; a byte per
  // voxel of the 10 x 10 x 10 global geometry.
  EXPECT_EQ(lbm::lattice_bytes({4, 5, 6}, {10, 10, 10}, 8), 19.0 * (336 + 2 * 48) * 8 + 336 + 1000.0);
  EXPECT_EQ(lbm::lattice_bytes({4, 5, 6}, {10, 10, 10}, 4), 19.0 * (336 + 2 * 48) * 4 + 336 + 1000.0);
  // The estimate is what the field allocates: a 90 x 20 x 40 block (the paper's rank).
  const lbm::Box box{{0, 0, 0}, {90, 20, 40}};
  const lbm::BlockLayout layout(box);
  const lbm::PopulationField field(layout);
  EXPECT_EQ(lbm::lattice_bytes({90, 20, 40}, {90, 40, 40}),
            double(field.raw().size() * sizeof(lbm::Real)) + double(layout.num_cells()) +
                90.0 * 40 * 40);
  EXPECT_EQ(lbm::lattice_bytes({4, 5, 6}, {10, 10, 10}),
            lbm::lattice_bytes({4, 5, 6}, {10, 10, 10}, sizeof(lbm::Real)));
  // No overflow for absurd sizes.
  EXPECT_GT(lbm::geometry_bytes({1 << 30, 1 << 30, 1 << 30}), 1e27);
}

TEST(MemoryEstimate, AvailableMemoryIsPositiveAndBelowAPetabyte) {
  const double available = lbm::available_memory_bytes();
  EXPECT_GT(available, 0.0);
  EXPECT_LT(available, 1e15);
  EXPECT_EQ(lbm::format_bytes(512), "512 bytes");
  EXPECT_EQ(lbm::format_bytes(1.5 * 1024 * 1024 * 1024), "1.5 GiB");
}

TEST(MemoryEstimate, TooLargeIsRefusedWithBothFiguresAndTheHint) {
  lbm::check_fits_in_memory(1e6, "small");  // below 64 MiB: never refused
  try {
    lbm::check_fits_in_memory(1e15, "the lattice", "raise dx");
    FAIL();
  } catch (const lbm::InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("the lattice needs 909 TiB, more than the ", 0), 0u) << what;
    EXPECT_NE(what.find(" of memory available; raise dx"), std::string::npos) << what;
  }
}

TEST(MemoryEstimate, AGeometryThatDoesNotFitIsRefusedByItsConstructor) {
  lbm::PoreSceneSpec spec;
  spec.inlet_length = 1 << 20;
  spec.width = 1 << 20;
  try {
    lbm::make_pore_scene(spec);
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("voxel geometry: 1048646 x 1048576 x 1048576 voxels"),
              std::string::npos)
        << e.what();
  }
}
