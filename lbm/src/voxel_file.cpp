#include "lbm/voxel_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"

#ifdef LBM_PORE_HAVE_VTK
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLImageDataReader.h>
#endif

namespace lbm {
namespace {

constexpr const char* kMagic = "LBMPORE_VOXELS";

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("voxel file '" + path + "': " + what);
}

// A header line's words and nothing after them but blanks (a '\r' of a Windows line end).
bool read_whole_line(std::istringstream& line) { return !line.fail() && (line >> std::ws).eof(); }

// Refuses sizes whose voxels do not fit in memory, before anything is allocated for them.
void check_geometry_fits(const std::string& path, const std::array<int, 3>& dims,
                         double bytes_per_voxel) {
  check_fits_in_memory(geometry_bytes(dims) * bytes_per_voxel,
                       "voxel file '" + path + "': a geometry of " + std::to_string(dims[0]) +
                           " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                           " voxels (its sizes)");
}

// A geometry without a fluid voxel has nothing to simulate (and buries every particle).
void check_has_fluid(const std::string& path, const VoxelGeometry& g) {
  if (g.count_solid() == g.num_voxels())
    fail(path, "is all solid: there is no fluid (all " + std::to_string(g.num_voxels()) +
                   " voxels are nonzero; 0 = fluid)");
}

// Bytes left in `in` from its current position (the stream is left there); -1 when the stream
// cannot tell (not seekable). A header whose last line has no newline leaves the stream at
// its end, where tellg() fails: nothing is left then (found by tests/fuzz).
std::streamoff bytes_left(std::istream& in) {
  if (in.eof()) return 0;
  const std::streampos here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  return here < 0 || end < 0 ? -1 : std::streamoff(end - here);
}

}  // namespace

VoxelGeometry read_raw_voxels(std::istream& in, const std::string& path) {
  std::string line;
  if (!std::getline(in, line)) fail(path, "is empty");
  std::istringstream magic_line(line);
  std::string magic;
  int version = 0;
  magic_line >> magic >> version;
  if (magic != kMagic || version != 1 || !read_whole_line(magic_line))
    fail(path, "first line must be '" + std::string(kMagic) + " 1' (got '" + line + "')");
  std::array<int, 3> dims{};
  if (!std::getline(in, line)) fail(path, "missing dimensions line '<nx> <ny> <nz>'");
  std::istringstream dims_line(line);
  dims_line >> dims[0] >> dims[1] >> dims[2];
  if (!read_whole_line(dims_line))
    fail(path, "second line must be '<nx> <ny> <nz>' (got '" + line + "')");
  for (int d = 0; d < 3; ++d)
    if (dims[d] <= 0 || dims[d] > 100000) fail(path, "dimensions must be in [1, 100000]");
  double spacing = 0;
  std::array<double, 3> origin{};
  if (!std::getline(in, line)) fail(path, "missing line '<spacing> <ox> <oy> <oz>'");
  std::istringstream frame_line(line);
  frame_line >> spacing >> origin[0] >> origin[1] >> origin[2];
  if (!read_whole_line(frame_line))
    fail(path, "third line must be '<spacing> <ox> <oy> <oz>' (got '" + line + "')");
  if (!(spacing > 0) || !std::isfinite(spacing)) fail(path, "spacing must be > 0");
  check_geometry_fits(path, dims, 1.0);
  const double expected = geometry_bytes(dims);
  const std::streamoff left = bytes_left(in);
  if (left >= 0 && double(left) < expected)
    fail(path, "truncated: expected " + std::to_string(std::size_t(expected)) +
                   " voxel bytes, found " + std::to_string(left));
  VoxelGeometry g(dims, spacing, origin);
  std::string bytes(g.num_voxels(), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::size_t>(in.gcount()) != bytes.size())
    fail(path, "truncated: expected " + std::to_string(bytes.size()) + " voxel bytes, found " +
                   std::to_string(in.gcount()));
  if (in.peek() != std::char_traits<char>::eof())
    fail(path, "has bytes after the " + std::to_string(bytes.size()) + " expected voxels");
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) g.set_solid(i, j, k, bytes[g.index(i, j, k)] != 0);
  check_has_fluid(path, g);
  return g;
}

