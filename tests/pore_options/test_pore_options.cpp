#include <gtest/gtest.h>

#include <sstream>

#include "lbm/input_error.h"
#include "lbm_pore_options.h"
#include "pore_scene_setup.h"
#include "split_words.h"

namespace {
std::string error_of(const std::string& line) {
  try {
    lbm_pore::parse_pore_options(split(line));
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}
const std::string kScene =
    " scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3.5 velocity 0.01";
}  // namespace

TEST(PoreOptions, PaperSceneWithDefaults) {
  const auto o = lbm_pore::parse_pore_options(split("dx 0.142857" + kScene));
  EXPECT_DOUBLE_EQ(o.dx, 0.142857);
  EXPECT_EQ(o.scene, lbm_pore::PoreOptions::Scene::kPore);
  EXPECT_DOUBLE_EQ(o.pore_diameter, 3.5);
  EXPECT_DOUBLE_EQ(o.pore_length, 4);
  EXPECT_EQ(o.n_dem, 100);
  EXPECT_DOUBLE_EQ(o.nu, 1.0 / 6.0);
  EXPECT_EQ(o.boundary, "mls");
  EXPECT_TRUE(o.lubrication);
  EXPECT_TRUE(o.mass_correction);
  EXPECT_TRUE(o.mass_correction_in_kernel);
  EXPECT_FALSE(o.keep_reference_pressure);
  EXPECT_FALSE(o.substep_fraction);
  EXPECT_EQ(o.checkpoint_keep, 0);
  EXPECT_EQ(o.drive, lbm_pore::PoreOptions::Drive::kVelocity);
}

TEST(PoreOptions, AllKeywords) {
  const auto o = lbm_pore::parse_pore_options(
      split("dx 1 rho 2 nu 0.1 n_dem 50 magic 0.25 scene voxels g.raw origin 0 1 2 lateral wall "
            "pressure_loss 0.02 boundary bouzidi mass_correction no lubrication no lubrication_cutoff 0.5 "
            "deposit_speed 0.001 vtk 10 out checkpoint ck reference_pressure keep checkpoint_keep 2 deposit_region pore "
            "substep_force fraction deposit_speeds 500 speeds.txt"));
  EXPECT_EQ(o.deposit_speeds_every, 500);
  EXPECT_EQ(o.deposit_speeds_file, "speeds.txt");
  EXPECT_EQ(o.voxel_file, "g.raw");
  EXPECT_FALSE(o.lateral_periodic);
  EXPECT_EQ(o.drive, lbm_pore::PoreOptions::Drive::kPressureLoss);
  EXPECT_DOUBLE_EQ(o.drive_value, 0.02);
  EXPECT_EQ(o.vtk_every, 10);
  EXPECT_EQ(o.vtk_directory, "out");
  EXPECT_FALSE(o.lubrication);
  EXPECT_FALSE(o.mass_correction);
  EXPECT_EQ(o.checkpoint_prefix, "ck");
  EXPECT_TRUE(o.keep_reference_pressure);
  EXPECT_EQ(o.checkpoint_keep, 2);
  EXPECT_TRUE(o.deposits_in_pore_only);
  EXPECT_TRUE(o.substep_fraction);
}

TEST(PoreOptions, ACeilingOnTheVelocityInletsLoss) {
  const auto o = lbm_pore::parse_pore_options(split("dx 1" + kScene + " max_pressure_loss 0.05"));
  EXPECT_EQ(o.drive, lbm_pore::PoreOptions::Drive::kVelocity);
  EXPECT_DOUBLE_EQ(o.max_pressure_loss, 0.05);
  EXPECT_EQ(lbm_pore::parse_pore_options(split("dx 1" + kScene)).max_pressure_loss, 0.0);
}

TEST(PoreOptions, MassCorrectionInTheKernel) {
  const auto o = lbm_pore::parse_pore_options(split("dx 1 mass_correction kernel" + kScene));
  EXPECT_TRUE(o.mass_correction);
  EXPECT_TRUE(o.mass_correction_in_kernel);
  EXPECT_TRUE(lbm_pore::coupling_options(o).correct_mass_in_kernel);
  EXPECT_TRUE(lbm_pore::coupling_options(lbm_pore::parse_pore_options(split("dx 1" + kScene)))
                  .correct_mass_in_kernel);
  EXPECT_FALSE(lbm_pore::coupling_options(lbm_pore::parse_pore_options(split("dx 1 mass_correction sweep" + kScene)))
                   .correct_mass_in_kernel);
}

TEST(PoreOptions, MovingWallsInTheKernel) {
  EXPECT_TRUE(lbm_pore::coupling_options(lbm_pore::parse_pore_options(split("dx 1" + kScene)))
                  .moving_walls_in_kernel);
  EXPECT_TRUE(lbm_pore::coupling_options(lbm_pore::parse_pore_options(split("dx 1 moving_walls kernel" + kScene)))
                  .moving_walls_in_kernel);
  EXPECT_FALSE(lbm_pore::coupling_options(lbm_pore::parse_pore_options(split("dx 1 moving_walls sweep" + kScene)))
                   .moving_walls_in_kernel);
}

TEST(PoreOptions, BadValuesNameTheKeywordAndRange) {
  EXPECT_NE(error_of("dx -1" + kScene).find("'dx' = '-1': must be a number in (0, inf]"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 n_dem 0" + kScene).find("'n_dem' = '0': must be an integer in [1, 100000]"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 magic abc" + kScene).find("'magic'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 boundary curved" + kScene).find("bounce_back, bouzidi or mls"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 colour red" + kScene).find("unknown keyword 'colour'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 mass_correction 1" + kScene).find("'mass_correction' = '1': must be yes, sweep, kernel or no"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 moving_walls fused" + kScene).find("'moving_walls' = 'fused': must be 'kernel' or 'sweep'"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 reference_pressure literal" + kScene).find("'reference_pressure' = 'literal': must be 'remove' or 'keep'"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 substep_force half" + kScene).find("'substep_force' = 'half': must be 'held' or 'fraction'"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 deposit_region inlet" + kScene).find("'deposit_region' = 'inlet': must be 'from_inlet' or 'pore'"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 deposit_speeds 0 s.txt" + kScene).find("'deposit_speeds' = '0': must be an integer in [1,"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 checkpoint_keep -1" + kScene).find("'checkpoint_keep' = '-1': must be an integer in [0,"),
            std::string::npos);
  EXPECT_NE(error_of(kScene).find("'dx'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 velocity 0.1").find("'scene' is required"), std::string::npos);
  EXPECT_NE(error_of("dx 1 scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 6 velocity 1")
                .find("must be <= width"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 scene pore inlet 3 free 2").find("'scene pore'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 lubrication maybe" + kScene).find("yes or no"), std::string::npos);
  EXPECT_NE(error_of("dx 1 scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3")
                .find("drive is required"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1 vtk 10").find("'vtk (directory)' needs a value"), std::string::npos);
  // The ceiling on the loss caps a velocity inlet: with a pressure drive or a closed box it
  // would silently do nothing.
  EXPECT_NE(error_of("dx 1 scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3 pressure_loss 0.01 "
                     "max_pressure_loss 0.02")
                .find("'max_pressure_loss' caps the pressure loss of a velocity inlet"),
            std::string::npos);
  EXPECT_NE(error_of("dx 1" + kScene + " max_pressure_loss 0").find("'max_pressure_loss' = '0': must be a number in (0,"),
            std::string::npos);
  // Two drives used to be accepted silently, the last one winning.
  EXPECT_NE(error_of("dx 1" + kScene + " pressure_loss 0.01").find("exclude each other"),
            std::string::npos);
}

TEST(PoreOptions, EveryKeywordAtMostOnce) {
  // The last one used to win silently.
  for (const char* twice : {"dx 1 dx 2", "dx 1 nu 0.1 nu 0.2", "dx 1 vtk 10 a vtk 20 b",
                            "dx 1 boundary mls boundary mls", "dx 1 lateral wall lateral periodic"})
    EXPECT_NE(error_of(twice + kScene).find("is given twice; give it once"), std::string::npos)
        << twice;
  EXPECT_EQ(error_of("dx 1" + kScene + " velocity 0.02"),
            "fix lbm/pore: keyword 'velocity' is given twice; give it once");
  EXPECT_NE(error_of("dx 1" + kScene + " scene voxels a.raw").find("'scene' is given twice"),
            std::string::npos);
}

TEST(PoreOptions, HexInfAndNanAreRefusedNamingTheirKeyword) {
  // std::strtod reads "0x10" as 16, which then failed later naming another keyword.
  EXPECT_EQ(error_of("dx 0x10" + kScene),
            "fix lbm/pore: keyword 'dx' = '0x10': must be a number in (0, inf]");
  EXPECT_NE(error_of("dx 1 nu inf" + kScene).find("'nu' = 'inf'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 rho nan" + kScene).find("'rho' = 'nan'"), std::string::npos);
  EXPECT_NE(error_of("dx 1 n_dem 0x10" + kScene).find("'n_dem' = '0x10'"), std::string::npos);
  EXPECT_NE(
      error_of("dx 1 scene pore inlet 0x3 free 2 length 4 outlet 3 width 5 diameter 3 velocity 0")
          .find("'scene pore inlet' = '0x3'"),
      std::string::npos);
}

TEST(PoreOptions, NegativeDrivesAreRefusedAndZeroIsAClosedBox) {
  const std::string scene = "dx 1 scene pore inlet 3 free 2 length 4 outlet 3 width 5 diameter 3.5";
  EXPECT_NE(error_of(scene + " velocity -0.01")
                .find("'velocity' = '-0.01': must be a number in [0, inf]"),
            std::string::npos);
  EXPECT_NE(error_of(scene + " pressure_loss -1").find("'pressure_loss' = '-1'"),
            std::string::npos);
  EXPECT_EQ(lbm_pore::parse_pore_options(split(scene + " velocity 0")).drive_value, 0.0);
}
