// fix lbm/pore's per-atom state: growing and moving it with its atoms, restart files (the
// fluid goes to a companion checkpoint), and LIGGGHTS's forward/reverse communication. The
// flat layout of the buffers is lbm_pore::AtomCouplingState's.
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "lbm/checkpoint.h"
#include "lbm/input_error.h"
#include "memory.h"
#include "plugin_common/stop_run.h"
#include "update.h"

using namespace LAMMPS_NS;
using lbm_pore::AtomCouplingState;

// Restart: the particles travel in LIGGGHTS's restart file with their state; the fluid goes
// to a companion checkpoint (one file per rank) whose name is stored in the restart file,
// after the monitor's state (the cumulative particle fluxes, the burst detector).
void FixLbmPore::write_restart(FILE* fp) {
  std::string prefix = options_.checkpoint_prefix.empty() ? std::string(id) + ".fluid"
                                                          : options_.checkpoint_prefix;
  const std::string path = prefix + "." + std::to_string(update->ntimestep);
  if (update->ntimestep % options_.n_dem != 0 && comm->me == 0)
    error->warning(FLERR, "fix lbm/pore: restart written between fluid steps (not a multiple of "
                          "n_dem): the continued run will differ slightly from an uninterrupted one");
  try {
    lbm::write_checkpoint(*solver_, path);
    lbm::prune_checkpoints(prefix, solver_->decomposition().comm.rank(), options_.checkpoint_keep);
  } catch (const lbm::InputError& e) {
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, e.what());
  }
  if (comm->me == 0) {
    const std::vector<double> state = monitor_->state();
    const double count = double(state.size());
    const int size = static_cast<int>(sizeof(double) * (state.size() + 1) + path.size() + 1);
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(&count, sizeof(double), 1, fp);
    std::fwrite(state.data(), sizeof(double), state.size(), fp);
    std::fwrite(path.c_str(), 1, path.size() + 1, fp);
  }
}

// buf: the monitor's state (its length first), then the checkpoint path.
void FixLbmPore::restart(char* buf) {
  double count = 0.0;
  std::memcpy(&count, buf, sizeof(double));
  restored_state_.resize(static_cast<std::size_t>(count));
  std::memcpy(restored_state_.data(), buf + sizeof(double), sizeof(double) * restored_state_.size());
  resume_checkpoint_ = std::string(buf + sizeof(double) * (restored_state_.size() + 1));
}

void FixLbmPore::grow_arrays(int nmax) {
  const int old = static_cast<int>(state_.size());
  state_.resize(nmax);
  memory->grow(hydrodynamic_force_, nmax, 3, "lbm/pore:hydrodynamic_force");
  for (int i = old; i < nmax; ++i) hydrodynamic_force_[i][0] = hydrodynamic_force_[i][1] = hydrodynamic_force_[i][2] = 0.0;
  array_atom = hydrodynamic_force_;
}

// A new atom (fix insert/...) starts with no load and no previous position: its slot may
// hold a former atom's values. Not every LIGGGHTS insertion calls set_arrays, so the slot
// also records its atom's tag and own_state() resets a slot whose tag differs.
void FixLbmPore::set_arrays(int i) {
  state_[i] = AtomCouplingState{};
  state_[i].tag = atom->tag[i];
}

AtomCouplingState& FixLbmPore::own_state(int i) {
  if (state_[i].tag != double(atom->tag[i])) set_arrays(i);
  return state_[i];
}

void FixLbmPore::copy_arrays(int i, int j, int) {
  state_[j] = state_[i];
  for (int a = 0; a < 3; ++a) hydrodynamic_force_[j][a] = hydrodynamic_force_[i][a];
}

int FixLbmPore::pack_exchange(int i, double* buf) {
  state_[i].pack(buf);
  return AtomCouplingState::kDoubles;
}

int FixLbmPore::unpack_exchange(int nlocal, double* buf) {
  state_[nlocal].unpack(buf);
  return AtomCouplingState::kDoubles;
}

int FixLbmPore::pack_restart(int i, double* buf) {
  buf[0] = AtomCouplingState::kDoubles + 1;
  state_[i].pack(buf + 1);
  return AtomCouplingState::kDoubles + 1;
}

void FixLbmPore::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int n = 0; n < nth; ++n) m += static_cast<int>(extra[nlocal][m]);
  const int size = static_cast<int>(extra[nlocal][m]);
  if (size != AtomCouplingState::kDoubles + 1 && size != AtomCouplingState::kDoubles1 + 1)
    error->one(FLERR, "fix lbm/pore: the restart file's per-atom data has another layout (written by "
                      "another version of lbm-pore); restart from a file written by this one");
  state_[nlocal].unpack(&extra[nlocal][m + 1], size - 1);
}

int FixLbmPore::size_restart(int) { return AtomCouplingState::kDoubles + 1; }
int FixLbmPore::maxsize_restart() { return AtomCouplingState::kDoubles + 1; }

// Forward: the velocity the fluid sees and the angular velocity, owner -> ghosts.
int FixLbmPore::pack_comm(int n, int* list, double* buf, int, int*) {
  double** omega = atom->omega;
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const int i = list[k];
    for (int a = 0; a < 3; ++a) buf[m++] = state_[i].fluid_velocity[a];
    for (int a = 0; a < 3; ++a) buf[m++] = omega ? omega[i][a] : 0.0;
  }
  return comm_forward;  // LIGGGHTS's Comm expects the count per atom, not the total
}

void FixLbmPore::unpack_comm(int n, int first, double* buf) {
  double** omega = atom->omega;
  int m = 0;
  for (int i = first; i < first + n; ++i) {
    for (int a = 0; a < 3; ++a) state_[i].fluid_velocity[a] = buf[m++];
    for (int a = 0; a < 3; ++a) {
      if (omega) omega[i][a] = buf[m];
      ++m;
    }
  }
}

int FixLbmPore::pack_reverse_comm(int n, int first, double* buf) {
  for (int i = first; i < first + n; ++i) state_[i].pack_summed(buf + AtomCouplingState::kSummed * (i - first));
  return AtomCouplingState::kSummed;  // per atom, as LIGGGHTS's Comm expects
}

void FixLbmPore::unpack_reverse_comm(int n, int* list, double* buf) {
  for (int k = 0; k < n; ++k) state_[list[k]].add_summed(buf + AtomCouplingState::kSummed * k);
}
