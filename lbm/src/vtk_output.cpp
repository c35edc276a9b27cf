#include "lbm/vtk_output.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "lbm/d3q19.h"
#include "lbm/halo_exchange.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"

#ifdef LBM_PORE_HAVE_VTK
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkTrivialProducer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>
#endif

// Choices, for a reader of the files:
// - Point data on lattice nodes: point (i,j,k) of the image is node (i,j,k) at
//   origin + (i,j,k) * spacing. Contours and stream tracers in ParaView work on point data.
// - Pieces share their boundary points, so ParaView shows no gap between ranks: a rank's
//   piece is its owned nodes plus the first node layer of the rank above on every axis that
//   does not end at the global upper face. Those values come from the neighbour through a
//   halo exchange of the macroscopic fields (not of the populations: ghost populations are
//   one step stale between steps).
// - Lattice units for the values: density rho, pressure p = cs^2 rho = rho / 3 (absolute,
//   as in plane_mean_pressure), velocity u; node_type is lbm::NodeType. Solid nodes report
//   rho0 and u = 0 (compute_fields).

namespace lbm {

bool VtkSeriesWriter::available() {
#ifdef LBM_PORE_HAVE_VTK
  return true;
#else
  return false;
#endif
}

VtkSeriesWriter::VtkSeriesWriter(std::string directory, std::string prefix)
    : directory_(std::move(directory)), prefix_(std::move(prefix)) {
  if (!available())
    throw InputError(
        "fluid VTK output needs VTK: this build of lbm-pore has none (install "
        "libvtk9-dev and reconfigure with LBM_PORE_WITH_VTK=ON)");
  if (prefix_.empty()) throw InputError("fluid VTK output: the file prefix is empty");
}

#ifdef LBM_PORE_HAVE_VTK

namespace {
std::string step_name(const std::string& prefix, long long step) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%06lld", step);
  return prefix + "_" + digits;
}

// The shortest of 15..17 significant digits that reads back as the same double.
std::string number(double value) {
  std::string text;
  for (int digits = 15; digits <= 17; ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    text = out.str();
    if (std::stod(text) == value) break;
  }
  return text;
}

// Writes `text` to `path` through a temporary file and a rename, so ParaView never reads a
// half-written index.
bool write_text(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << text;
    if (!out) return false;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  return !error;
}

// Every rank learns whether any rank failed, so all throw together instead of some
// waiting forever in the next collective call.
void check_all(const Communicator& comm, bool ok, const std::string& message) {
  double failures = ok ? 0.0 : 1.0;
  comm.sum(&failures, 1);
  if (failures > 0.0) throw std::runtime_error(message);
}
// The macroscopic fields on the padded block: owned values from compute_fields, the
// ghost layer from the neighbours.
struct PaddedFields {
  std::vector<double> density, ux, uy, uz, node_type;
};

PaddedFields padded_fields(const FluidSolver& solver) {
  const BlockLayout& layout = solver.layout();
  const MacroscopicFields owned = compute_fields(solver);
  PaddedFields p;
  const std::size_t cells = layout.num_cells();
  p.density.assign(cells, solver.parameters().rho0);
  p.ux.assign(cells, 0.0);
  p.uy.assign(cells, 0.0);
  p.uz.assign(cells, 0.0);
  p.node_type.assign(solver.node_types().begin(), solver.node_types().end());
  std::size_t n = 0;
  for (int k = 0; k < layout.size(2); ++k)
    for (int j = 0; j < layout.size(1); ++j)
      for (int i = 0; i < layout.size(0); ++i, ++n) {
        const std::size_t cell = layout.cell(i, j, k);
        p.density[cell] = owned.density[n];
        p.ux[cell] = owned.velocity[3 * n];
        p.uy[cell] = owned.velocity[3 * n + 1];
        p.uz[cell] = owned.velocity[3 * n + 2];
        p.node_type[cell] = owned.node_type[n];
      }
  // Collective over the ranks of the decomposition, so decided by the communicator's size
  // alone (every rank takes the same branch).
  if (solver.decomposition().comm.size() > 1) {
    HaloExchange halo(solver.decomposition(), layout);
    for (auto* field : {&p.density, &p.ux, &p.uy, &p.uz, &p.node_type})
      halo.exchange_scalar(*field);
  }
  return p;
}

// The entries of an existing .pvd written before `time`: a run resumed from a restart
// continues the series of the run it resumes; later entries (of the interrupted run) and
// every entry of an older run that started at time 0 again are dropped.
std::vector<std::pair<double, std::string>> earlier_entries(const std::filesystem::path& pvd,
                                                            double time) {
  std::vector<std::pair<double, std::string>> kept;
  std::ifstream in(pvd);
  if (!in) return kept;
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  const std::regex entry("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), entry); it != std::sregex_iterator();
       ++it) {
    double t = 0.0;
    try {
      t = std::stod((*it)[1].str());
    } catch (const std::exception&) {
      continue;  // not ours: skip rather than fail the run over an index file
    }
    if (t < time) kept.emplace_back(t, (*it)[2].str());
  }
  return kept;
}

const char* byte_order() {
  const std::uint16_t one = 1;
  return *reinterpret_cast<const unsigned char*>(&one) == 1 ? "LittleEndian" : "BigEndian";
}

bool write_piece(const FluidSolver& solver, const PaddedFields& fields, const int extent[6],
                 const int whole[6], const std::string& path) {
  const VoxelGeometry& geometry = solver.geometry();
  const BlockLayout& layout = solver.layout();
  vtkNew<vtkImageData> image;
  image->SetExtent(const_cast<int*>(extent));
  image->SetOrigin(geometry.origin()[0], geometry.origin()[1], geometry.origin()[2]);
  image->SetSpacing(geometry.spacing(), geometry.spacing(), geometry.spacing());
  const vtkIdType points = image->GetNumberOfPoints();

  vtkNew<vtkDoubleArray> density, pressure, velocity;
  vtkNew<vtkUnsignedCharArray> node_type;
  density->SetName("density");
  pressure->SetName("pressure");
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  node_type->SetName("node_type");
  density->SetNumberOfTuples(points);
  pressure->SetNumberOfTuples(points);
  velocity->SetNumberOfTuples(points);
  node_type->SetNumberOfTuples(points);
  const auto& lo = layout.owned().lo;
  vtkIdType n = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
    for (int j = extent[2]; j <= extent[3]; ++j)
      for (int i = extent[0]; i <= extent[1]; ++i, ++n) {
        const std::size_t cell = layout.cell(i - lo[0], j - lo[1], k - lo[2]);
        density->SetValue(n, fields.density[cell]);
        pressure->SetValue(n, D3Q19::cs2 * fields.density[cell]);
        const double u[3] = {fields.ux[cell], fields.uy[cell], fields.uz[cell]};
        velocity->SetTypedTuple(n, u);
        node_type->SetValue(n, static_cast<unsigned char>(fields.node_type[cell]));
      }
  image->GetPointData()->AddArray(density);
  image->GetPointData()->AddArray(pressure);
  image->GetPointData()->AddArray(velocity);
  image->GetPointData()->AddArray(node_type);
  image->GetPointData()->SetActiveScalars("density");
  image->GetPointData()->SetActiveVectors("velocity");

  // The producer carries the global whole extent into the piece file.
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(image);
  producer->SetWholeExtent(const_cast<int*>(whole));
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputConnection(producer->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // as declared in the .pvti
  return writer->Write() == 1;
}

std::string pvti_text(const FluidSolver& solver, const std::vector<long long>& extents,
                      const int whole[6], const std::string& stem) {
  const VoxelGeometry& geometry = solver.geometry();
  const double h = geometry.spacing();
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"PImageData\" version=\"1.0\" byte_order=\"" << byte_order()
    << "\" header_type=\"UInt64\">\n"
    << "  <PImageData WholeExtent=\"" << whole[0] << ' ' << whole[1] << ' ' << whole[2] << ' '
    << whole[3] << ' ' << whole[4] << ' ' << whole[5] << "\" GhostLevel=\"0\" Origin=\""
    << number(geometry.origin()[0]) << ' ' << number(geometry.origin()[1]) << ' '
    << number(geometry.origin()[2]) << "\" Spacing=\"" << number(h) << ' ' << number(h) << ' '
    << number(h) << "\">\n"
    << "    <PPointData Scalars=\"density\" Vectors=\"velocity\">\n"
    << "      <PDataArray type=\"Float64\" Name=\"density\"/>\n"
    << "      <PDataArray type=\"Float64\" Name=\"pressure\"/>\n"
    << "      <PDataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"/>\n"
    << "      <PDataArray type=\"UInt8\" Name=\"node_type\"/>\n"
    << "    </PPointData>\n";
  const std::size_t ranks = extents.size() / 6;
  for (std::size_t r = 0; r < ranks; ++r) {
    x << "    <Piece Extent=\"";
    for (int e = 0; e < 6; ++e) x << extents[6 * r + e] << (e < 5 ? " " : "");
    x << "\" Source=\"" << stem << '_' << r << ".vti\"/>\n";
  }
  x << "  </PImageData>\n</VTKFile>\n";
  return x.str();
}
}  // namespace

void VtkSeriesWriter::write(const FluidSolver& solver, double time) {
  const Decomposition& d = solver.decomposition();
  const Communicator& comm = d.comm;
  const int rank = comm.rank(), ranks = comm.size();
  const std::filesystem::path directory(directory_);
  bool ok = true;
  if (rank == 0) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    ok = !error && std::filesystem::is_directory(directory);
  }
  check_all(comm, ok, "fluid VTK output: cannot create the directory '" + directory_ + "'");

