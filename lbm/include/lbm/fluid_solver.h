#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/collide_stream.h"
#include "lbm/decomposition.h"
#include "lbm/halo_populations.h"
#include "lbm/node_moment_field.h"
#include "lbm/node_type.h"
#include "lbm/open_boundary.h"
#include "lbm/population_field.h"
#include "lbm/pull_correction.h"
#include "lbm/trt.h"
#include "lbm/voxel_geometry.h"

namespace lbm {

class HaloExchange;

struct FluidParameters {
  double tau = 1.0;                 // relaxation time (lattice units); nu = (tau - 1/2)/3
  double magic = 3.0 / 16.0;        // TRT magic parameter Lambda
  double rho0 = 1.0;                // initial / reference density
  // He & Luo 1997 incompressible equilibrium: f_eq = w [rho + rho0 (3 c.u + 9/2 (c.u)^2 -
  // 3/2 u^2)], momentum rho0 u. Its steady states obey the incompressible Navier-Stokes
  // equations, with p = c_s^2 rho a pressure only, so a large pressure drive (density
  // differences of 0.3-0.6, the paper's regime) leaves the velocity unchanged along the
  // flow instead of slowing it where the fluid is denser (doc/stability.md). lbm/ only:
  // coupling/'s refill of fresh nodes and its curved moving-wall links (Mei-Luo-Shyy) still
  // use the standard equilibrium.
  bool incompressible = false;
  std::array<double, 3> body_force{0.0, 0.0, 0.0};  // force per unit volume (lattice units)
  std::array<bool, 3> periodic{false, false, false};
};

// How the flow is driven through the domain along +axis: the inlet is the face at the
// global lower bound of `axis`, the outlet the face at the upper bound (both on-site,
// Hecht & Harting 2010 for D3Q19). With kNone those faces follow `periodic` / walls.
struct FlowDrive {
  enum Kind { kNone, kInletVelocity, kPressureLoss } kind = kNone;
  int axis = 0;
  double inlet_velocity = 0.0;  // normal velocity at the inlet (kInletVelocity)
  double pressure_loss = 0.0;   // p_in - p_out in lattice units (kPressureLoss)
  double outlet_density = 1.0;  // density imposed at the outlet (both kinds)
};

// One rank's share of the fluid. A step is a named pipeline of stages so that coupling/
// can insert its moving-boundary stages between them:
//   exchange_halo -> apply_wall_bounce_back -> [moving boundaries] -> apply_open_boundaries
//   -> collide_stream (in place: the field changes placement, PopulationField).
// State between steps: post-collision populations f*(x, t) in populations().
class FluidSolver {
 public:
  FluidSolver(const VoxelGeometry& geometry, const FluidParameters& parameters,
              const FlowDrive& drive, const Decomposition& decomposition);
  ~FluidSolver();
  FluidSolver(const FluidSolver&) = delete;
  FluidSolver& operator=(const FluidSolver&) = delete;

