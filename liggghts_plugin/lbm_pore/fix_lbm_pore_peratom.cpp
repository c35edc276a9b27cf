// fix lbm/pore's per-atom data: growing and moving it with its atoms, restart files (the
// fluid goes to a companion checkpoint), and LIGGGHTS's forward/reverse communication.
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "fix_lbm_pore_internal.h"
#include "lbm/checkpoint.h"
#include "lbm/input_error.h"
#include "memory.h"
#include "plugin_common/stop_run.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace lbm_pore::slots;

// Restart: the particles travel in LIGGGHTS's restart file with their loads; the fluid goes
// to a companion checkpoint (one file per rank) whose name is stored in the restart file.
void FixLbmPore::write_restart(FILE* fp) {
  std::string prefix = options_.checkpoint_prefix.empty() ? std::string(id) + ".fluid"
                                                          : options_.checkpoint_prefix;
  const std::string path = prefix + "." + std::to_string(update->ntimestep);
  if (update->ntimestep % options_.n_dem != 0 && comm->me == 0)
    error->warning(FLERR, "fix lbm/pore: restart written between fluid steps (not a multiple of "
                          "n_dem): the continued run will differ slightly from an uninterrupted one");
  try {
    lbm::write_checkpoint(*solver_, path);
  } catch (const lbm::InputError& e) {
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, e.what());
  }
  if (comm->me == 0) {
    const int size = static_cast<int>(path.size()) + 1 + 8 * kNumDiagnostics;
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(diagnostics_.data(), sizeof(double), kNumDiagnostics, fp);
    std::fwrite(path.c_str(), 1, path.size() + 1, fp);
  }
}

void FixLbmPore::restart(char* buf) {
  // buf: the diagnostics (cumulative particle fluxes), then the checkpoint path.
  std::memcpy(diagnostics_.data(), buf, sizeof(double) * kNumDiagnostics);
  resume_checkpoint_ = std::string(buf + sizeof(double) * kNumDiagnostics);
}

void FixLbmPore::grow_arrays(int nmax) {
  memory->grow(loads_, nmax, kLoadsPerAtom, "lbm/pore:loads");
  for (int i = nmax_; i < nmax; ++i)
    for (int k = 0; k < kLoadsPerAtom; ++k) loads_[i][k] = 0.0;
  nmax_ = nmax;
}

// A new atom (fix insert/...) starts with no load and no previous position: its slot may
// hold a former atom's values. Not every LIGGGHTS insertion calls set_arrays, so the slot
// also records its atom's tag and own_slot() resets a slot whose tag differs.
void FixLbmPore::set_arrays(int i) {
  for (int k = 0; k < kLoadsPerAtom; ++k) loads_[i][k] = 0.0;
  loads_[i][kTag] = atom->tag[i];
}

void FixLbmPore::own_slot(int i) {
  if (loads_[i][kTag] != double(atom->tag[i])) set_arrays(i);
}

void FixLbmPore::copy_arrays(int i, int j, int) {
  for (int k = 0; k < kLoadsPerAtom; ++k) loads_[j][k] = loads_[i][k];
}

int FixLbmPore::pack_exchange(int i, double* buf) {
  for (int k = 0; k < kLoadsPerAtom; ++k) buf[k] = loads_[i][k];
  return kLoadsPerAtom;
}

int FixLbmPore::unpack_exchange(int nlocal, double* buf) {
  for (int k = 0; k < kLoadsPerAtom; ++k) loads_[nlocal][k] = buf[k];
  return kLoadsPerAtom;
}

int FixLbmPore::pack_restart(int i, double* buf) {
  buf[0] = kLoadsPerAtom + 1;
  for (int k = 0; k < kLoadsPerAtom; ++k) buf[1 + k] = loads_[i][k];
  return kLoadsPerAtom + 1;
}

void FixLbmPore::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int n = 0; n < nth; ++n) m += static_cast<int>(extra[nlocal][m]);
  ++m;
  for (int k = 0; k < kLoadsPerAtom; ++k) loads_[nlocal][k] = extra[nlocal][m++];
}

int FixLbmPore::size_restart(int) { return kLoadsPerAtom + 1; }
int FixLbmPore::maxsize_restart() { return kLoadsPerAtom + 1; }

// Forward: the velocity the fluid sees and the angular velocity, owner -> ghosts.
int FixLbmPore::pack_comm(int n, int* list, double* buf, int, int*) {
  double** omega = atom->omega;
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const int i = list[k];
    for (int a = 0; a < 3; ++a) buf[m++] = loads_[i][kWallVelocity + a];
    for (int a = 0; a < 3; ++a) buf[m++] = omega ? omega[i][a] : 0.0;
  }
  return comm_forward;  // LIGGGHTS's Comm expects the count per atom, not the total
}

void FixLbmPore::unpack_comm(int n, int first, double* buf) {
  double** omega = atom->omega;
  int m = 0;
  for (int i = first; i < first + n; ++i) {
    for (int a = 0; a < 3; ++a) loads_[i][kWallVelocity + a] = buf[m++];
    for (int a = 0; a < 3; ++a) {
      if (omega) omega[i][a] = buf[m];
      ++m;
    }
  }
}

int FixLbmPore::pack_reverse_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i)
    for (int k = 0; k < kSummedPerAtom; ++k) buf[m++] = loads_[i][k];
  return kSummedPerAtom;  // per atom, as LIGGGHTS's Comm expects
}

void FixLbmPore::unpack_reverse_comm(int n, int* list, double* buf) {
  int m = 0;
  for (int k = 0; k < n; ++k)
    for (int q = 0; q < kSummedPerAtom; ++q) loads_[list[k]][q] += buf[m++];
}

