#include "lbm/checkpoint.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/input_error.h"
#include "lbm/node_type.h"

namespace lbm {
namespace {

constexpr char kMagic[8] = {'L', 'B', 'M', 'P', 'C', 'K', '0', '1'};

struct Header {
  char magic[8];
  std::int32_t real_bytes;
  std::int32_t global_lo[3], global_hi[3], owned_lo[3], owned_hi[3];
  std::int64_t time_step;
};

Header header_of(const FluidSolver& s) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.real_bytes = sizeof(Real);
  for (int a = 0; a < 3; ++a) {
    h.global_lo[a] = s.decomposition().global.lo[a];
    h.global_hi[a] = s.decomposition().global.hi[a];
    h.owned_lo[a] = s.decomposition().owned.lo[a];
    h.owned_hi[a] = s.decomposition().owned.hi[a];
  }
  h.time_step = s.time_step();
  return h;
}

// Test-only hook (tests/faults/kill_check.py, kill_during_checkpoint): with
// LBM_PORE_TEST_SLOW_WRITE=<seconds> each write pauses that long after the header, so a test
// can kill the run while a checkpoint is half written. Unset: no pause.
void pause_if_testing_slow_write() {
  const char* seconds = std::getenv("LBM_PORE_TEST_SLOW_WRITE");
  if (seconds) std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(seconds)));
}

std::string rank_path(const FluidSolver& s, const std::string& path) {
  return path + "." + std::to_string(s.decomposition().comm.rank());
}

// Visits every owned cell in storage order (x fastest).
template <class Visit>
void for_owned(const BlockLayout& g, Visit visit) {
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) visit(g.cell(i, j, k));
}

}  // namespace

void write_checkpoint(const FluidSolver& solver, const std::string& path) {
  // Written to a temporary name and renamed once complete: a run killed while writing (a
  // batch system's wall-time limit, a full disk) leaves the previous file intact.
  const std::string file = rank_path(solver, path);
  const std::string partial = file + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    if (!out) throw InputError("fluid checkpoint '" + file + "': cannot be written");
    const Header h = header_of(solver);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.flush();
    pause_if_testing_slow_write();
    const auto& g = solver.layout();
    for_owned(g, [&](std::size_t cell) {
      out.put(static_cast<char>(solver.node_types()[cell]));
      for (int q = 0; q < D3Q19::Q; ++q) {
        const Real v = solver.populations().at(q, cell);
        out.write(reinterpret_cast<const char*>(&v), sizeof v);
      }
    });
    out.flush();
    if (!out) {
      out.close();
      std::remove(partial.c_str());
      throw InputError("fluid checkpoint '" + file + "': write failed (disk full?); the previous file is kept");
    }
  }
  if (std::rename(partial.c_str(), file.c_str()) != 0)
    throw InputError("fluid checkpoint '" + file + "': cannot replace it with the new one (" + partial + ")");
}

void read_checkpoint(FluidSolver& solver, const std::string& path) {
  const std::string file = rank_path(solver, path);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("fluid checkpoint '" + file + "': cannot be opened");
  Header h{};
  in.read(reinterpret_cast<char*>(&h), sizeof h);
  if (!in || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0)
    throw InputError("fluid checkpoint '" + file + "': not an lbm-pore fluid checkpoint");
  const Header expected = header_of(solver);
  if (h.real_bytes != expected.real_bytes)
    throw InputError("fluid checkpoint '" + file + "': written with " +
                     std::to_string(h.real_bytes * 8) + "-bit populations, this build uses " +
                     std::to_string(expected.real_bytes * 8));
  for (int a = 0; a < 3; ++a)
    if (h.global_lo[a] != expected.global_lo[a] || h.global_hi[a] != expected.global_hi[a] ||
        h.owned_lo[a] != expected.owned_lo[a] || h.owned_hi[a] != expected.owned_hi[a])
      throw InputError("fluid checkpoint '" + file +
                       "': lattice or decomposition differs from this run (same lattice and "
                       "the same processor grid are required)");
  const auto& g = solver.layout();
  for_owned(g, [&](std::size_t cell) {
    char type = 0;
    in.get(type);
    solver.node_types()[cell] = static_cast<std::uint8_t>(type);
    for (int q = 0; q < D3Q19::Q; ++q) {
      Real v;
      in.read(reinterpret_cast<char*>(&v), sizeof v);
      solver.populations().at(q, cell) = v;
    }
  });
  if (!in) throw InputError("fluid checkpoint '" + file + "': truncated");
  solver.set_time_step(h.time_step);
}

void release_moving_nodes(FluidSolver& solver) {
  auto& types = solver.node_types();
  auto& f = solver.populations();
  for (std::size_t cell = 0; cell < types.size(); ++cell) {
    if (types[cell] != kMoving) continue;
    types[cell] = kFluid;
    for (int q = 0; q < D3Q19::Q; ++q) f.at(q, cell) = equilibrium(q, 1.0, {0.0, 0.0, 0.0});
  }
}

}  // namespace lbm

namespace lbm {

int prune_checkpoints(const std::string& prefix, int rank, int keep) {
  if (keep <= 0) return 0;
  namespace fs = std::filesystem;
  const fs::path prefix_path(prefix);
  const fs::path folder = prefix_path.has_parent_path() ? prefix_path.parent_path() : fs::path(".");
  const std::string stem = prefix_path.filename().string() + ".";
  const std::string rank_suffix = "." + std::to_string(rank);
  std::vector<std::pair<long long, fs::path>> found;  // (step, file)
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= stem.size() + rank_suffix.size() || name.compare(0, stem.size(), stem) != 0 ||
        name.compare(name.size() - rank_suffix.size(), rank_suffix.size(), rank_suffix) != 0)
      continue;
    const std::string step = name.substr(stem.size(), name.size() - stem.size() - rank_suffix.size());
    if (step.empty() || step.find_first_not_of("0123456789") != std::string::npos) continue;
    found.emplace_back(std::stoll(step), entry.path());
  }
  if (static_cast<int>(found.size()) <= keep) return 0;
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  int deleted = 0;
  for (std::size_t i = static_cast<std::size_t>(keep); i < found.size(); ++i)
    if (fs::remove(found[i].second, ec)) ++deleted;
  return deleted;
}

}  // namespace lbm
