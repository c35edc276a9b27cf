#include "lbm/fluid_solver.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/halo_exchange.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"
#include "lbm/open_boundary.h"
#include "plane_nodes.h"

namespace lbm {

namespace {
// Below this many static wall links one thread copies them faster than two start.
constexpr std::size_t kMinParallelWallLinks = 4096;

void validate(const VoxelGeometry& geometry, const FlowDrive& drive, const Decomposition& d) {
  for (int a = 0; a < 3; ++a)
    if (d.global.lo[a] != 0 || d.global.hi[a] != geometry.dims()[a])
      throw InputError("fluid solver: the decomposition's global box does not match the voxel "
                       "geometry's dimensions on axis " + std::to_string(a));
  if (drive.axis < 0 || drive.axis > 2)
    throw InputError("flow drive: axis = " + std::to_string(drive.axis) + ", must be 0, 1 or 2");
  if (drive.kind != FlowDrive::kNone && d.periodic[drive.axis])
    throw InputError("flow drive: the drive axis cannot also be periodic");
  if (drive.kind == FlowDrive::kInletVelocity && !(std::abs(drive.inlet_velocity) < 0.3))
    throw InputError("flow drive: inlet velocity = " + std::to_string(drive.inlet_velocity) +
                     " lattice units, must be in (-0.3, 0.3) (lattice Mach number < 0.5)");
  if (!(drive.outlet_density > 0.0))
    throw InputError("flow drive: outlet density must be > 0");
  if (drive.kind == FlowDrive::kPressureLoss &&
      !(std::abs(drive.pressure_loss) < 0.3 * drive.outlet_density))
    throw InputError("flow drive: pressure loss = " + std::to_string(drive.pressure_loss) +
                     " lattice units, must be below 0.3 rho_out (density variation < 90 %)");
}
}  // namespace

FluidSolver::FluidSolver(const VoxelGeometry& geometry, const FluidParameters& parameters,
                         const FlowDrive& drive, const Decomposition& decomposition)
    : geometry_(geometry),
      parameters_(parameters),
      drive_(drive),
      decomposition_(decomposition),
      trt_(TrtParameters::from_tau(parameters.tau, parameters.magic)),
      layout_(decomposition.owned) {
  decomposition_.periodic = parameters.periodic;
  validate(geometry_, drive_, decomposition_);
  f_ = PopulationField(layout_);
  halo_ = std::make_unique<HaloExchange>(decomposition_, layout_);
  build_node_types();
  build_wall_links();
  kernel_spans_ = spans_without_solid(layout_, node_type_.data());
  for (int k = 0; k < layout_.size(2); ++k)
    for (int j = 0; j < layout_.size(1); ++j)
      for (int i = 0; i < layout_.size(0); ++i) updated_cells_ += node_type_[layout_.cell(i, j, k)] != kSolid;
  initialise_equilibrium(parameters_.rho0, {0.0, 0.0, 0.0});
}

FluidSolver::~FluidSolver() = default;

void FluidSolver::set_drive(const FlowDrive& drive) {
  if (drive.axis != drive_.axis || (drive.kind == FlowDrive::kNone) != (drive_.kind == FlowDrive::kNone))
    throw InputError("flow drive: only the drive values can change during a run, not its axis or kind");
  validate(geometry_, drive, decomposition_);
  drive_ = drive;
}

// Node types of owned and ghost cells from the global geometry. Ghosts beyond the domain
// are: periodic images, open (inlet/outlet ghosts of the drive axis), or closed walls.
void FluidSolver::build_node_types() {
  node_type_.assign(layout_.num_cells(), kFluid);
  const Box& global = decomposition_.global;
  for (int k = -1; k <= layout_.size(2); ++k)
    for (int j = -1; j <= layout_.size(1); ++j)
      for (int i = -1; i <= layout_.size(0); ++i) {
        std::array<int, 3> g = layout_.to_global(i, j, k);
        std::uint8_t type = kFluid;
        for (int a = 0; a < 3 && type == kFluid; ++a) {
          if (g[a] >= global.lo[a] && g[a] < global.hi[a]) continue;
          if (drive_.kind != FlowDrive::kNone && a == drive_.axis)
            type = kOpen;
          else if (decomposition_.periodic[a])
            g[a] = (g[a] - global.lo[a] + global.size(a)) % global.size(a) + global.lo[a];
          else
            type = kSolid;
        }
        if (type == kFluid && geometry_.is_solid(g[0], g[1], g[2])) type = kSolid;
        node_type_[layout_.cell(i, j, k)] = type;
      }
}

void FluidSolver::build_wall_links() {
  using P = PopulationField::Placement;
  for (int p = 0; p < 2; ++p) {
    wall_slot_[p].clear();
    wall_source_[p].clear();
  }
  for (int k = 0; k < layout_.size(2); ++k)
    for (int j = 0; j < layout_.size(1); ++j)
      for (int i = 0; i < layout_.size(0); ++i) {
        const std::size_t x = layout_.cell(i, j, k);
        if (node_type_[x] != kFluid) continue;
        for (int q = 1; q < D3Q19::Q; ++q) {
          const std::size_t y =
              x - layout_.offset(D3Q19::c[q][0], D3Q19::c[q][1], D3Q19::c[q][2]);
          if (node_type_[y] != kSolid) continue;
          for (const P p : {P::kReversed, P::kForward}) {
            wall_slot_[int(p)].push_back(f_.index(p, q, y));
            wall_source_[int(p)].push_back(f_.index(p, D3Q19::opposite(q), x));
          }
        }
      }
}

double FluidSolver::equilibrium_at(int q, double rho, const std::array<double, 3>& u) const {
  return parameters_.incompressible ? incompressible_equilibrium(q, rho, parameters_.rho0, u)
                                    : equilibrium(q, rho, u);
}

void FluidSolver::initialise_equilibrium(double rho, const std::array<double, 3>& u) {
  face_density_time_[0] = face_density_time_[1] = kNever;
  node_moments_valid_ = false;
  const std::size_t n = layout_.num_cells();
  for (std::size_t cell = 0; cell < n; ++cell) {
    const bool fluid = node_type_[cell] == kFluid;
    for (int q = 0; q < D3Q19::Q; ++q)
      f_.at(q, cell) = fluid ? static_cast<Real>(equilibrium_at(q, rho, u)) : Real(0);
  }
}

void FluidSolver::initialise_equilibrium(
    const std::function<std::array<double, 4>(int, int, int)>& state) {
  face_density_time_[0] = face_density_time_[1] = kNever;
  node_moments_valid_ = false;
  for (int k = -1; k <= layout_.size(2); ++k)
    for (int j = -1; j <= layout_.size(1); ++j)
      for (int i = -1; i <= layout_.size(0); ++i) {
        const std::size_t cell = layout_.cell(i, j, k);
        const auto g = layout_.to_global(i, j, k);
        const auto s = state(g[0], g[1], g[2]);
        const bool fluid = node_type_[cell] == kFluid;
        for (int q = 0; q < D3Q19::Q; ++q)
          f_.at(q, cell) =
              fluid ? static_cast<Real>(equilibrium_at(q, s[0], {s[1], s[2], s[3]})) : Real(0);
      }
}

void FluidSolver::exchange_halo() { halo_->exchange(f_); }

void FluidSolver::exchange_halo(const HaloPopulations& which) { halo_->exchange(f_, which); }

bool FluidSolver::exchanges_face(int axis, int side) const {
  return halo_->exchanges_face(axis, side);
}

bool FluidSolver::borders_exchanged_ghost(std::size_t cell) const {
  return halo_->borders_exchanged_ghost(cell);
}

// Every cell the sweeps send gets its density, summed as density() sums it; the scalar
// sweeps then carry it along the paths exchange() moves the populations (bit-identical).
void FluidSolver::exchange_ghost_densities(std::vector<double>& ghost_density) {
  ghost_density.resize(layout_.num_cells());
  // density(cell) summed population by population over all the sent cells: the same sum in
  // the same order (q = 0, 1, ..., 18), but each pass reads one array along the planes' rows
  // instead of 19 arrays for every cell. The kernel has just streamed them to memory, and a
  // row of a plane is a dozen lines, too short for the hardware to fetch ahead: the cell
  // kAhead places further is asked for (paper scene across the flow: 7.3 -> 5.4 % of rank
  // 0's profile).
  constexpr std::size_t kAhead = 64;
  const std::vector<std::size_t>& sent = halo_->sent_cells();
  const std::size_t count = sent.size();
  double* rho = ghost_density.data();
  for (int q = 0; q < D3Q19::Q; ++q) {
    const Real* fq = f_.q(q);
    for (std::size_t i = 0; i < count; ++i) {
      if (i + kAhead < count) __builtin_prefetch(fq + sent[i + kAhead]);
      const std::size_t cell = sent[i];
      rho[cell] = (q == 0 ? 0.0 : rho[cell]) + fq[cell];
    }
  }
  halo_->exchange_scalar(ghost_density);
}

const std::vector<std::size_t>& FluidSolver::halo_sent_planes(int axis) const {
  return halo_->sent_planes(axis);
}

const std::vector<std::size_t>& FluidSolver::halo_ghost_planes(int axis) const {
  return halo_->ghost_planes(axis);
}

void FluidSolver::exchange_ghost_fields(double* const* fields, int count,
                                        const std::array<bool, 3>& axes) {
  halo_->exchange_scalars(fields, count, axes);
}

bool FluidSolver::is_exchanged_ghost(std::size_t cell) const {
  return halo_->is_exchanged_ghost(cell);
}

// Half-way bounce-back (Ladd 1994): the population leaving fluid node x towards a wall
// returns to x reversed one step later, f_q(x, t+1) = f*_{-q}(x, t).
void FluidSolver::apply_wall_bounce_back() {
  Real* data = f_.raw().data();
  const std::vector<std::size_t>& slot = wall_slot_[int(f_.placement())];
  const std::vector<std::size_t>& source = wall_source_[int(f_.placement())];
  const std::size_t links = slot.size();
  // Each link copies a fluid node's outgoing population into a slot of a wall node, which
  // no link reads: any split over the threads gives the same field.
  const long n = long(links);
#pragma omp parallel for schedule(static) if (links >= kMinParallelWallLinks)
  for (long l = 0; l < n; ++l) data[slot[std::size_t(l)]] = data[source[std::size_t(l)]];
}

std::optional<OpenFace> FluidSolver::open_face(int side) const {
  if (drive_.kind == FlowDrive::kNone) return std::nullopt;
  const int a = drive_.axis;
  const Box& global = decomposition_.global;
  const Box& owned = decomposition_.owned;
  OpenFace face;
  face.axis = a;
  face.momentum_density = parameters_.incompressible ? parameters_.rho0 : 0.0;
  if (side == 0) {
    if (owned.lo[a] != global.lo[a]) return std::nullopt;
    face.inward = +1;
    face.local_plane = 0;
    if (drive_.kind == FlowDrive::kInletVelocity) {
      face.kind = OpenFace::kVelocity;
      face.value = drive_.inlet_velocity;
    } else {
      // p = cs^2 rho, so a pressure loss dp needs rho_in = rho_out + dp / cs^2.
      face.kind = OpenFace::kDensity;
      face.value = drive_.outlet_density + drive_.pressure_loss / D3Q19::cs2;
    }
    return face;
  }
  if (owned.hi[a] != global.hi[a]) return std::nullopt;
  face.inward = -1;
  face.local_plane = layout_.size(a) - 1;
  face.kind = OpenFace::kDensity;
  face.value = drive_.outlet_density;
  return face;
}

void FluidSolver::apply_open_boundaries() {
  for (int side = 0; side < 2; ++side) {
    open_face_mass_[side] = 0.0;
    face_density_time_[side] = kNever;
    const std::optional<OpenFace> face = open_face(side);
    if (!face) continue;
    const int a = face->axis;
    std::vector<double>& density = face_density_[side];
    density.resize(std::size_t(layout_.size((a + 1) % 3)) * std::size_t(layout_.size((a + 2) % 3)));
    apply_open_face(*face, layout_, node_type_, f_, density.data());
    open_face_mass_[side] = lbm::open_face_mass(*face, layout_, node_type_, f_);
    // Summed on one thread in the plane's order, as lbm::pressure_loss sums a plane it reads.
    double* const sums = face_density_sums_[side];
    sums[0] = sums[1] = 0.0;
    detail::for_plane_fluid_nodes(layout_, node_type_, a, face->local_plane,
                                  [&](std::size_t, std::size_t slot) {
                                    sums[0] += density[slot];
                                    sums[1] += 1.0;
                                  },
                                  [](std::size_t) {});
    face_density_time_[side] = time_step_;
  }
}

bool FluidSolver::add_open_face_densities(int face, double* sums) const {
  // Set before this step's collide_stream, which advanced the time step by one.
  if (face_density_time_[face] == kNever || face_density_time_[face] + 1 != time_step_) return false;
  sums[0] += face_density_sums_[face][0];
  sums[1] += face_density_sums_[face][1];
  return true;
}

double FluidSolver::open_face_density(std::size_t cell) const {
  const int a = drive_.axis;
  for (int side = 0; side < 2; ++side)
    if (const std::optional<OpenFace> face = open_face(side))
      if (layout_.coords(cell)[std::size_t(a)] == face->local_plane && node_type_[cell] == kFluid)
        return open_face_node_density(*face, layout_, f_, cell);
  return parameters_.rho0;
}

void FluidSolver::collide_stream() {
  // In place (PopulationField: the AA pattern): read under the field's placement, written
  // under the other one, into the same slots.
  const PopulationField::Placement next = other(f_.placement());
  CollideStreamArgs args;
  const std::array<Real*, D3Q19::Q> src = f_.arrays(f_.placement());
  std::copy(src.begin(), src.end(), args.src.begin());
  args.dst = f_.arrays(next);
  args.in_place = true;
  args.spans = kernel_spans_.data();
  args.num_spans = kernel_spans_.size();
  args.node_type = node_type_.data();
  args.layout = layout_;
  args.omega_plus = trt_.omega_plus;
  args.omega_minus = trt_.omega_minus;
  args.force = parameters_.body_force;
  args.incompressible = parameters_.incompressible;
  args.rho0 = parameters_.rho0;
  if (keep_node_moments_) args.moments = node_moments_.data();
  args.pull_corrections = pull_corrections_;
  pull_corrections_ = PullCorrections{};
  lbm::collide_stream(args);
  f_.set_placement(next);
  ++time_step_;
  node_moments_valid_ = keep_node_moments_;
}

void FluidSolver::keep_node_moments() {
  if (keep_node_moments_) return;
  keep_node_moments_ = true;
  node_moments_.assign(layout_.num_cells());
}

void FluidSolver::correct_pulls_in_next_step(const std::uint32_t* cell, const double* defect,
                                             std::size_t count, PullPreparation preparation) {
  pull_corrections_ = PullCorrections{cell, defect, count, preparation};
}

void FluidSolver::refresh_node_moments(std::size_t cell) {
  if (!keep_node_moments_) return;
  const NodeMoments m = node_moments(f_, cell, parameters_.body_force);
  double* const kept = node_moments_.at(cell);
  kept[0] = m.rho;
  for (int a = 0; a < 3; ++a) kept[1 + a] = m.u[std::size_t(a)];
}

void FluidSolver::exchange_ghost_node_moments(const std::array<bool, 3>& axes) {
  halo_->exchange_interleaved(node_moments_.data(), NodeMomentField::kValues, axes);
}

void FluidSolver::step() {
  // Static walls and open faces read only the crossing populations of a ghost.
  exchange_halo(HaloPopulations::crossing());
  apply_wall_bounce_back();
  apply_open_boundaries();
  collide_stream();
}

double FluidSolver::bytes_per_node() const {
  const double bytes = double(f_.raw().capacity()) * sizeof(Real) +
                       double(node_type_.capacity()) * sizeof(std::uint8_t);
  return bytes / double(layout_.num_cells());
}

double FluidSolver::density(std::size_t cell) const {
  double rho = 0.0;
  for (int q = 0; q < D3Q19::Q; ++q) rho += f_.at(q, cell);
  return rho;
}

std::array<double, 3> FluidSolver::velocity(std::size_t cell) const {
  double j[3] = {0.0, 0.0, 0.0};
  double rho = 0.0;
  for (int q = 0; q < D3Q19::Q; ++q) {
    const double v = f_.at(q, cell);
    rho += v;
    for (int a = 0; a < 3; ++a) j[a] += v * D3Q19::c[q][a];
  }
  if (rho <= 0.0) return {0.0, 0.0, 0.0};
  if (parameters_.incompressible) rho = parameters_.rho0;  // momentum rho0 u (He & Luo)
  const auto& F = parameters_.body_force;
  // Post-collision momentum = rho u + F/2 with Guo forcing (see collide_stream.cpp).
  return {(j[0] - 0.5 * F[0]) / rho, (j[1] - 0.5 * F[1]) / rho, (j[2] - 0.5 * F[2]) / rho};
}

}  // namespace lbm