  // All stages in order; its exchange sends the five populations crossing each face
  // (HaloPopulations::crossing()): the stages of a pure fluid step read no other ghost
  // population (HaloExchange's audit).
  void step();
  // All 19 populations along every axis: for a host that builds its own pipeline and may
  // read whole ghost nodes (Mei-Luo-Shyy on static curved walls, tests).
  void exchange_halo();
  // The populations `which` names per axis (HaloPopulations); every rank must pass the same.
  void exchange_halo(const HaloPopulations& which);
  // Whether the exchange fills the ghost plane on `side` (0 low, 1 high) of `axis`
  // (HaloExchange::exchanges_face).
  bool exchanges_face(int axis, int side) const;
  // Whether the owned cell `cell` reads a ghost that exchange_halo() fills when it looks at
  // its D3Q19 neighbours (HaloExchange::borders_exchanged_ghost).
  bool borders_exchanged_ghost(std::size_t cell) const;
  // The densities (density(), below) that exchange_halo() would give the ghosts it fills,
  // written into `ghost_density` (num_cells() values, sized on first use) at those ghosts,
  // while one value per cell travels instead of 19 populations; the populations stay as
  // they are. Other cells of `ghost_density` hold nothing of use. Collective.
  void exchange_ghost_densities(std::vector<double>& ghost_density);
  // The cells of the padded planes that exchange_halo() sends along `axis`, and the ghosts
  // it fills there (HaloExchange::sent_planes, ghost_planes), for a host that carries values
  // of its own along the same paths (exchange_ghost_fields).
  const std::vector<std::size_t>& halo_sent_planes(int axis) const;
  const std::vector<std::size_t>& halo_ghost_planes(int axis) const;
  // `count` fields of num_cells() doubles each, carried to the ghosts along the axes marked
  // in `axes` as exchange_halo() carries the populations (HaloExchange::exchange_scalars):
  // a field that holds g(populations) on the sent planes of those axes holds, at their
  // ghosts, the g of the populations that exchange_halo() with all 19 along them would have
  // put there (edge ghosts when both their axes are marked). The ghosts of the other axes
  // keep what they held. Collective; every rank must pass the same `count` and `axes`.
  void exchange_ghost_fields(double* const* fields, int count, const std::array<bool, 3>& axes);
  // Whether `cell` is a ghost that exchange_halo() fills (HaloExchange::is_exchanged_ghost).
  bool is_exchanged_ghost(std::size_t cell) const;
  void apply_wall_bounce_back();
  void apply_open_boundaries();
  // The inlet (side 0) or outlet (side 1) face of the drive, where this rank holds it.
  std::optional<OpenFace> open_face(int side) const;
  // The density the open boundary gives the face's fluid node `cell` this step
  // (lbm::open_face_node_density); rho0 where `cell` is no fluid node of an open face here.
  double open_face_density(std::size_t cell) const;
  void collide_stream();

  // Reset every fluid node to equilibrium at density rho and velocity u.
  void initialise_equilibrium(double rho, const std::array<double, 3>& u);
  // Node by node: state(global i, j, k) -> {rho, ux, uy, uz}; ghosts included (the
  // function is called with global coordinates outside the box there).
  void initialise_equilibrium(
      const std::function<std::array<double, 4>(int, int, int)>& state);

  const BlockLayout& layout() const { return layout_; }
  const Decomposition& decomposition() const { return decomposition_; }
  const FluidParameters& parameters() const { return parameters_; }
  const FlowDrive& drive() const { return drive_; }
  const TrtParameters& trt() const { return trt_; }
  const VoxelGeometry& geometry() const { return geometry_; }
  PopulationField& populations() { return f_; }
  const PopulationField& populations() const { return f_; }
  std::vector<std::uint8_t>& node_types() { return node_type_; }
  const std::vector<std::uint8_t>& node_types() const { return node_type_; }
  long long time_step() const { return time_step_; }
  void set_time_step(long long t) {
    time_step_ = t;
    node_moments_valid_ = false;
    face_density_time_[0] = face_density_time_[1] = kNever;
  }
  // Changes the drive between steps (e.g. a pressure ramp).
  void set_drive(const FlowDrive& drive);

  // Memory the solver holds per stored lattice node (owned and ghost): the population field
  // (one, streamed in place, with its padding) and the node type, from their actual sizes.
  // Storage that grows with the wall surface (bounce-back link lists, halo buffers) is not
  // in it. About 153 bytes in double precision, 77 in single.
  double bytes_per_node() const;
  // The owned cells that are not static walls: the lattice updates of one collide_stream on
  // this rank (as MLUPS count them; the kernel also sweeps row padding), the unit of the
  // "fluid-cell updates" in which the coupling's cost is counted.
  std::size_t updated_cells() const { return updated_cells_; }

