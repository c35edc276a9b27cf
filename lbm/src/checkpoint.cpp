#include "lbm/checkpoint.h"

#include <algorithm>
#include <array>
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

namespace {

// A checkpoint file's header, checked against this run's lattice and precision; the file
// left positioned at its first cell.
Header read_header(std::ifstream& in, const std::string& file, const FluidSolver& solver) {
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
    if (h.global_lo[a] != expected.global_lo[a] || h.global_hi[a] != expected.global_hi[a])
      throw InputError("fluid checkpoint '" + file + "': written for another lattice (" +
                       std::to_string(h.global_hi[0] - h.global_lo[0]) + " x " +
                       std::to_string(h.global_hi[1] - h.global_lo[1]) + " x " +
                       std::to_string(h.global_hi[2] - h.global_lo[2]) + " nodes)");
  return h;
}

bool same_owned_box(const Header& h, const FluidSolver& solver) {
  const Header mine = header_of(solver);
  for (int a = 0; a < 3; ++a)
    if (h.owned_lo[a] != mine.owned_lo[a] || h.owned_hi[a] != mine.owned_hi[a]) return false;
  return true;
}

// The owned cells of `solver` inside the box the file `in` (its header `h` read) holds.
// Returns how many it read.
long long read_overlap(std::ifstream& in, const std::string& file, const Header& h, FluidSolver& solver) {
  const auto& g = solver.layout();
  const Box& mine = solver.decomposition().owned;
  const std::array<int, 3> size{h.owned_hi[0] - h.owned_lo[0], h.owned_hi[1] - h.owned_lo[1],
                                h.owned_hi[2] - h.owned_lo[2]};
  const std::size_t record = 1 + D3Q19::Q * sizeof(Real);
  std::vector<char> row(std::size_t(std::max(size[0], 0)) * record);
  const std::streamoff first = std::streamoff(sizeof(Header));
  long long read = 0;
  for (int z = std::max(h.owned_lo[2], mine.lo[2]); z < std::min(h.owned_hi[2], mine.hi[2]); ++z)
    for (int y = std::max(h.owned_lo[1], mine.lo[1]); y < std::min(h.owned_hi[1], mine.hi[1]); ++y) {
      const int x0 = std::max(h.owned_lo[0], mine.lo[0]), x1 = std::min(h.owned_hi[0], mine.hi[0]);
      if (x0 >= x1) continue;
      const std::streamoff at =
          first + std::streamoff((std::size_t(z - h.owned_lo[2]) * std::size_t(size[1]) +
                                  std::size_t(y - h.owned_lo[1])) * std::size_t(size[0]) +
                                 std::size_t(x0 - h.owned_lo[0])) * std::streamoff(record);
      in.seekg(at);
      in.read(row.data(), std::streamsize(std::size_t(x1 - x0) * record));
      if (!in) throw InputError("fluid checkpoint '" + file + "': truncated");
      for (int x = x0; x < x1; ++x) {
        const char* r = row.data() + std::size_t(x - x0) * record;
        const std::size_t cell = g.cell(x - mine.lo[0], y - mine.lo[1], z - mine.lo[2]);
        solver.node_types()[cell] = static_cast<std::uint8_t>(r[0]);
        for (int q = 0; q < D3Q19::Q; ++q) {
          Real v;
          std::memcpy(&v, r + 1 + std::size_t(q) * sizeof(Real), sizeof v);
          solver.populations().at(q, cell) = v;
        }
        ++read;
      }
    }
  return read;
}

}  // namespace

void read_checkpoint(FluidSolver& solver, const std::string& path) {
  const std::string file = rank_path(solver, path);
  {
    std::ifstream in(file, std::ios::binary);
    if (in) {
      const Header h = read_header(in, file, solver);
      if (same_owned_box(h, solver)) {
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
        return;
      }
    }
  }
  // Written by another decomposition (another number of ranks or processor grid): every
  // rank's file `<path>.0`, `<path>.1`, ... until one is missing, each giving the part of
  // its box this rank owns.
  const long long wanted = solver.decomposition().owned.volume();
  long long found = 0;
  long long time_step = -1;
  for (int r = 0;; ++r) {
    const std::string other = path + "." + std::to_string(r);
    std::ifstream in(other, std::ios::binary);
    if (!in) break;
    const Header h = read_header(in, other, solver);
    if (time_step >= 0 && h.time_step != time_step)
      throw InputError("fluid checkpoint '" + other + "': from another step than '" + path +
                       ".0' (" + std::to_string(h.time_step) + " against " + std::to_string(time_step) + ")");
    time_step = h.time_step;
    found += read_overlap(in, other, h, solver);
  }
  if (time_step < 0) throw InputError("fluid checkpoint '" + file + "': cannot be opened");
  if (found != wanted)
    throw InputError("fluid checkpoint '" + path + ".<rank>': the files found cover " +
                     std::to_string(found) + " of this rank's " + std::to_string(wanted) +
                     " nodes (a rank's file missing?)");
  solver.set_time_step(time_step);
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
