#include "lbm/memory_estimate.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "lbm/d3q19.h"
#include "lbm/input_error.h"

namespace lbm {

namespace {
constexpr double kNoLimit = std::numeric_limits<double>::max();
constexpr double kAskBelow = 64.0 * 1024 * 1024;  // smaller requests are not checked

double nodes(const std::array<int, 3>& dims) { return double(dims[0]) * dims[1] * dims[2]; }

// "MemAvailable:   12345678 kB" -> bytes; kNoLimit when absent.
double meminfo_available() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string key;
    double kib = 0.0;
    if (words >> key >> kib && key == "MemAvailable:") return kib * 1024.0;
  }
  return kNoLimit;
}

// cgroup v2 (memory.max, memory.current) then v1 (limit_in_bytes, usage_in_bytes) of this
// process's group as the container sees it; kNoLimit without a limit.
double cgroup_headroom() {
  const char* pairs[][2] = {{"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
                            {"/sys/fs/cgroup/memory/memory.limit_in_bytes",
                             "/sys/fs/cgroup/memory/memory.usage_in_bytes"}};
  for (const auto& pair : pairs) {
    std::ifstream limit_file(pair[0]), usage_file(pair[1]);
    double limit = 0.0, usage = 0.0;
    if (!(limit_file >> limit) || !(usage_file >> usage)) continue;  // "max": no limit
    if (limit >= 1e18) continue;                                     // v1's "unlimited"
    return limit > usage ? limit - usage : 0.0;
  }
  return kNoLimit;
}
}  // namespace

double lattice_bytes(const std::array<int, 3>& owned, const std::array<int, 3>& global,
                     std::size_t real_bytes) {
  const std::array<int, 3> padded{owned[0] + 2 * BlockLayout::kGhost,
                                  owned[1] + 2 * BlockLayout::kGhost,
                                  owned[2] + 2 * BlockLayout::kGhost};
  // One population field (streamed in place, PopulationField) and the node type. Each of
  // the field's 19 arrays has a padding of one link's reach (a plane and a row) at both
  // ends, in whole 64-byte lines. The same shape as PopulationField's constructor, here in
  // doubles and for any precision: the guard must refuse absurd sizes (10^27 nodes) without
  // overflowing, before anything is allocated (test_memory_estimate.cpp checks the two agree).
  const double line = 64.0 / double(real_bytes);
  const auto whole_lines = [line](double values) { return std::ceil(values / line) * line; };
  const double reach = double(padded[0]) * padded[1] + padded[0];
  const double per_array = whole_lines(nodes(padded)) + 2.0 * whole_lines(reach);
  return D3Q19::Q * per_array * double(real_bytes) + nodes(padded) + geometry_bytes(global);
}

double geometry_bytes(const std::array<int, 3>& dims) { return nodes(dims); }

double available_memory_bytes() {
  double available = meminfo_available();
  if (available == kNoLimit) {
    const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) available = double(pages) * double(page);
  }
  const double cgroup = cgroup_headroom();
  return cgroup < available ? cgroup : available;
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 4) {
    bytes /= 1024.0;
    ++u;
  }
  char text[64];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

void check_fits_in_memory(double bytes, const std::string& what, const std::string& hint) {
  if (bytes < kAskBelow) return;
  const double available = available_memory_bytes();
  if (bytes <= available) return;
  throw InputError(what + " needs " + format_bytes(bytes) + ", more than the " +
                   format_bytes(available) + " of memory available" +
                   (hint.empty() ? "" : "; " + hint));
}

void check_fits_in_memory_on_every_machine(double bytes_this_rank, const std::string& what,
                                           const std::string& hint, const Communicator& comm) {
  double machine_bytes = bytes_this_rank;
  int sharers = 1;
#ifdef LBM_PORE_HAVE_MPI
  MPI_Comm machine;
  MPI_Comm_split_type(comm.native(), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
  MPI_Allreduce(&bytes_this_rank, &machine_bytes, 1, MPI_DOUBLE, MPI_SUM, machine);
  MPI_Comm_size(machine, &sharers);
  MPI_Comm_free(&machine);
#endif
  std::string message;
  try {
    const std::string shared =
        sharers > 1 ? ", with the " + std::to_string(sharers) + " ranks on this machine together,"
                    : "";
    check_fits_in_memory(machine_bytes, what + shared, hint);
  } catch (const InputError& e) {
    message = e.what();
  }
  double short_somewhere = message.empty() ? 0.0 : 1.0;
  comm.max(&short_somewhere, 1);
  if (short_somewhere == 0.0) return;
  throw InputError(message.empty()
                       ? what + " does not fit in the memory of another machine of this run" +
                             (hint.empty() ? "" : "; " + hint)
                       : message);
}

}  // namespace lbm
