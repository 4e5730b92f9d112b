// VtkGrid -> vtkUnstructuredGrid -> .vtu (appended, raw binary, zlib).
// The file writers' VTK code (vtk_messages.cpp routes VTK's messages; the
// plots under coupling/plots/ include VTK on their own).
#include "rockfdem/coupling/vtk_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::coupling {
namespace {

// Number of components in the file for an array of the record (see vtk_grid.hpp).
int file_components(const VtkArray& a) {
  switch (a.kind) {
    case VtkKind::scalar:
      return 1;
    case VtkKind::vector:
      return 3;
    case VtkKind::symmetric_tensor:
      return 9;
  }
  return 1;
}

// What a vector or tensor gains out of the plane: 0, or NaN where the
// tuple is padding (all NaN: the array does not apply to this cell kind),
// so that such a cell reads NaN in every component, not a zero stress.
template <typename T>
T out_of_plane(const VtkArray& a, const T* in) {
  if constexpr (std::is_floating_point_v<T>) {
    if (std::all_of(in, in + a.n_components, [](T v) { return std::isnan(v); }))
      return std::numeric_limits<T>::quiet_NaN();
  }
  return T(0);
}

// One tuple of the record -> one tuple of the file. Vectors gain z = 0;
// symmetric tensors (xx, yy, xy) or (xx, yy, zz, xy) become the full,
// row-major 3x3 tensor.
template <typename T>
void expand_tuple(const VtkArray& a, const T* in, T* out) {
  if (a.kind == VtkKind::scalar) {
    out[0] = in[0];
    return;
  }
  const T o = out_of_plane(a, in);
  if (a.kind == VtkKind::vector) {
    out[0] = in[0];
    out[1] = in[1];
    out[2] = a.n_components == 3 ? in[2] : o;
  } else {
    const T xx = in[0], yy = in[1];
    const T zz = a.n_components == 4 ? in[2] : o;
    const T xy = a.n_components == 4 ? in[3] : in[2];
    const T full[9] = {xx, xy, o, xy, yy, o, o, o, zz};
    std::copy(full, full + 9, out);
  }
}

template <typename VtkArrayT, typename T>
vtkSmartPointer<vtkDataArray> to_vtk_array(const VtkArray& a, const std::vector<T>& values) {
  auto out = vtkSmartPointer<VtkArrayT>::New();
  out->SetName(a.name.c_str());
  const int nc = file_components(a);
  out->SetNumberOfComponents(nc);
  const vtkIdType n = static_cast<vtkIdType>(a.n_tuples());
  out->SetNumberOfTuples(n);
  auto* dst = out->GetPointer(0);
  for (vtkIdType t = 0; t < n; ++t)
    expand_tuple(a, values.data() + t * a.n_components, dst + t * nc);
  return out;
}

vtkSmartPointer<vtkDataArray> to_vtk_array(const VtkArray& a) {
  // vtkIntArray holds `int`, which the record's int32 values fit exactly.
  static_assert(sizeof(int) == sizeof(std::int32_t), "vtkIntArray must be 32-bit");
  if (a.is_int()) {
    const auto& v = std::get<std::vector<std::int32_t>>(a.values);
    return to_vtk_array<vtkIntArray>(a, std::vector<int>(v.begin(), v.end()));
  }
  return to_vtk_array<vtkDoubleArray>(a, std::get<std::vector<double>>(a.values));
}

void add_field_data(const VtkFieldData& field, vtkFieldData& out) {
  for (const auto& [name, value] : field.text) {
    vtkNew<vtkStringArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    out.AddArray(a);
  }
  for (const auto& [name, value] : field.numbers) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    out.AddArray(a);
  }
}

vtkSmartPointer<vtkPoints> to_vtk_points(const std::vector<double>& x,
                                         const std::vector<double>& y) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), x[i], y[i], 0.0);
  }
  return points;
}

vtkSmartPointer<vtkUnstructuredGrid> to_vtk_grid(const VtkGrid& grid) {
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  ug->SetPoints(to_vtk_points(grid.x, grid.y));
  ug->Allocate(static_cast<vtkIdType>(grid.n_cells()));
  for (const auto& t : grid.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    ug->InsertNextCell(VTK_TRIANGLE, 3, ids);
  }
  for (const auto& l : grid.lines) {
    const vtkIdType ids[2] = {l[0], l[1]};
    ug->InsertNextCell(VTK_LINE, 2, ids);
  }
  for (const VtkArray& a : grid.point_arrays) ug->GetPointData()->AddArray(to_vtk_array(a));
  for (const VtkArray& a : grid.cell_arrays) ug->GetCellData()->AddArray(to_vtk_array(a));
  add_field_data(grid.field, *ug->GetFieldData());
  return ug;
}

/// A writer's error code in words: VTK's own codes (vtkErrorCode, from
/// 20001) name the kind, a system error (errno, as the XML writers set it
/// when a stream fails: 28 for a full disk) is its strerror text.
std::string vtk_error_text(unsigned long code) {
  const bool vtk_kind =
      code >= vtkErrorCode::FileNotFoundError && code <= vtkErrorCode::UnknownError;
  const std::string text = code == vtkErrorCode::OutOfDiskSpaceError   ? "out of disk space"
                           : code == vtkErrorCode::CannotOpenFileError ? "cannot open the file"
                           : vtk_kind                                  ? "a VTK error"
                                                                       : std::strerror(int(code));
  return "VTK writer failed: " + text + " (error code " + std::to_string(code) + ")";
}

/// Appended raw binary, zlib, UInt64 headers; temp file then rename.
template <typename Writer>
void write_xml(Writer* writer, const std::string& path) {
  AtomicFile file(path);
  writer->SetFileName(file.temp_path().c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes, not base64: a third smaller
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // block sizes beyond 4 GiB
  if (writer->Write() != 1 || writer->GetErrorCode() != 0)
    throw OutputError("cannot write '" + path + "': " + vtk_error_text(writer->GetErrorCode()) +
                      "; check free disk space and permissions");
  file.commit();
}

vtkSmartPointer<vtkPolyData> to_vtk_polylines(const VtkPolylines& lines) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(to_vtk_points(lines.x, lines.y));
  vtkNew<vtkCellArray> cells;
  for (const std::vector<int>& line : lines.polylines) {
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (int id : line) cells->InsertCellPoint(id);
  }
  pd->SetLines(cells);
  for (const VtkArray& a : lines.point_arrays) pd->GetPointData()->AddArray(to_vtk_array(a));
  for (const VtkArray& a : lines.cell_arrays) pd->GetCellData()->AddArray(to_vtk_array(a));
  add_field_data(lines.field, *pd->GetFieldData());
  return pd;
}

}  // namespace

void write_vtu(const VtkGrid& grid, const std::string& path) {
  grid.validate();
  const auto ug = to_vtk_grid(grid);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(ug);
  write_xml(writer.Get(), path);
}

void write_vtp(const VtkPolylines& lines, const std::string& path) {
  lines.validate();
  const auto pd = to_vtk_polylines(lines);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(pd);
  write_xml(writer.Get(), path);
}

}  // namespace rockfdem::coupling
