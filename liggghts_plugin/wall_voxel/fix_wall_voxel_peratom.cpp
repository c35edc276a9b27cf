// fix wall/voxel's per-atom tangential springs: grown and moved with their atoms, and written
// to restart files so that a run continued with read_restart and the same fix (ID, style and
// model) keeps them. The springs' own layout is the wall model's (wall_model.h); a restart
// record is [size, model code, the model's packed springs].
#include <string>

#include "atom.h"
#include "comm.h"
#include "fix_wall_voxel.h"
#include "plugin_common/stop_run.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kRestartHeader = 2;  // the record's size and the model's code
}  // namespace

void FixWallVoxel::grow_arrays(int nmax) { model_->grow(nmax); }

void FixWallVoxel::copy_arrays(int i, int j, int /*delflag*/) { model_->copy(i, j); }

int FixWallVoxel::pack_exchange(int i, double* buf) {
  model_->pack(i, buf);
  return model_->packed_size();
}

int FixWallVoxel::unpack_exchange(int nlocal, double* buf) {
  if (!model_->unpack(nlocal, buf))
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile,
                                "fix wall/voxel: an atom arrived from another rank with corrupt springs");
  return model_->packed_size();
}

int FixWallVoxel::pack_restart(int i, double* buf) {
  buf[0] = model_->packed_size() + kRestartHeader;
  buf[1] = static_cast<double>(model_kind_);
  model_->pack(i, buf + kRestartHeader);
  return model_->packed_size() + kRestartHeader;
}

void FixWallVoxel::unpack_restart(int nlocal, int nth) {
  const double* record = atom->extra[nlocal];
  for (int n = 0; n < nth; ++n) record += static_cast<int>(record[0]);
  const double code = record[1];
  if (code != static_cast<double>(model_kind_)) {
    const bool known = code == static_cast<double>(lbm_pore::WallModelKind::kSmooth) ||
                       code == static_cast<double>(lbm_pore::WallModelKind::kVoxelSum);
    const std::string written =
        known ? std::string("model ") +
                    lbm_pore::wall_model_name(static_cast<lbm_pore::WallModelKind>(code))
              : std::string("an older version of lbm-pore");
    const std::string text = "fix wall/voxel: the restart file holds springs written by " +
                             written + ", this fix has model " +
                             lbm_pore::wall_model_name(model_kind_) +
                             ": give the same model, or a new fix ID to start the springs from zero";
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text.c_str());
  }
  if (static_cast<int>(record[0]) != model_->packed_size() + kRestartHeader ||
      !model_->unpack(nlocal, record + kRestartHeader))
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile,
                                "fix wall/voxel: the restart file's springs are corrupt (not a "
                                "packed set of this model's springs); restart from a file written "
                                "by this version");
}

int FixWallVoxel::size_restart(int /*nlocal*/) { return model_->packed_size() + kRestartHeader; }

int FixWallVoxel::maxsize_restart() { return model_->packed_size() + kRestartHeader; }
