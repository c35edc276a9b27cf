#include "lbm/voxel_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "lbm/input_error.h"

#ifdef LBM_PORE_HAVE_VTK
#include <vtkDataArray.h>
#include <vtkCellData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
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

VoxelGeometry load_raw(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened");
  std::string line;
  if (!std::getline(in, line)) fail(path, "is empty");
  std::istringstream magic_line(line);
  std::string magic;
  int version = 0;
  magic_line >> magic >> version;
  if (magic != kMagic || version != 1)
    fail(path, "first line must be '" + std::string(kMagic) + " 1' (got '" + line + "')");
  std::array<int, 3> dims{};
  if (!std::getline(in, line)) fail(path, "missing dimensions line '<nx> <ny> <nz>'");
  std::istringstream dims_line(line);
  if (!(dims_line >> dims[0] >> dims[1] >> dims[2]))
    fail(path, "second line must be '<nx> <ny> <nz>' (got '" + line + "')");
  for (int d = 0; d < 3; ++d)
    if (dims[d] <= 0 || dims[d] > 100000) fail(path, "dimensions must be in [1, 100000]");
  double spacing = 0;
  std::array<double, 3> origin{};
  if (!std::getline(in, line)) fail(path, "missing line '<spacing> <ox> <oy> <oz>'");
  std::istringstream frame_line(line);
  if (!(frame_line >> spacing >> origin[0] >> origin[1] >> origin[2]))
    fail(path, "third line must be '<spacing> <ox> <oy> <oz>' (got '" + line + "')");
  if (!(spacing > 0)) fail(path, "spacing must be > 0");
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
  return g;
}

#ifdef LBM_PORE_HAVE_VTK
VoxelGeometry load_vti(const std::string& path) {
  {
    std::ifstream probe(path);
    if (!probe) fail(path, "cannot be opened");
  }
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  if (!reader->CanReadFile(path.c_str())) fail(path, "is not a VTK XML image file");
  reader->SetFileName(path.c_str());
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
  return load_raw(path);
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
