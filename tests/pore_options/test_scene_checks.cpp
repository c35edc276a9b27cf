// The set-up checks of fix lbm/pore that need no LIGGGHTS (pore_scene_setup.h): output paths,
// a scene too large for memory, and what velocity 0 (a closed box) gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lbm/input_error.h"
#include "lbm_pore_options.h"
#include "pore_scene_setup.h"
#include "split_words.h"

namespace {
namespace fs = std::filesystem;

lbm_pore::PoreOptions options_of(const std::string& line) {
  return lbm_pore::parse_pore_options(split(line));
}

const std::string kScene =
    " scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3.5 velocity 0.01";

std::string output_error(const std::string& extra) {
  try {
    lbm_pore::check_output_paths(options_of("dx 1" + kScene + extra));
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}

fs::path scratch(const std::string& name) {
  const fs::path p = fs::path(::testing::TempDir()) / ("scene_checks_" + name);
  fs::remove_all(p);
  return p;
}
}  // namespace

TEST(OutputPaths, WritableFoldersPassAndNothingIsLeftBehind) {
  const fs::path dir = scratch("ok");
  fs::create_directories(dir);
  EXPECT_EQ(output_error(" vtk 10 " + (dir / "new" / "deeper").string() + " checkpoint " +
                         (dir / "ck").string() + " burst_file " + (dir / "bursts.txt").string()),
            "");
  EXPECT_FALSE(fs::exists(dir / "new"));  // checked, not created (the writer creates it)
  EXPECT_TRUE(fs::is_empty(dir));         // the probe file is removed
  EXPECT_EQ(output_error(" vtk 0 /nonexistent_file_for_vtk/x"), "");  // vtk 0: no output, no check
}

TEST(OutputPaths, AFileWhereAFolderIsNeededIsRefusedNamingTheKeyword) {
  const fs::path dir = scratch("file");
  fs::create_directories(dir);
  const fs::path file = dir / "plain_file";
  std::ofstream(file) << "x";
  EXPECT_NE(output_error(" vtk 10 " + file.string())
                .find("vtk: '" + file.string() + "' exists and is not a directory"),
            std::string::npos);
  EXPECT_NE(output_error(" vtk 10 " + (file / "sub").string()).find("is not a directory"),
            std::string::npos);
  EXPECT_NE(output_error(" checkpoint " + (file / "ck").string()).find("checkpoint:"),
            std::string::npos);
  EXPECT_NE(output_error(" burst_file " + dir.string())
                .find("burst_file: '" + dir.string() + "' is a directory"),
            std::string::npos);
}

TEST(OutputPaths, AFolderThatRefusesFilesIsRefused) {
  // /proc refuses new files even to root (the tests run as root, where permissions do not);
  // the project targets Linux (Debian 12), where /proc is always there.
  ASSERT_TRUE(fs::is_directory("/proc")) << "this test needs Linux's /proc";
  EXPECT_NE(output_error(" vtk 10 /proc/lbm_vtk")
                .find("vtk: cannot create files in the directory '/proc'"),
            std::string::npos);
}

TEST(SceneSize, ALatticeTooLargeForMemoryIsRefusedNamingDxBeforeAllocating) {
  const double box_lo[3] = {0, 0, 0};
  try {
    lbm_pore::build_scene(options_of("dx 1e-4" + kScene), box_lo);
    FAIL();
  } catch (const lbm::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("with dx = 0.0001 the lattice has 120000 x 50000 x 50000 nodes"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("of memory available; raise dx"), std::string::npos) << what;
  }
  try {
    lbm_pore::build_scene(options_of("dx 1e-300" + kScene), box_lo);  // cells no longer fit an int
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 2^30 along an axis"), std::string::npos)
        << e.what();
  }
}

TEST(ClosedBox, VelocityZeroIsValidAndDepositsUseTheDefaultSpeed) {
  const lbm_pore::PoreOptions o = options_of(
      "dx 1 scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3.5 "
      "velocity 0");
  const coupling::UnitConversion units(lbm_pore::unit_inputs(o, 0.01));
  const lbm::FlowDrive drive = lbm_pore::drive_of(o, units);
  EXPECT_EQ(drive.inlet_velocity, 0.0);
  // A fraction of 0 would be 0: nothing would ever count as deposited.
  EXPECT_EQ(lbm_pore::deposit_speed_threshold(o, units, drive),
            coupling::DepositionCriteria{}.speed_threshold);
  EXPECT_GT(lbm_pore::deposit_speed_threshold(o, units, drive), 0.0);
}
