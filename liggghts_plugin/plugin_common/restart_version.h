#pragma once
// The version string of liggghts-lbm's LIGGGHTS, and the restart files that carry it.
//
// LIGGGHTS-PUBLIC follows an ERROR, one time in five, with a joke or a "tip of the day" read
// from a destroyed string (error_special.h): garbage after the error, which must stay the last
// line. It does so only while its version string contains "PUBLIC", so liggghts-lbm keeps the
// string as "Version LIGGGHTS-public 3.8.0, ...". The same string heads every restart file,
// and read_restart warns ("Restart file version does not match LIGGGHTS version") when a
// file's string is not its own: liggghts-lbm's files would warn in Debian's liggghts and the
// other way round. So LIGGGHTS's own string is back, on the rank that writes or reads a
// restart file's header (rank 0 of the run), while it does, and the files of both programs
// are the same:
//  - write_restart runs with it, and read_restart with a file that carries it (the two
//    commands are wrapped);
//  - in a run, Output writes restart files after the fixes' end_of_step. A fix liggghts-lbm
//    adds to every run (ID lbm_restart_version) puts the string back at the end of a step that
//    writes one, as the last end_of_step, and hides it again at the start of the next step, as
//    the first pre_initial_integrate, and at the end of the run.
// An error that rank 0 raises within that window (in the output of a step that writes a
// restart file, e.g. fix lbm/pore failing to write its checkpoint, or while a restart file is
// read) may still be followed by LIGGGHTS's joke; the other ranks never show it.
namespace LAMMPS_NS {
class Fix;
class LAMMPS;
}  // namespace LAMMPS_NS

namespace lbm_pore {

// At start-up, after the LAMMPS instance is built and before any input: hides "PUBLIC" and
// wraps read_restart, write_restart and run. Only the first instance of a process; nothing
// when the version string has no "PUBLIC" (another edition of LIGGGHTS).
void keep_restart_files_stock(LAMMPS_NS::LAMMPS* lmp);

// The fix of the runs (style_registry.cpp registers it; keep_restart_files_stock adds it).
inline constexpr const char* kRestartVersionFixStyle = "lbm/restart_version";
LAMMPS_NS::Fix* create_restart_version_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

}  // namespace lbm_pore
