// The VtkGrid record: factories, padding to all cells, and validation.
// No VTK here: stages that only fill a grid do not compile VTK headers.
#include "rockfdem/coupling/vtk_grid.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace rockfdem::coupling {
namespace {

std::invalid_argument bad_array(const std::string& where, const VtkArray& a,
                                const std::string& what) {
  return std::invalid_argument(where + " array '" + a.name + "': " + what);
}

std::size_t n_values(const VtkArray& a) {
  return std::visit([](const auto& v) { return v.size(); }, a.values);
}

bool components_fit_kind(const VtkArray& a) {
  switch (a.kind) {
    case VtkKind::scalar:
      return a.n_components == 1;
    case VtkKind::vector:
      return a.n_components == 2 || a.n_components == 3;
    case VtkKind::symmetric_tensor:
      return a.n_components == 3 || a.n_components == 4;
  }
  return false;
}

void validate_array(const std::string& where, const VtkArray& a, std::size_t n_tuples) {
  if (a.name.empty()) throw std::invalid_argument(where + " array with an empty name");
  if (!components_fit_kind(a)) {
    throw bad_array(where, a,
                    std::to_string(a.n_components) +
                        " components do not fit its kind (scalar 1, vector 2|3, "
                        "symmetric tensor 3|4)");
  }
  if (a.kind == VtkKind::symmetric_tensor && a.is_int()) {
    throw bad_array(where, a, "a tensor must hold doubles");
  }
  const std::size_t expected = n_tuples * static_cast<std::size_t>(a.n_components);
  if (n_values(a) != expected) {
    throw bad_array(where, a,
                    "has " + std::to_string(n_values(a)) + " values, expected " +
                        std::to_string(expected) + " (" + std::to_string(n_tuples) + " tuples x " +
                        std::to_string(a.n_components) + " components)");
  }
}

void validate_arrays(const std::string& where, const std::vector<VtkArray>& arrays,
                     std::size_t n_tuples) {
  std::set<std::string> names;
  for (const VtkArray& a : arrays) {
    validate_array(where, a, n_tuples);
    if (!names.insert(a.name).second) throw bad_array(where, a, "name used twice");
  }
}

template <std::size_t N>
void validate_cells(const char* kind, const std::vector<std::array<int, N>>& cells,
                    std::size_t n_points) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (int id : cells[c]) {
      if (id < 0 || static_cast<std::size_t>(id) >= n_points) {
        throw std::invalid_argument(std::string(kind) + " " + std::to_string(c) + ": point id " +
                                    std::to_string(id) + " outside [0, " +
                                    std::to_string(n_points) + ")");
      }
    }
  }
}

// Copies `part` (n_part tuples) into a cell array of n_cells tuples starting
// at tuple `first`; the rest holds NaN (double) or -1 (int32).
VtkArray pad_to_cells(const VtkGrid& grid, VtkArray part, std::size_t n_part, std::size_t first,
                      const char* kind) {
  validate_array(std::string("per-") + kind, part, n_part);
  const std::size_t nc = static_cast<std::size_t>(part.n_components);
  std::visit(
      [&](auto& v) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        const T fill = std::is_same_v<T, double>
                           ? static_cast<T>(std::numeric_limits<double>::quiet_NaN())
                           : static_cast<T>(-1);
        std::vector<T> all(grid.n_cells() * nc, fill);
        std::copy(v.begin(), v.end(), all.begin() + static_cast<std::ptrdiff_t>(first * nc));
        v = std::move(all);
      },
      part.values);
  return part;
}

}  // namespace

std::size_t VtkArray::n_tuples() const {
  return n_components > 0 ? n_values(*this) / static_cast<std::size_t>(n_components) : 0;
}

VtkArray scalar_array(std::string name, std::vector<double> values) {
  return {std::move(name), VtkKind::scalar, 1, std::move(values)};
}

VtkArray scalar_array(std::string name, std::vector<std::int32_t> values) {
  return {std::move(name), VtkKind::scalar, 1, std::move(values)};
}

VtkArray vector_array(std::string name, int n_components, std::vector<double> values) {
  return {std::move(name), VtkKind::vector, n_components, std::move(values)};
}

VtkArray tensor_array(std::string name, int n_components, std::vector<double> values) {
  return {std::move(name), VtkKind::symmetric_tensor, n_components, std::move(values)};
}

namespace {

void validate_field(const VtkFieldData& field) {
  std::set<std::string> names;
  auto check_name = [&](const std::string& name) {
    if (name.empty() || !names.insert(name).second)
      throw std::invalid_argument("field data: name '" + name + "' is empty or used twice");
  };
  for (const auto& [name, value] : field.text) check_name(name);
  for (const auto& [name, value] : field.numbers) check_name(name);
}

}  // namespace

const VtkArray* VtkGrid::find_cell_array(const std::string& name) const {
  for (const VtkArray& a : cell_arrays) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

void VtkGrid::validate() const {
  if (x.size() != y.size()) {
    throw std::invalid_argument("grid points: " + std::to_string(x.size()) + " x but " +
                                std::to_string(y.size()) + " y coordinates");
  }
  validate_cells("triangle", triangles, n_points());
  validate_cells("line", lines, n_points());
  validate_arrays("point", point_arrays, n_points());
  validate_arrays("cell", cell_arrays, n_cells());
  validate_field(field);
}

void VtkPolylines::validate() const {
  if (x.size() != y.size()) {
    throw std::invalid_argument("polyline points: " + std::to_string(x.size()) + " x but " +
                                std::to_string(y.size()) + " y coordinates");
  }
  for (std::size_t c = 0; c < polylines.size(); ++c) {
    if (polylines[c].size() < 2)
      throw std::invalid_argument("polyline " + std::to_string(c) + ": " +
                                  std::to_string(polylines[c].size()) + " points, at least 2");
    for (int id : polylines[c])
      if (id < 0 || static_cast<std::size_t>(id) >= n_points())
        throw std::invalid_argument("polyline " + std::to_string(c) + ": point id " +
                                    std::to_string(id) + " outside [0, " +
                                    std::to_string(n_points()) + ")");
  }
  validate_arrays("point", point_arrays, n_points());
  validate_arrays("cell", cell_arrays, polylines.size());
  validate_field(field);
}

VtkArray triangle_cell_array(const VtkGrid& grid, VtkArray per_triangle) {
  return pad_to_cells(grid, std::move(per_triangle), grid.n_triangles(), 0, "triangle");
}

VtkArray line_cell_array(const VtkGrid& grid, VtkArray per_line) {
  return pad_to_cells(grid, std::move(per_line), grid.n_lines(), grid.n_triangles(), "line");
}

}  // namespace rockfdem::coupling