  // The moments of every node (rho and u, as node_moments gives them from the stored
  // populations), kept by collide_stream while it holds each node's values, for a host whose
  // boundary stages read the moments of many nodes (Mei-Luo-Shyy moving walls): four values
  // per node (32 bytes) instead of 19 populations gathered from 19 arrays. Off until asked
  // for. node_moment_field() is null until the first collide_stream after it was asked for,
  // and again after anything else rewrote the populations wholesale (initialise_equilibrium,
  // a checkpoint's set_time_step); a host that rewrites a node's populations between steps
  // calls refresh_node_moments(cell) (the refill of uncovered nodes) or
  // invalidate_node_moments(). The field's ghost cells hold whatever the kernel or
  // exchange_ghost_node_moments left there.
  void keep_node_moments();
  const NodeMomentField* node_moment_field() const {
    return node_moments_valid_ ? &node_moments_ : nullptr;
  }
  void refresh_node_moments(std::size_t cell);
  // The moments the kernel kept on the sent planes of the axes marked in `axes`, carried to
  // the ghosts as exchange_ghost_fields carries a field (edge ghosts when both their axes
  // are marked); the ghosts of the other axes keep what they held. Collective.
  void exchange_ghost_node_moments(const std::array<bool, 3>& axes);
  void invalidate_node_moments() { node_moments_valid_ = false; }

  // Densities the next collide_stream takes off the populations some nodes pull, in its own
  // pass (lbm/pull_correction.h: `count` entries, cell ascending, a node's consecutive): the
  // moving walls' link mass correction, the same bits as written into the slots before it.
  // The arrays must live until then; nothing else may read those nodes' slots in between.
  // With a `preparation`, the kernel has the entries written (and what else the nodes pull
  // prepared) in its own pass, a reach ahead of the cells it computes (PullPreparation).
  void correct_pulls_in_next_step(const std::uint32_t* cell, const double* defect, std::size_t count,
                                  PullPreparation preparation = {});

  // Macroscopic values at a local cell, from the stored post-collision populations:
  // rho = sum f, rho u = sum c f - F/2 (the Guo forcing shift undone).
  double density(std::size_t cell) const;
  std::array<double, 3> velocity(std::size_t cell) const;

  // Mass the streaming of the step moves into this rank's block through the inlet (face 0)
  // and the outlet (face 1) faces, set by apply_open_boundaries (lbm::open_face_mass);
  // 0 where the rank has no such face or the drive is none. Negative = outflow.
  double open_face_mass(int face) const { return open_face_mass_[face]; }

  // The sum of the densities of the inlet (face 0) or outlet (face 1) face's fluid nodes and
  // their count, added to sums[0] and sums[1] in plane order (lbm::pressure_loss's sums), as
  // the open boundary imposed them in the last step: the collision conserves mass, so they
  // are the nodes' densities after it to round-off. False, adding nothing, where this rank
  // has no such face or the populations changed otherwise since (a checkpoint read, an
  // initialisation): then the plane must be read.
  bool add_open_face_densities(int face, double* sums) const;

 private:
  static constexpr long long kNever = -2;
  double open_face_mass_[2] = {0.0, 0.0};
  // Each face node's imposed density by its slot in the plane, their sum and count, and the
  // time step at which the open boundary set them (kNever: not since the last reset).
  std::vector<double> face_density_[2];
  double face_density_sums_[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  long long face_density_time_[2] = {kNever, kNever};
  // The equilibrium of the chosen model (FluidParameters::incompressible).
  double equilibrium_at(int q, double rho, const std::array<double, 3>& u) const;
  void build_node_types();
  void build_wall_links();

  VoxelGeometry geometry_;
  FluidParameters parameters_;
  FlowDrive drive_;
  Decomposition decomposition_;
  TrtParameters trt_;
  BlockLayout layout_;
  PopulationField f_;  // streamed in place: one field, no second array
  std::vector<std::uint8_t> node_type_;
  // Half-way bounce-back on static walls: wall_slot_[p][n] (index into the population
  // storage under placement p, a slot at a solid cell) receives the value at
  // wall_source_[p][n] (the opposite population of the fluid node the link leaves).
  std::vector<std::size_t> wall_slot_[2], wall_source_[2];
  // The cells collide_stream computes: all owned ones but the static walls, whose slots
  // only the bounce-back above writes and reads (spans_without_solid). Built from the
  // node types with the wall links, which assume the same static walls.
  std::vector<KernelSpan> kernel_spans_;
  std::size_t updated_cells_ = 0;
  std::unique_ptr<HaloExchange> halo_;
  long long time_step_ = 0;
  NodeMomentField node_moments_;  // keep_node_moments()
  bool keep_node_moments_ = false, node_moments_valid_ = false;
  PullCorrections pull_corrections_;  // correct_pulls_in_next_step()
};

}  // namespace lbm
