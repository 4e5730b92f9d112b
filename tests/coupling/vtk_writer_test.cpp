// write_vtu: what ParaView reads back is exactly what the record held, the
// file is compressed appended binary, and writes are atomic.
#include "rockfdem/coupling/vtk_writer.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "temp_dir.hpp"

namespace rockfdem::coupling {
namespace {

using testing::TempDir;

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Values whose every bit matters: thirds, a subnormal, -0, huge and tiny.
double awkward(int i) {
  const double pool[] = {1.0 / 3.0, -2.0 / 7.0, 4.9e-324,           -0.0,   1.2e308, -1.82e7,
                         1e-300,    0.1,        11.4e6 + 1.0 / 9.0, -3.0e-9};
  return pool[i % 10] * (1.0 + i * 1e-13);
}

std::vector<double> awkward_values(std::size_t n, int seed) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = awkward(static_cast<int>(i) + seed);
  return v;
}

// Two triangles of a unit square plus a third, and two crack lines.
VtkGrid sample_grid() {
  VtkGrid g;
  g.x = {0.0, 1.0, 1.0, 0.0, 1.0 / 3.0};
  g.y = {0.0, 0.0, 1.0, 1.0, 2.0 + 1.0 / 7.0};
  g.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}};
  g.lines = {{0, 2}, {2, 3}};
  g.point_arrays.push_back(vector_array("displacement", 2, awkward_values(10, 1)));
  g.point_arrays.push_back(vector_array("velocity", 3, awkward_values(15, 2)));
  g.point_arrays.push_back(
      scalar_array("node_id", std::vector<std::int32_t>{7, -1, 0, 2147483647, -2147483647 - 1}));
  g.cell_arrays.push_back(triangle_cell_array(g, tensor_array("stress", 3, awkward_values(9, 3))));
  g.cell_arrays.push_back(
      triangle_cell_array(g, tensor_array("stress_3d", 4, awkward_values(12, 4))));
  g.cell_arrays.push_back(
      triangle_cell_array(g, scalar_array("zone", std::vector<std::int32_t>{1, 2, 3})));
  g.cell_arrays.push_back(
      line_cell_array(g, scalar_array("damage", std::vector<double>{0.25, 1.0})));
  g.cell_arrays.push_back(
      line_cell_array(g, scalar_array("mode", std::vector<std::int32_t>{1, 3})));
  g.cell_arrays.push_back(scalar_array("everywhere", awkward_values(5, 5)));
  return g;
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The tuple the file must hold for tuple t of `a`, derived from the documented
// convention (vtk_grid.hpp), independently of the writer's code.
std::vector<double> expected_tuple(const VtkArray& a, std::size_t t) {
  std::vector<double> in(a.n_components);
  for (int c = 0; c < a.n_components; ++c) {
    const std::size_t k = t * a.n_components + c;
    in[c] = a.is_int() ? std::get<std::vector<std::int32_t>>(a.values)[k]
                       : std::get<std::vector<double>>(a.values)[k];
  }
  if (a.kind == VtkKind::scalar) return in;
  // A tuple of NaN is padding (the array does not apply to the cell): all NaN.
  const bool padding = std::all_of(in.begin(), in.end(), [](double v) { return std::isnan(v); });
  const double zero = padding ? std::nan("") : 0.0;
  if (a.kind == VtkKind::vector) return {in[0], in[1], a.n_components == 3 ? in[2] : zero};
  const double xx = in[0], yy = in[1];
  const double zz = a.n_components == 4 ? in[2] : zero, xy = a.n_components == 4 ? in[3] : in[2];
  return {xx, xy, zero, xy, yy, zero, zero, zero, zz};
}

void expect_array_equal(const VtkArray& a, vtkDataArray* got, std::size_t n_tuples) {
  ASSERT_NE(got, nullptr) << a.name;
  EXPECT_EQ(got->GetNumberOfTuples(), static_cast<vtkIdType>(n_tuples)) << a.name;
  EXPECT_EQ(a.is_int(), vtkIntArray::SafeDownCast(got) != nullptr) << a.name;
  EXPECT_EQ(!a.is_int(), vtkDoubleArray::SafeDownCast(got) != nullptr) << a.name;
  for (std::size_t t = 0; t < n_tuples; ++t) {
    const std::vector<double> want = expected_tuple(a, t);
    ASSERT_EQ(got->GetNumberOfComponents(), static_cast<int>(want.size())) << a.name;
    for (std::size_t c = 0; c < want.size(); ++c) {
      const double v = got->GetComponent(static_cast<vtkIdType>(t), static_cast<int>(c));
      const bool same = std::isnan(want[c]) ? std::isnan(v) : bits(v) == bits(want[c]);
      EXPECT_TRUE(same) << a.name << " tuple " << t << " component " << c << ": " << v
                        << " != " << want[c];
    }
  }
}

