// A plain record of what goes into a ParaView file: 2-D points, triangle and
// line cells, and named arrays on points or cells. Stages fill it from their
// own data (mesh, implicit field, FDEM state); only the writers in
// vtk_writer.cpp / plot_mesh.cpp know VTK.
//
// Conventions (see docs/output-formats.md):
// - points are (x, y) with z = 0 in the file;
// - cells are all triangles first, then all lines (crack elements drawn as
//   line cells); cell i < n_triangles() is triangle i, cell n_triangles() + j
//   is line j;
// - a cell array covers every cell. An array meaningful for one kind only
//   holds NaN (double) or -1 (int32) on the other kind: use
//   triangle_cell_array() / line_cell_array() to pad it. A double tuple of
//   all NaN stays all NaN in the file (the writer's z components too);
// - vectors of 2 components are written as 3 (z = 0) so ParaView can warp
//   and glyph with them; symmetric tensors of 3 (xx, yy, xy) or 4
//   (xx, yy, zz, xy) components are written as full 9-component tensors
//   (row-major xx xy xz yx yy yz zx zy zz) which ParaView's tensor filters read;
// - field data (one value per file: stage, step, units, code tables) is
//   text or a number, shown by ParaView's Information panel and spreadsheet.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rockfdem::coupling {

enum class VtkKind { scalar, vector, symmetric_tensor };

/// One named array; values are tuple after tuple (n_components per tuple).
struct VtkArray {
  std::string name;
  VtkKind kind = VtkKind::scalar;
  int n_components = 1;  ///< scalar: 1; vector: 2 or 3; symmetric_tensor: 3 or 4 (see above)
  std::variant<std::vector<double>, std::vector<std::int32_t>> values;

  std::size_t n_tuples() const;
  bool is_int() const { return std::holds_alternative<std::vector<std::int32_t>>(values); }
};

VtkArray scalar_array(std::string name, std::vector<double> values);
VtkArray scalar_array(std::string name, std::vector<std::int32_t> values);
/// n_components = 2 (x, y) or 3 (x, y, z).
VtkArray vector_array(std::string name, int n_components, std::vector<double> values);
/// n_components = 3 (xx, yy, xy) or 4 (xx, yy, zz, xy).
VtkArray tensor_array(std::string name, int n_components, std::vector<double> values);

/// Values that describe the whole file rather than a point or cell.
struct VtkFieldData {
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
};

struct VtkGrid {
  std::vector<double> x, y;                   ///< point coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< point ids
  std::vector<std::array<int, 2>> lines;      ///< point ids (crack elements)
  std::vector<VtkArray> point_arrays;         ///< n_points() tuples each
  std::vector<VtkArray> cell_arrays;          ///< n_cells() tuples each: triangles, then lines
  VtkFieldData field;                         ///< one value each, for the whole file

  std::size_t n_points() const { return x.size(); }
  std::size_t n_triangles() const { return triangles.size(); }
  std::size_t n_lines() const { return lines.size(); }
  std::size_t n_cells() const { return triangles.size() + lines.size(); }

  /// Looks up a cell array by name; nullptr when absent.
  const VtkArray* find_cell_array(const std::string& name) const;

  /// Checks that x and y agree, point ids are in range, array names are
  /// non-empty and unique per location, component counts fit the kind and
  /// every array has n_points() (n_cells()) tuples.
  /// @throws std::invalid_argument naming the offending array or cell.
  void validate() const;
};

/// Polylines for a .vtp file (bolts as lines through their stations):
/// 2-D points (z = 0 in the file), each polyline its point ids in order;
/// point arrays hold one tuple per point, cell arrays one per polyline.
struct VtkPolylines {
  std::vector<double> x, y;                 ///< point coordinates [m]
  std::vector<std::vector<int>> polylines;  ///< point ids, at least 2 each
  std::vector<VtkArray> point_arrays;
  std::vector<VtkArray> cell_arrays;
  VtkFieldData field;  ///< one value each, for the whole file

  std::size_t n_points() const { return x.size(); }
  /// As VtkGrid::validate; a polyline of fewer than 2 points is refused too.
  void validate() const;
};

/// Pads an array given per triangle to a cell array (lines get NaN / -1).
VtkArray triangle_cell_array(const VtkGrid& grid, VtkArray per_triangle);
/// Pads an array given per line to a cell array (triangles get NaN / -1).
VtkArray line_cell_array(const VtkGrid& grid, VtkArray per_line);

}  // namespace rockfdem::coupling
