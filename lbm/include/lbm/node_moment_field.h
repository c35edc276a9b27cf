#pragma once
#include <cstddef>
#include <vector>

namespace lbm {

// The moments of every node (rho, u_x, u_y, u_z: FluidSolver::keep_node_moments), the four
// of a node side by side. Their readers, the moving walls, take them at scattered nodes,
// the nodes next to the spheres and the nodes behind them: one line of the cache holds a
// node's four where four arrays needed four lines, each fetched from memory after the DEM
// substeps between two fluid steps. The kernel writes them as one stream instead of four.
class NodeMomentField {
 public:
  static constexpr int kValues = 4;  // rho, u_x, u_y, u_z

  void assign(std::size_t cells) { values_.assign(kValues * cells, 0.0); }
  std::size_t num_cells() const { return values_.size() / kValues; }
  // The node's rho at [0], u at [1..3].
  double* at(std::size_t cell) { return values_.data() + kValues * cell; }
  const double* at(std::size_t cell) const { return values_.data() + kValues * cell; }
  double* data() { return values_.data(); }

 private:
  std::vector<double> values_;
};

}  // namespace lbm