  const PaddedFields fields = padded_fields(solver);
  int whole[6], extent[6];
  for (int a = 0; a < 3; ++a) {
    whole[2 * a] = d.global.lo[a];
    whole[2 * a + 1] = d.global.hi[a] - 1;
    extent[2 * a] = d.owned.lo[a];
    // One shared layer with the rank above, unless this piece ends at the global face.
    extent[2 * a + 1] = d.owned.hi[a] - (d.owned.hi[a] < d.global.hi[a] ? 0 : 1);
  }
  const std::string stem = step_name(prefix_, solver.time_step());
  const std::string piece = ranks == 1 ? stem + ".vti" : stem + "_" + std::to_string(rank) + ".vti";
  ok = write_piece(solver, fields, extent, whole, (directory / piece).string());
  check_all(comm, ok, "fluid VTK output: cannot write '" + (directory / piece).string() + "'");

  std::string listed = piece;
  if (ranks > 1) {
    // Rank 0 needs every piece's extent for the index file: a sum of one-hot slots.
    std::vector<long long> extents(6 * std::size_t(ranks), 0);
    for (int e = 0; e < 6; ++e) extents[6 * std::size_t(rank) + e] = extent[e];
    comm.sum(extents.data(), int(extents.size()));
    listed = stem + ".pvti";
    ok = rank != 0 || write_text(directory / listed, pvti_text(solver, extents, whole, stem));
    check_all(comm, ok, "fluid VTK output: cannot write '" + (directory / listed).string() + "'");
  }

  if (rank == 0) {
    const std::filesystem::path pvd_path = directory / (prefix_ + ".pvd");
    if (entries_.empty()) entries_ = earlier_entries(pvd_path, time);
    // Writing the same step again replaces its entry.
    if (!entries_.empty() && entries_.back().second == listed)
      entries_.back().first = time;
    else
      entries_.emplace_back(time, listed);
    std::ostringstream pvd;
    pvd << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"" << byte_order() << "\">\n"
        << "  <Collection>\n";
    for (const auto& [t, file] : entries_)
      pvd << "    <DataSet timestep=\"" << number(t) << "\" group=\"\" part=\"0\" file=\"" << file
          << "\"/>\n";
    pvd << "  </Collection>\n</VTKFile>\n";
    ok = write_text(pvd_path, pvd.str());
  }
  check_all(comm, ok,
            "fluid VTK output: cannot write '" + (directory / (prefix_ + ".pvd")).string() + "'");
}

#else

void VtkSeriesWriter::write(const FluidSolver&, double) {
  throw InputError("fluid VTK output needs VTK: this build of lbm-pore has none");
}

#endif

}  // namespace lbm
