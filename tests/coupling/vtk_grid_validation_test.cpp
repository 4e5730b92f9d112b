// VtkGrid::validate and write_vtu refuse inconsistent records, naming the
// array (or cell) at fault, and write nothing.
#include <gtest/gtest.h>

#include <cstdint>

#include "rockfdem/coupling/vtk_writer.hpp"
#include "temp_dir.hpp"

namespace rockfdem::coupling {
namespace {

using testing::TempDir;

VtkGrid two_triangles_one_line() {
  VtkGrid g;
  g.x = {0, 1, 1, 0};
  g.y = {0, 0, 1, 1};
  g.triangles = {{0, 1, 2}, {0, 2, 3}};
  g.lines = {{0, 2}};
  return g;
}

// Expects validate() and write_vtu() to throw std::invalid_argument whose
// message contains `needle`, and no file to appear.
void expect_refused(const VtkGrid& g, const std::string& needle) {
  try {
    g.validate();
    ADD_FAILURE() << "validate() accepted a grid; expected a message with '" << needle << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
  const TempDir dir;
  EXPECT_THROW(write_vtu(g, dir.file("g.vtu")), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtkGridValidation, consistent_grid_passes) {
  VtkGrid g = two_triangles_one_line();
  g.point_arrays.push_back(vector_array("displacement", 2, std::vector<double>(8, 0.0)));
  g.cell_arrays.push_back(scalar_array("material", std::vector<std::int32_t>{1, 1, -1}));
  EXPECT_NO_THROW(g.validate());
}

TEST(VtkGridValidation, point_array_of_wrong_size_is_named) {
  VtkGrid g = two_triangles_one_line();
  g.point_arrays.push_back(vector_array("displacement", 2, std::vector<double>(7, 0.0)));
  expect_refused(g, "'displacement'");
}

TEST(VtkGridValidation, cell_array_sized_for_triangles_only_is_named) {
  VtkGrid g = two_triangles_one_line();
  g.cell_arrays.push_back(tensor_array("stress", 3, std::vector<double>(6, 0.0)));
  expect_refused(g, "'stress'");
}

TEST(VtkGridValidation, int_cell_array_of_wrong_size_is_named) {
  VtkGrid g = two_triangles_one_line();
  g.cell_arrays.push_back(scalar_array("state", std::vector<std::int32_t>{0, 1}));
  expect_refused(g, "'state'");
}

TEST(VtkGridValidation, component_count_must_fit_kind) {
  VtkGrid g = two_triangles_one_line();
  g.cell_arrays.push_back(tensor_array("stress", 2, std::vector<double>(6, 0.0)));
  expect_refused(g, "'stress'");
}

TEST(VtkGridValidation, duplicate_array_name_is_named) {
  VtkGrid g = two_triangles_one_line();
  g.cell_arrays.push_back(scalar_array("damage", std::vector<double>(3, 0.0)));
  g.cell_arrays.push_back(scalar_array("damage", std::vector<double>(3, 0.0)));
  expect_refused(g, "'damage'");
}

TEST(VtkGridValidation, point_id_out_of_range_names_the_cell) {
  VtkGrid g = two_triangles_one_line();
  g.lines[0][1] = 4;
  expect_refused(g, "line 0");
}

TEST(VtkGridValidation, x_and_y_must_agree) {
  VtkGrid g = two_triangles_one_line();
  g.y.pop_back();
  expect_refused(g, "y coordinates");
}

TEST(VtkGridValidation, padding_helper_checks_its_input_size) {
  const VtkGrid g = two_triangles_one_line();
  EXPECT_THROW(triangle_cell_array(g, scalar_array("zone", std::vector<std::int32_t>{1})),
               std::invalid_argument);
  const VtkArray damage = line_cell_array(g, scalar_array("damage", std::vector<double>{0.5}));
  EXPECT_EQ(damage.n_tuples(), 3u);
}

}  // namespace
}  // namespace rockfdem::coupling
