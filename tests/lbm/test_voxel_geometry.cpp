// Voxel geometry, the paper's pore scene builder, and voxel files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "lbm/input_error.h"
#include "lbm/pore_scene.h"
#include "lbm/voxel_file.h"

namespace {
std::string temp_path(const std::string& name) { return ::testing::TempDir() + name; }

std::string error_of(const std::string& path) {
  try {
    lbm::load_voxel_file(path);
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(PoreScene, RegionsAndPoreCrossSection) {
  // inlet, free, pore, outlet lengths, width, pore diameter (cells)
  lbm::PoreSceneSpec spec{5, 7, 11, 3, 41, 30.0};
  const lbm::VoxelGeometry g = lbm::make_pore_scene(spec);
  EXPECT_EQ(g.dims()[0], 26);
  const auto r = lbm::regions_of(spec);
  EXPECT_EQ(r.pore_begin, 12);
  EXPECT_EQ(r.pore_end, 23);
  // Open area of a pore plane against pi D^2 / 4: staircase error below 2 %.
  int open = 0;
  for (int k = 0; k < spec.width; ++k)
    for (int j = 0; j < spec.width; ++j) open += !g.is_solid(r.pore_begin, j, k);
  const double area = M_PI * 30.0 * 30.0 / 4.0;
  EXPECT_NEAR(open / area, 1.0, 0.02);
  // Outside the block everything is fluid; solid count = block minus pore.
  EXPECT_FALSE(g.is_solid(r.pore_begin - 1, 0, 0));
  EXPECT_TRUE(g.is_solid(r.pore_begin, 0, 0));
  EXPECT_EQ(g.count_solid(), std::size_t(11) * (41 * 41 - open));
}

TEST(PoreScene, PoreWiderThanBoxIsRefused) {
  lbm::PoreSceneSpec spec;
  spec.width = 20;
  spec.pore_diameter = 25;
  try {
    lbm::make_pore_scene(spec);
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pore_diameter"), std::string::npos);
  }
}

TEST(VoxelFile, RawRoundTrip) {
  lbm::PoreSceneSpec spec;
  spec.width = 12;
  spec.pore_diameter = 6;
  const auto g = lbm::make_pore_scene(spec, 0.25, {1.0, 2.0, 3.0});
  const std::string path = temp_path("scene.voxels");
  lbm::save_voxel_file_raw(g, path);
  const auto back = lbm::load_voxel_file(path);
  EXPECT_EQ(back.dims(), g.dims());
  EXPECT_DOUBLE_EQ(back.spacing(), 0.25);
  EXPECT_DOUBLE_EQ(back.origin()[2], 3.0);
  EXPECT_EQ(back.data(), g.data());
}

TEST(VoxelFile, BadFilesGiveClearErrors) {
  EXPECT_NE(error_of(temp_path("missing.voxels")).find("cannot be opened"), std::string::npos);
  const std::string bad_magic = temp_path("bad_magic.voxels");
  std::ofstream(bad_magic) << "HELLO 1\n2 2 2\n1 0 0 0\n";
  EXPECT_NE(error_of(bad_magic).find("LBMPORE_VOXELS"), std::string::npos);
  const std::string bad_dims = temp_path("bad_dims.voxels");
  std::ofstream(bad_dims) << "LBMPORE_VOXELS 1\n2 -2 2\n1 0 0 0\n";
  EXPECT_NE(error_of(bad_dims).find("dimensions"), std::string::npos);
  const std::string truncated = temp_path("truncated.voxels");
  std::ofstream(truncated) << "LBMPORE_VOXELS 1\n2 2 2\n1 0 0 0\n\x01\x00\x01";
  EXPECT_NE(error_of(truncated).find("truncated"), std::string::npos);
  const std::string bad_spacing = temp_path("bad_spacing.voxels");
  std::ofstream(bad_spacing) << "LBMPORE_VOXELS 1\n2 2 2\n0 0 0 0\n";
  EXPECT_NE(error_of(bad_spacing).find("spacing"), std::string::npos);
}

namespace {
// A string literal with its NUL bytes.
template <std::size_t N>
std::string bytes(const char (&text)[N]) {
  return std::string(text, N - 1);
}

std::string raw_error(const std::string& text) {
  std::istringstream in(text);
  try {
    lbm::read_raw_voxels(in, "mem.raw");
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(VoxelFile, HugeHeaderSizesAreRefusedBeforeAllocatingWithBothFigures) {
  // 1e15 voxels: std::string(1e15) used to end in std::bad_alloc ("terminate called").
  const std::string e = raw_error("LBMPORE_VOXELS 1\n100000 100000 100000\n1 0 0 0\n");
  EXPECT_NE(e.find("voxel file 'mem.raw': a geometry of 100000 x 100000 x 100000 voxels (its "
                   "sizes) needs 909 TiB, "
                   "more than the "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("of memory available"), std::string::npos) << e;
  // Sizes that fit but whose bytes are not there: truncated, found before allocating.
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1\n1000 1000 100\n1 0 0 0\nab")
                .find("truncated: expected 100000000 voxel "
                      "bytes, found 2"),
            std::string::npos);
  // The same without the newline ending the header (the stream then ends there; tests/fuzz found
  // it).
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1\n1000 1000 100\n1 0 0 0")
                .find("truncated: expected 100000000 voxel bytes, "
                      "found 0"),
            std::string::npos);
}

TEST(VoxelFile, AllSolidIsRefusedSayingThereIsNoFluid) {
  EXPECT_NE(raw_error(bytes("LBMPORE_VOXELS 1\n2 1 1\n1 0 0 0\n\x01\x02"))
                .find("is all solid: there is no fluid"),
            std::string::npos);
  EXPECT_EQ(raw_error(bytes("LBMPORE_VOXELS 1\n2 1 1\n1 0 0 0\n\x01\x00")), "");
}

TEST(VoxelFile, HeaderLinesMustHoldExactlyTheirWords) {
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1\n2 1 1 7\n1 0 0 0\n\x01").find("second line"),
            std::string::npos);
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1\n2 1 1\n0x10 0 0 0\n\x01").find("third line"),
            std::string::npos);
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1\n2 1 1\n1 nan 0 0\n\x01").find("third line"),
            std::string::npos);
  EXPECT_NE(raw_error("LBMPORE_VOXELS 1 extra\n2 1 1\n1 0 0 0\n").find("first line"),
            std::string::npos);
  // Windows line ends stay valid.
  EXPECT_EQ(raw_error(bytes("LBMPORE_VOXELS 1\r\n2 1 1\r\n1 0 0 0\r\n\x00\x01")), "");
}
