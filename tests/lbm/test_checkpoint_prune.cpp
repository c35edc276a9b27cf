// prune_checkpoints: a long run that writes restart files in turn keeps on disk only the
// fluid checkpoints they can name, whatever else lies in the folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "lbm/checkpoint.h"

namespace {
namespace fs = std::filesystem;

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

struct ScratchFolder {
  fs::path path;
  ScratchFolder() {
    path = fs::temp_directory_path() / ("lbm_prune_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchFolder() { fs::remove_all(path); }
  void touch(const std::string& name) const { std::ofstream(path / name) << "x"; }
};
}  // namespace

TEST(PruneCheckpoints, KeepsTheNewestStepsOfThisRankOnly) {
  ScratchFolder dir;
  // Steps out of order and of different lengths (sorted by number, not by text).
  for (const char* step : {"900", "10000", "1000", "100", "20000"}) {
    dir.touch(std::string("pore.fluid.") + step + ".0");
    dir.touch(std::string("pore.fluid.") + step + ".1");
  }
  dir.touch("pore.fluid.30000.0.partial");  // a checkpoint being written
  dir.touch("other.fluid.100.0");           // another prefix
  dir.touch("pore.fluid.abc.0");            // not a step
  dir.touch("restart.a");
  const std::string prefix = (dir.path / "pore.fluid").string();
  EXPECT_EQ(lbm::prune_checkpoints(prefix, 0, 2), 3);
  const std::set<std::string> expected{"pore.fluid.20000.0", "pore.fluid.10000.0",
                                       "pore.fluid.900.1", "pore.fluid.10000.1", "pore.fluid.1000.1",
                                       "pore.fluid.100.1", "pore.fluid.20000.1",
                                       "pore.fluid.30000.0.partial", "other.fluid.100.0",
                                       "pore.fluid.abc.0", "restart.a"};
  EXPECT_EQ(names_in(dir.path), expected);
  // Rank 1 prunes its own; nothing left to do on a second call.
  EXPECT_EQ(lbm::prune_checkpoints(prefix, 1, 2), 3);
  EXPECT_EQ(lbm::prune_checkpoints(prefix, 1, 2), 0);
  EXPECT_TRUE(fs::exists(dir.path / "pore.fluid.20000.1"));
  EXPECT_TRUE(fs::exists(dir.path / "pore.fluid.10000.1"));
  EXPECT_FALSE(fs::exists(dir.path / "pore.fluid.1000.1"));
}

TEST(PruneCheckpoints, ZeroKeepsEverythingAndAPrefixInTheWorkingFolderWorks) {
  ScratchFolder dir;
  dir.touch("f.1.0");
  dir.touch("f.2.0");
  EXPECT_EQ(lbm::prune_checkpoints((dir.path / "f").string(), 0, 0), 0);
  EXPECT_EQ(names_in(dir.path).size(), 2u);
  const fs::path here = fs::current_path();
  fs::current_path(dir.path);
  const int deleted = lbm::prune_checkpoints("f", 0, 1);
  fs::current_path(here);
  EXPECT_EQ(deleted, 1);
  EXPECT_EQ(names_in(dir.path), std::set<std::string>{"f.2.0"});
}
