// Bad input: one InputError, whose message names the key to change.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "fixtures.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::insitu::test {
namespace {

void expect_input_error(const mesh::Mesh& m, const InsituSpec& spec, const std::string& key) {
  try {
    solve_insitu(m, spec);
    ADD_FAILURE() << "no InputError; expected one naming '" << key << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

class BadInput : public ::testing::Test {
 protected:
  const mesh::Mesh m = polar_box_mesh({1.0, 4.0, 16, true, 0.2});
  InsituSpec spec = seed_spec();
};

TEST_F(BadInput, zero_or_tensile_far_field) {
  spec.far_field.sH = 0;
  expect_input_error(m, spec, "far_field.sH");
  spec = seed_spec();
  spec.far_field.sV = -5e6;
  expect_input_error(m, spec, "far_field.sV");
  spec = seed_spec();
  spec.far_field.sZ = -1.0;
  expect_input_error(m, spec, "far_field.sZ");
}

TEST_F(BadInput, gravity_that_turns_the_top_of_the_model_tensile) {
  spec.gravity.unit_weight = 27e3;
  spec.gravity.reference_y = -1000;  // far below the model: the top is "above ground"
  expect_input_error(m, spec, "compression is required");
}

TEST_F(BadInput, alpha_outside_0_1_or_not_decreasing) {
  spec.alphas = {1.2, 0.5};
  expect_input_error(m, spec, "alphas[0]");
  spec.alphas = {1.0, 0.5, 0.7};
  expect_input_error(m, spec, "strictly decreasing");
  spec.alphas = {1.0, 0.5, 0.5};
  expect_input_error(m, spec, "strictly decreasing");
  spec.alphas = {};
  expect_input_error(m, spec, "alphas is empty");
}

TEST_F(BadInput, material_missing_for_a_zone_in_the_mesh) {
  spec.materials.core.reset();
  expect_input_error(m, spec, "materials.core");
  spec = seed_spec();
  spec.materials.rock.reset();
  expect_input_error(m, spec, "materials.rock");
  spec = seed_spec();
  spec.lining.active = true;
  spec.materials.lining.reset();
  expect_input_error(m, spec, "materials.lining");
  spec = seed_spec();
  spec.materials.rock->nu = 0.5;
  expect_input_error(m, spec, "materials.rock.nu");
  spec = seed_spec();
  spec.materials.core->E = 0;
  expect_input_error(m, spec, "materials.core.E");
}

TEST_F(BadInput, everything_softened_away_is_singular) {
  mesh::Mesh core_only = m;
  for (auto& z : core_only.zone) z = mesh::kCore;
  spec.alphas = {1.0, 0.0};
  expect_input_error(core_only, spec, "singular");
}

TEST_F(BadInput, a_rock_island_left_floating_by_the_excavation_is_singular) {
  mesh::Mesh island = m;
  island.zone.back() = mesh::kRock;  // the last fan triangle at the centre
  spec.alphas = {1.0, 0.0};
  expect_input_error(island, spec, "disconnected");
}

TEST_F(BadInput, clockwise_triangle_and_kirsch_without_radius) {
  mesh::Mesh flipped = m;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  expect_input_error(flipped, spec, "counter-clockwise");
  spec.loading = BoundaryLoading::kKirschExact;
  expect_input_error(m, spec, "kirsch_radius");
}

TEST_F(BadInput, lining_active_on_a_mesh_without_lining) {
  const mesh::Mesh unlined = polar_box_mesh({1.0, 4.0, 16, true, 0.0});
  spec.lining.active = true;
  expect_input_error(unlined, spec, "lining_thickness");
}

}  // namespace
}  // namespace rockfdem::insitu::test
