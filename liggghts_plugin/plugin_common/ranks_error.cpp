#include "plugin_common/ranks_error.h"

namespace lbm_pore {

std::string first_error_of_ranks(MPI_Comm world, const std::string& local_error) {
  int rank = 0, size = 1;
  MPI_Comm_rank(world, &rank);
  MPI_Comm_size(world, &size);
  int first = local_error.empty() ? size : rank;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, world);
  if (first == size) return "";
  std::string text = first > 0 ? "rank " + std::to_string(first) + ": " + local_error : local_error;
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, first, world);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(&text[0], length, MPI_CHAR, first, world);
  return text;
}

}  // namespace lbm_pore
