// Accuracy study driver: runs the validation cases over resolutions, DEM steps per contact
// and boundary/collision options, and writes one CSV row per run
// (case, option, resolution, n_dem, error, reference, wall_seconds, value, reference_value,
// steps, note). plot_accuracy.py turns the CSV into a plot and a Markdown table.
//
//   accuracy_cases [--quick] [--check] [--cases pipe,drag,lubrication,dashdot,moving]
//                  [--csv FILE]
//
// --quick runs a reduced set (well under a minute); --check exits non-zero unless the error
// of every converging series shrinks with resolution (or with DEM steps per contact).
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#ifdef LBM_PORE_HAVE_MPI
#include <mpi.h>
#endif

#include "accuracy.h"

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void write_csv(std::FILE* out, const std::vector<accuracy::Row>& rows) {
  std::fprintf(out, "case,option,resolution,n_dem,error,reference,wall_seconds,value,reference_value,steps,note\n");
  for (const auto& r : rows)
    std::fprintf(out, "%s,%s,%g,%d,%.6e,%s,%.6e,%.8g,%.8g,%ld,%s\n", csv_field(r.case_name).c_str(),
                 csv_field(r.option).c_str(), r.resolution, r.n_dem, r.error,
                 csv_field(r.reference).c_str(), r.wall_seconds, r.value, r.reference_value, r.steps,
                 csv_field(r.note).c_str());
}

// Series whose error must decrease as the resolution (or n_dem) grows. The others (bounce-back
// on moving spheres, the lattice without the lubrication correction) are shown for
// comparison: their error need not shrink monotonically.
bool must_converge(const accuracy::Row& r) {
  if (r.case_name == "pipe") return r.option == "Bouzidi" || r.option == "bounce-back";
  if (r.case_name == "drag") return r.option == "Mei-Luo-Shyy" || r.option == "Bouzidi";
  if (r.case_name == "moving") return r.option == "Mei-Luo-Shyy";
  if (r.case_name == "dashdot") return true;
  return false;
}

int check(const std::vector<accuracy::Row>& rows) {
  std::map<std::string, std::vector<const accuracy::Row*>> series;
  for (const auto& r : rows)
    if (must_converge(r)) series[r.case_name + " / " + r.option].push_back(&r);
  int failures = 0;
  // The lubrication correction must make the sphere-wall force closer to Brenner's at
  // every resolution.
  for (const auto& with : rows) {
    if (with.case_name != "lubrication" || with.option != "with correction") continue;
    for (const auto& without : rows)
      if (without.case_name == "lubrication" && without.option == "without correction" &&
          without.resolution == with.resolution) {
        const bool ok = with.error < without.error;
        std::printf("CHECK lubrication d=%-4g          with correction %.4f < without %.4f: %s\n",
                    with.resolution, with.error, without.error, ok ? "ok" : "NOT smaller");
        if (!ok) ++failures;
      }
  }
  for (const auto& [name, list] : series) {
    bool ok = list.size() >= 2;
    std::ostringstream errors;
    for (std::size_t i = 0; i < list.size(); ++i) {
      errors << (i ? " > " : "") << list[i]->error;
      if (i > 0 && !(list[i]->error < list[i - 1]->error)) ok = false;
    }
    std::printf("CHECK %-28s errors %s: %s\n", name.c_str(), errors.str().c_str(),
                ok ? "decreasing, ok" : "NOT decreasing with resolution");
    if (!ok) ++failures;
  }
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef LBM_PORE_HAVE_MPI
  MPI_Init(&argc, &argv);  // the lattice's communicator may call MPI even on one rank
#endif
  accuracy::Options options;
  bool do_check = false;
  std::string csv_path, cases = "pipe,drag,lubrication,dashdot,moving";
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") options.quick = true;
    else if (a == "--check") do_check = true;
    else if (a == "--csv" && i + 1 < argc) csv_path = argv[++i];
    else if (a == "--cases" && i + 1 < argc) cases = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: %s [--quick] [--check] [--cases pipe,drag,lubrication,dashdot,moving] "
                   "[--csv FILE]\n(unknown argument '%s')\n", argv[0], a.c_str());
      status = 2;
    }
  }
  const std::map<std::string, void (*)(const accuracy::Options&, std::vector<accuracy::Row>&)> runners{
      {"pipe", accuracy::run_pipe}, {"drag", accuracy::run_drag},
      {"lubrication", accuracy::run_lubrication}, {"dashdot", accuracy::run_dashdot},
      {"moving", accuracy::run_moving}};
  std::vector<std::string> selected;
  if (status == 0) {
    std::stringstream ss(cases);
    for (std::string name; std::getline(ss, name, ',');) {
      if (!runners.count(name)) {
        std::fprintf(stderr, "--cases: unknown case '%s' (allowed: pipe, drag, lubrication, dashdot, moving)\n",
                     name.c_str());
        status = 2;
      }
      selected.push_back(name);
    }
  }
  if (status == 0) {
    try {
      std::vector<accuracy::Row> rows;
      accuracy::Stopwatch total;
      for (const auto& name : selected) runners.at(name)(options, rows);
      std::fprintf(stderr, "accuracy study: %zu runs, %.1f s\n", rows.size(), total.seconds());
      if (csv_path.empty()) {
        write_csv(stdout, rows);
      } else {
        std::FILE* f = std::fopen(csv_path.c_str(), "w");
        if (!f) {
          std::fprintf(stderr, "cannot write %s\n", csv_path.c_str());
          status = 1;
        } else {
          write_csv(f, rows);
          std::fclose(f);
        }
      }
      if (do_check && check(rows) > 0) status = 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy study failed: %s\n", e.what());
      status = 1;
    }
  }
#ifdef LBM_PORE_HAVE_MPI
  MPI_Finalize();
#endif
  return status;
}
