#pragma once
// Shared pieces of the accuracy study (examples/accuracy): one result row per run. The set-ups
// it shares with the tests (pipe, sphere array, sphere-wall approach, serial solver, timing)
// are in tests/cases (lbmpore::cases). Every number in a row is computed by the run.
#include <string>
#include <vector>

#include "cases/serial_flow.h"

namespace accuracy {

// The serial solver set-up and lattice sums shared with the tests (tests/cases).
using cases::fluid_mass;
using cases::kPi;
using cases::make_solver;
using cases::Stopwatch;
using cases::superficial_velocity;

// One run of one case: the columns of accuracy.csv.
struct Row {
  std::string case_name;   // pipe, drag, lubrication, dashdot, moving
  std::string option;      // scheme or variant
  double resolution = 0;   // cells (pipe: radius, spheres: diameter); 0 where none
  int n_dem = 0;           // DEM steps per contact (dashdot); 0 where not applicable
  double error = 0;        // relative error, >= 0 (the case says which norm)
  std::string reference;   // the source the error is measured against
  double wall_seconds = 0;
  double value = 0;            // the headline quantity measured ...
  double reference_value = 0;  // ... and its reference value (the error's basis may differ)
  long steps = 0;              // fluid or DEM steps
  std::string note;            // key=value extras (mass drift, signed errors)
};

struct Options {
  bool quick = false;
};

// The cases; each appends its rows.
void run_pipe(const Options& options, std::vector<Row>& rows);
void run_drag(const Options& options, std::vector<Row>& rows);
void run_lubrication(const Options& options, std::vector<Row>& rows);
void run_dashdot(const Options& options, std::vector<Row>& rows);
void run_moving(const Options& options, std::vector<Row>& rows);

}  // namespace accuracy