namespace {

#ifdef LBM_PORE_HAVE_VTK
VoxelGeometry load_vti(const std::string& path) {
  {
    std::ifstream probe(path);
    if (!probe) fail(path, "cannot be opened");
  }
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  if (!reader->CanReadFile(path.c_str())) fail(path, "is not a VTK XML image file");
  reader->SetFileName(path.c_str());
  // The sizes first (the XML header only): VTK allocates the whole array in Update().
  reader->UpdateInformation();
  int extent[6] = {0, -1, 0, -1, 0, -1};
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  // VTK's array (up to 8 bytes a value) and the geometry (one byte). An empty or inverted
  // extent is refused below, by the geometry's own size check.
  const std::array<int, 3> extent_dims{extent[1] - extent[0] + 1, extent[3] - extent[2] + 1,
                                       extent[5] - extent[4] + 1};
  if (extent_dims[0] > 0 && extent_dims[1] > 0 && extent_dims[2] > 0)
    check_geometry_fits(path, extent_dims, 9.0);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int vtk_dims[3];
  image->GetDimensions(vtk_dims);
  double vtk_spacing[3], vtk_origin[3];
  image->GetSpacing(vtk_spacing);
  image->GetOrigin(vtk_origin);
  vtkDataArray* array = image->GetPointData()->GetArray("solid");
  std::array<int, 3> dims{vtk_dims[0], vtk_dims[1], vtk_dims[2]};
  std::array<double, 3> origin{vtk_origin[0], vtk_origin[1], vtk_origin[2]};
  if (!array) {
    // Cell data: one value per cell of the image, whose centres are the voxel nodes.
    array = image->GetCellData()->GetArray("solid");
    if (!array) fail(path, "has no point or cell data array named 'solid'");
    for (int d = 0; d < 3; ++d) {
      dims[d] = std::max(1, vtk_dims[d] - 1);
      origin[d] += 0.5 * vtk_spacing[d];
    }
  }
  if (std::abs(vtk_spacing[0] - vtk_spacing[1]) > 1e-12 * vtk_spacing[0] ||
      std::abs(vtk_spacing[0] - vtk_spacing[2]) > 1e-12 * vtk_spacing[0])
    fail(path, "spacing must be equal on all axes (the lattice is cubic)");
  VoxelGeometry g(dims, vtk_spacing[0], origin);
  if (array->GetNumberOfTuples() != static_cast<vtkIdType>(g.num_voxels()))
    fail(path, "array 'solid' has " + std::to_string(array->GetNumberOfTuples()) +
                   " values, expected " + std::to_string(g.num_voxels()));
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        g.set_solid(i, j, k, array->GetComponent(static_cast<vtkIdType>(g.index(i, j, k)), 0) != 0);
  check_has_fluid(path, g);
  return g;
}
#endif

}  // namespace

VoxelGeometry load_voxel_file(const std::string& path) {
  if (ends_with(path, ".vti")) {
#ifdef LBM_PORE_HAVE_VTK
    return load_vti(path);
#else
    fail(path, ".vti geometry needs VTK; rebuild with libvtk9-dev or use the raw format");
#endif
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened");
  return read_raw_voxels(in, path);
}

void save_voxel_file_raw(const VoxelGeometry& g, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError("voxel file '" + path + "': cannot be written");
  out << kMagic << " 1\n"
      << g.dims()[0] << ' ' << g.dims()[1] << ' ' << g.dims()[2] << '\n';
  out.precision(17);
  out << g.spacing() << ' ' << g.origin()[0] << ' ' << g.origin()[1] << ' ' << g.origin()[2]
      << '\n';
  for (std::uint8_t v : g.data()) out.put(static_cast<char>(v));
}

}  // namespace lbm