TEST(VtkWriter, round_trip_is_bit_exact_for_points_cells_and_arrays) {
  const TempDir dir;
  const VtkGrid g = sample_grid();
  write_vtu(g, dir.file("grid.vtu"));
  const auto ug = read_vtu(dir.file("grid.vtu"));

  ASSERT_EQ(ug->GetNumberOfPoints(), 5);
  for (vtkIdType i = 0; i < 5; ++i) {
    double p[3];
    ug->GetPoint(i, p);
    EXPECT_EQ(bits(p[0]), bits(g.x[i]));
    EXPECT_EQ(bits(p[1]), bits(g.y[i]));
    EXPECT_EQ(bits(p[2]), bits(0.0));
  }
  ASSERT_EQ(ug->GetNumberOfCells(), 5);
  for (vtkIdType c = 0; c < 5; ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    ug->GetCellPoints(c, n, ids);
    const bool triangle = c < 3;
    EXPECT_EQ(ug->GetCellType(c), triangle ? VTK_TRIANGLE : VTK_LINE);
    ASSERT_EQ(n, triangle ? 3 : 2);
    for (vtkIdType k = 0; k < n; ++k) {
      EXPECT_EQ(ids[k], triangle ? g.triangles[c][k] : g.lines[c - 3][k]);
    }
  }
  for (const VtkArray& a : g.point_arrays) {
    expect_array_equal(a, ug->GetPointData()->GetArray(a.name.c_str()), 5);
  }
  for (const VtkArray& a : g.cell_arrays) {
    expect_array_equal(a, ug->GetCellData()->GetArray(a.name.c_str()), 5);
  }
}

// Field data (stage, step, units) comes back as one value per name.
TEST(VtkWriter, field_data_round_trips_as_text_and_numbers) {
  const TempDir dir;
  VtkGrid g = sample_grid();
  g.field.text = {{"stage", "remove_core"}, {"units", "stress: Pa"}};
  g.field.numbers = {{"step", 12345.0}, {"time_s", 1.0 / 3.0}};
  write_vtu(g, dir.file("grid.vtu"));
  const auto ug = read_vtu(dir.file("grid.vtu"));
  vtkFieldData* f = ug->GetFieldData();
  ASSERT_NE(f, nullptr);
  for (const auto& [name, value] : g.field.text) {
    auto* a = vtkStringArray::SafeDownCast(f->GetAbstractArray(name.c_str()));
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->GetValue(0), value);
  }
  for (const auto& [name, value] : g.field.numbers) {
    vtkDataArray* a = f->GetArray(name.c_str());
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(bits(a->GetTuple1(0)), bits(value));
  }
  g.field.numbers.push_back({"stage", 1.0});
  EXPECT_THROW(g.validate(), std::invalid_argument);
}

// Polylines (.vtp): points, each polyline's ids in order as one
// VTK_POLY_LINE (VTK_LINE for 2 points), point and per-polyline arrays, all bit-exact; a polyline
// of one point is refused before anything is written.
TEST(VtkWriter, polylines_round_trip_bit_exact) {
  const TempDir dir;
  VtkPolylines l;
  l.x = awkward_values(5, 7);
  l.y = awkward_values(5, 8);
  l.polylines = {{0, 1, 2}, {4, 3}};
  l.point_arrays.push_back(scalar_array("axial_force_kN", awkward_values(5, 9)));
  l.point_arrays.push_back(scalar_array("state", std::vector<std::int32_t>{0, 1, 2, 0, 1}));
  l.cell_arrays.push_back(scalar_array("bolt", std::vector<std::int32_t>{0, 1}));
  write_vtp(l, dir.file("bolts.vtp"));
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(dir.file("bolts.vtp").c_str());
  reader->Update();
  vtkPolyData* pd = reader->GetOutput();
  ASSERT_EQ(pd->GetNumberOfPoints(), 5);
  for (vtkIdType i = 0; i < 5; ++i) {
    double p[3];
    pd->GetPoint(i, p);
    EXPECT_EQ(bits(p[0]), bits(l.x[i]));
    EXPECT_EQ(bits(p[1]), bits(l.y[i]));
  }
  ASSERT_EQ(pd->GetNumberOfCells(), 2);
  for (vtkIdType c = 0; c < 2; ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    pd->GetCellPoints(c, n, ids);
    EXPECT_EQ(pd->GetCellType(c), n > 2 ? VTK_POLY_LINE : VTK_LINE);  // VTK reads 2 as a line
    ASSERT_EQ(std::size_t(n), l.polylines[c].size());
    for (vtkIdType k = 0; k < n; ++k) EXPECT_EQ(ids[k], l.polylines[c][k]);
  }
  for (const VtkArray& a : l.point_arrays)
    expect_array_equal(a, pd->GetPointData()->GetArray(a.name.c_str()), 5);
  expect_array_equal(l.cell_arrays[0], pd->GetCellData()->GetArray("bolt"), 2);
  l.polylines.push_back({1});
  EXPECT_THROW(write_vtp(l, dir.file("one.vtp")), std::invalid_argument);
  EXPECT_FALSE(std::ifstream(dir.file("one.vtp")).good());
}

