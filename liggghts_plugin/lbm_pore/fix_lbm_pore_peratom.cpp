// fix lbm/pore's per-atom state: growing and moving it with its atoms, restart files (the
// fluid goes to a companion checkpoint), and LIGGGHTS's forward/reverse communication. The
// flat layouts of the buffers are lbm_pore::AtomCouplingState's and AtomStates'.
#include <cstdio>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "lbm/capped_drive.h"
#include "lbm/checkpoint.h"
#include "lbm/input_error.h"
#include "memory.h"
#include "plugin_common/stop_run.h"
#include "restart_record.h"
#include "update.h"

using namespace LAMMPS_NS;

// Restart: the particles travel in LIGGGHTS's restart file with their state; the fluid goes
// to a companion checkpoint (one file per rank) whose path the restart file keeps, after the
// monitor's state (lbm_pore::RestartRecord).
void FixLbmPore::write_restart(FILE* fp) {
  const std::string prefix = lbm_pore::checkpoint_prefix(options_, id);
  const std::string path = lbm_pore::checkpoint_path(prefix, update->ntimestep);
  if (!at_fluid_step() && comm->me == 0)
    error->warning(FLERR, "fix lbm/pore: restart written between fluid steps (not a multiple of "
                          "n_dem): the continued run will differ slightly from an uninterrupted one");
  try {
    lbm::write_checkpoint(*solver_, path);
    lbm::prune_checkpoints(prefix, solver_->decomposition().comm.rank(), options_.checkpoint_keep);
  } catch (const lbm::InputError& e) {
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, e.what());
  }
  if (comm->me != 0) return;
  const std::string record = lbm_pore::RestartRecord{
      monitor_->state(), path, capped_drive_ ? capped_drive_->state() : std::vector<double>()}.bytes();
  const int size = static_cast<int>(record.size());
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(record.data(), 1, record.size(), fp);
}

void FixLbmPore::restart(char* buf) {
  lbm_pore::RestartRecord record = lbm_pore::RestartRecord::read(buf);
  restored_state_ = std::move(record.monitor_state);
  resume_checkpoint_ = std::move(record.checkpoint);
  restored_drive_state_ = std::move(record.drive_state);
}

void FixLbmPore::grow_arrays(int nmax) {
  const int old = states_.size();
  states_.resize(nmax);
  memory->grow(hydrodynamic_force_, nmax, 3, "lbm/pore:hydrodynamic_force");
  for (int i = old; i < nmax; ++i) hydrodynamic_force_[i][0] = hydrodynamic_force_[i][1] = hydrodynamic_force_[i][2] = 0.0;
  array_atom = hydrodynamic_force_;
}

// A new atom (fix insert/..., create_attribute) starts with no load and no previous
// position. Insertion calls this before it numbers the atom (tag 0): AtomStates::own then
// resets the slot again under the atom's tag at its first fluid step, which changes nothing.
void FixLbmPore::set_arrays(int i) {
  states_.reset(i, atom->tag[i]);
  for (int a = 0; a < 3; ++a) hydrodynamic_force_[i][a] = 0.0;
}

void FixLbmPore::copy_arrays(int i, int j, int) {
  states_[j] = states_[i];
  for (int a = 0; a < 3; ++a) hydrodynamic_force_[j][a] = hydrodynamic_force_[i][a];
}

int FixLbmPore::pack_exchange(int i, double* buf) { return states_.pack_exchange(i, buf); }
int FixLbmPore::unpack_exchange(int nlocal, double* buf) { return states_.unpack_exchange(nlocal, buf); }
int FixLbmPore::pack_restart(int i, double* buf) { return states_.pack_restart(i, buf); }

void FixLbmPore::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int n = 0; n < nth; ++n) m += static_cast<int>(extra[nlocal][m]);
  if (!states_.unpack_restart(nlocal, &extra[nlocal][m]))
    error->one(FLERR, "fix lbm/pore: the restart file's per-atom data has another layout (written by "
                      "another version of lbm-pore); restart from a file written by this one");
}

int FixLbmPore::size_restart(int) { return lbm_pore::AtomStates::kRestart; }
int FixLbmPore::maxsize_restart() { return lbm_pore::AtomStates::kRestart; }

// Forward: the velocity the fluid sees and the angular velocity, owner -> ghosts. Reverse:
// the loads the fluid put on ghost images, onto their owners. LIGGGHTS's Comm expects the
// count per atom that the packs return, not the total.
int FixLbmPore::pack_comm(int n, int* list, double* buf, int, int*) {
  return states_.pack_forward(n, list, atom->omega, buf);
}
void FixLbmPore::unpack_comm(int n, int first, double* buf) { states_.unpack_forward(n, first, atom->omega, buf); }
int FixLbmPore::pack_reverse_comm(int n, int first, double* buf) { return states_.pack_reverse(n, first, buf); }
void FixLbmPore::unpack_reverse_comm(int n, int* list, double* buf) { states_.unpack_reverse(n, list, buf); }
