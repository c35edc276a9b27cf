// The argument parsers of pair_style lbm/dashdot and fix wall/voxel, without LIGGGHTS.
#include <gtest/gtest.h>

#include <sstream>

#include "dashdot/dashdot_arguments.h"
#include "lbm/input_error.h"
#include "split_words.h"
#include "wall_voxel/wall_voxel_arguments.h"

namespace {

template <class Parse>
std::string error_of(Parse parse) {
  try {
    parse();
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}

std::string dashdot_error(const std::string& line) {
  contact::PairContactParams p;
  return error_of(
      [&] { lbm_pore::parse_dashdot_coefficients(split(line), p, "pair_style lbm/dashdot"); });
}

std::string wall_error(const std::string& line) {
  return error_of([&] { lbm_pore::parse_wall_voxel_arguments(split(line)); });
}
}  // namespace

TEST(DashdotArguments, SetsTheGivenKeywordsOnly) {
  contact::PairContactParams p;
  const double damping = p.normal.damping_ratio;
  lbm_pore::parse_dashdot_coefficients(split("kn 2.5 kc 0"), p, "pair_coeff lbm/dashdot");
  EXPECT_EQ(p.normal.k_n, 2.5);
  EXPECT_EQ(p.cohesion.k_c, 0.0);
  EXPECT_EQ(p.normal.damping_ratio, damping);
}

TEST(DashdotArguments, BadInputNamesTheKeyword) {
  EXPECT_EQ(dashdot_error("kn 1 kn 2"),
            "pair_style lbm/dashdot: keyword 'kn' is given twice; give it once");
  EXPECT_EQ(dashdot_error("kn 0x10"),
            "pair_style lbm/dashdot: kn must be a number > 0 (got '0x10')");
  EXPECT_EQ(dashdot_error("damping 1.5"),
            "pair_style lbm/dashdot: damping must be a number in [0, 1] (got '1.5')");
  EXPECT_EQ(dashdot_error("kc"), "pair_style lbm/dashdot: keyword 'kc' needs a value");
  EXPECT_NE(dashdot_error("colour red").find("unknown keyword 'colour'"), std::string::npos);
  EXPECT_NE(dashdot_error("kn nan").find("kn must be"), std::string::npos);
}

TEST(WallVoxelArguments, GeometryAndContactKeywords) {
  const auto a = lbm_pore::parse_wall_voxel_arguments(split(
      "pore inlet_length 4 width 9 pore_diameter 5 spacing 0.5 origin 1 2 3 kw 10 ka 1 mu 0.3"));
  EXPECT_EQ(a.source.kind, lbm_pore::WallGeometrySource::Kind::kPoreScene);
  EXPECT_EQ(a.source.pore.inlet_length, 4);
  EXPECT_EQ(a.source.pore.width, 9);
  EXPECT_EQ(a.source.origin[2], 3.0);
  EXPECT_EQ(a.params.normal.k_n, 10.0);
  // kt and the tangential damping follow kw and damping unless given.
  EXPECT_EQ(a.params.friction.k_t, contact::default_tangential_stiffness(10.0));
  EXPECT_EQ(a.params.friction.damping_ratio, a.params.normal.damping_ratio);
  const auto b =
      lbm_pore::parse_wall_voxel_arguments(split("lbm fluid kt 3 tangential_damping 0.1"));
  EXPECT_EQ(b.lbm_fix_id, "fluid");
  EXPECT_EQ(b.params.friction.k_t, 3.0);
  EXPECT_EQ(b.params.friction.damping_ratio, 0.1);
}

TEST(WallVoxelArguments, BadInputNamesTheKeyword) {
  EXPECT_EQ(wall_error("lbm f mu 0.1 mu 0.2"),
            "fix wall/voxel: keyword 'mu' is given twice; give it once");
  EXPECT_NE(wall_error("file a.raw pore").find("give one geometry"), std::string::npos);
  EXPECT_NE(wall_error("kw 1").find("no geometry"), std::string::npos);
  EXPECT_EQ(wall_error("pore width 0x10"),
            "fix wall/voxel: width must be an integer in [1, 1048576] (got '0x10')");
  EXPECT_EQ(wall_error("pore spacing inf"),
            "fix wall/voxel: spacing must be a number > 0 (got 'inf')");
  EXPECT_EQ(wall_error("pore origin 1 2"), "fix wall/voxel: keyword 'origin' needs 3 value(s)");
  EXPECT_EQ(wall_error("lbm f mu -1"), "fix wall/voxel: mu must be a number >= 0 (got '-1')");
  EXPECT_NE(wall_error("lbm f colour red").find("unknown keyword 'colour'"), std::string::npos);
  EXPECT_EQ(wall_error("lbm f kw"), "fix wall/voxel: keyword 'kw' needs a value");
}