TEST(VtkWriter, one_kind_arrays_are_padded_with_nan_or_minus_one) {
  const VtkGrid g = sample_grid();
  const auto& damage = std::get<std::vector<double>>(g.find_cell_array("damage")->values);
  ASSERT_EQ(damage.size(), 5u);
  for (int t = 0; t < 3; ++t) EXPECT_TRUE(std::isnan(damage[t]));
  EXPECT_EQ(damage[3], 0.25);
  const auto& zone = std::get<std::vector<std::int32_t>>(g.find_cell_array("zone")->values);
  EXPECT_EQ(zone, (std::vector<std::int32_t>{1, 2, 3, -1, -1}));
}

// A triangle-only tensor or vector on a line cell (a crack element) is NaN
// in all its components in the file, the z ones the writer adds included,
// so that no filter reads a zero stress on a crack.
TEST(VtkWriter, arrays_of_one_cell_kind_are_all_nan_on_the_other_kind_in_the_file) {
  const TempDir dir;
  VtkGrid g = sample_grid();
  g.cell_arrays.push_back(
      triangle_cell_array(g, vector_array("principal", 2, awkward_values(6, 6))));
  write_vtu(g, dir.file("grid.vtu"));
  const auto ug = read_vtu(dir.file("grid.vtu"));
  for (const char* name : {"stress", "stress_3d", "principal"}) {
    vtkDataArray* a = ug->GetCellData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    for (vtkIdType line = 3; line < 5; ++line)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        EXPECT_TRUE(std::isnan(a->GetComponent(line, c)))
            << name << " line cell " << line << " component " << c;
    // Triangles keep their zeros out of the plane.
    EXPECT_EQ(a->GetComponent(0, 2), 0.0) << name;
  }
}

TEST(VtkWriter, file_is_zlib_compressed_appended_raw_binary) {
  const TempDir dir;
  write_vtu(sample_grid(), dir.file("grid.vtu"));
  const std::string text = file_text(dir.file("grid.vtu"));
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_NE(text.find("format=\"appended\""), std::string::npos);
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(text.find("format=\"binary\""), std::string::npos);
}

TEST(VtkWriter, write_into_missing_directory_throws_naming_path_and_leaves_nothing) {
  const TempDir dir;
  const std::string path = dir.file("missing/grid.vtu");
  try {
    write_vtu(sample_grid(), path);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtkWriter, write_failing_at_the_rename_throws_and_removes_its_temp_file) {
  const TempDir dir;
  // A directory where the file should go: the temporary file is created and
  // written, then the rename onto the target fails (EISDIR).
  const std::string path = dir.file("grid.vtu");
  std::filesystem::create_directory(path);
  try {
    write_vtu(sample_grid(), path);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"grid.vtu"}));
}

ino_t inode_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return st.st_ino;
}

TEST(VtkWriter, existing_file_is_replaced_by_rename_leaving_no_temp_file) {
  const TempDir dir;
  const std::string path = dir.file("grid.vtu");
  VtkGrid g = sample_grid();
  write_vtu(g, path);
  const ino_t before = inode_of(path);
  g.x[4] = 42.0;
  write_vtu(g, path);
  // A new inode: the old file was swapped out whole, never rewritten in place
  // (a reader holding it open keeps a complete old version).
  EXPECT_NE(inode_of(path), before);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"grid.vtu"}));
  EXPECT_EQ(read_vtu(path)->GetPoint(4)[0], 42.0);
}

TEST(VtkWriter, empty_grid_is_written) {
  const TempDir dir;
  write_vtu(VtkGrid{}, dir.file("empty.vtu"));
  EXPECT_EQ(read_vtu(dir.file("empty.vtu"))->GetNumberOfCells(), 0);
}

}  // namespace
}  // namespace rockfdem::coupling
