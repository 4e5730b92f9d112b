// The exact outlines against closed forms: areas, perimeters, distances and
// inside tests for each tunnel shape and for the lining's inward offset.
#include "rockfdem/mesh/outline.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/constants.hpp"

namespace rockfdem::mesh {
namespace {

TunnelSpec circular(double r) {
  TunnelSpec t;
  t.shape = TunnelShape::kCircular;
  t.radius = r;
  return t;
}

TunnelSpec shaped(TunnelShape shape, double span, double height, double rise = 0) {
  TunnelSpec t;
  t.shape = shape;
  t.span = span, t.height = height, t.rise = rise;
  return t;
}

TEST(TunnelOutline, circular_area_and_perimeter_are_pi_r2_and_2_pi_r) {
  const Outline o = tunnel_outline(circular(2.5));
  EXPECT_NEAR(outline_area(o), kPi * 6.25, 1e-12);
  EXPECT_NEAR(outline_perimeter(o), 5 * kPi, 1e-12);
}

// Seed tunnel: rectangle of span s and wall height h - s/2 plus a half disc.
TEST(TunnelOutline, horseshoe_area_is_walls_plus_half_disc) {
  const double s = 11.3, h = 8.8;
  const TunnelSpec t = shaped(TunnelShape::kHorseshoe, s, h);
  EXPECT_NEAR(opening_area(t), s * (h - s / 2) + kPi * s * s / 8, 1e-10);
  EXPECT_NEAR(outline_perimeter(tunnel_outline(t)), s + 2 * (h - s / 2) + kPi * s / 2, 1e-10);
}

// Arch of rise f over span s: radius R = (s^2/4 + f^2) / 2f, segment area
// R^2 (theta - sin theta) / 2 with theta = 2 asin(s / 2R).
TEST(TunnelOutline, arched_area_is_walls_plus_circular_segment) {
  const double s = 8, h = 6, f = 1.5;
  const double r = (s * s / 4 + f * f) / (2 * f), theta = 2 * std::asin(s / (2 * r));
  const TunnelSpec t = shaped(TunnelShape::kArched, s, h, f);
  EXPECT_NEAR(opening_area(t), s * (h - f) + r * r * (theta - std::sin(theta)) / 2, 1e-10);
}

// A curved invert of rise g adds its circular segment below the walls'
// feet, which rise by g: walls s (h - s/2 - g), half disc, invert segment.
TEST(TunnelOutline, horseshoe_with_invert_adds_the_inverts_segment) {
  const double s = 11.3, h = 8.8, g = 1.2;
  TunnelSpec t = shaped(TunnelShape::kHorseshoe, s, h);
  t.invert_rise = g;
  const double r = (s * s / 4 + g * g) / (2 * g), theta = 2 * std::asin(s / (2 * r));
  EXPECT_NEAR(opening_area(t),
              s * (h - s / 2 - g) + kPi * s * s / 8 + r * r * (theta - std::sin(theta)) / 2, 1e-10);
  EXPECT_NEAR(outline_perimeter(tunnel_outline(t)), 2 * (h - s / 2 - g) + kPi * s / 2 + r * theta,
              1e-10);
  // The lowest point sits at -h/2 on the axis, inset or not.
  EXPECT_NEAR(distance_to_outline(tunnel_outline(t), 0, -h / 2), 0, 1e-12);
  EXPECT_NEAR(distance_to_outline(tunnel_outline(t, 0.2), 0, -h / 2 + 0.2), 0, 1e-12);
  EXPECT_TRUE(inside_outline(tunnel_outline(t), 0, -h / 2 + 0.01));
  EXPECT_FALSE(inside_outline(tunnel_outline(t), s / 2 - 0.01, -h / 2 + 0.01));
}

// The inset outline is the inward offset: every joint of its pieces, and
// every piece's midpoint, lies at the inset's distance from the outline.
TEST(TunnelOutline, invert_inset_lies_at_the_inset_distance) {
  const double s = 11.3, h = 8.8, d = 0.2;
  TunnelSpec t = shaped(TunnelShape::kHorseshoe, s, h);
  t.invert_rise = 1.2;
  const Outline o = tunnel_outline(t), in = tunnel_outline(t, d);
  ASSERT_EQ(in.pieces.size(), 4u);
  for (const OutlinePiece& p : in.pieces) {
    const double a = (p.a0 + p.a1) / 2;
    const double mx = p.is_arc ? p.cx + p.radius * std::cos(a) : (p.x0 + p.x1) / 2;
    const double my = p.is_arc ? p.cy + p.radius * std::sin(a) : (p.y0 + p.y1) / 2;
    EXPECT_NEAR(distance_to_outline(o, p.x0, p.y0), d, 1e-12);
    EXPECT_NEAR(distance_to_outline(o, mx, my), d, 1e-12);
  }
}

// A floor part of its own thickness: the inner outline's floor (the invert
// arc) lies at the invert thickness from the opening, its walls and arch at
// the lining's; the part's top is the inner walls' feet, on the inset arc.
TEST(TunnelOutline, lining_inner_outline_offsets_the_floor_by_the_invert_thickness) {
  const double s = 11.3, h = 8.8, d = 0.2, f = 0.8;
  TunnelSpec t = shaped(TunnelShape::kHorseshoe, s, h);
  t.invert_rise = 1.2;
  t.lining_thickness = d;
  t.invert_thickness = f;
  const Outline o = tunnel_outline(t), in = lining_inner_outline(t);
  ASSERT_EQ(in.pieces.size(), 4u);
  for (std::size_t i = 0; i < in.pieces.size(); ++i) {
    const OutlinePiece& p = in.pieces[i];
    const double a = (p.a0 + p.a1) / 2;
    const double mx = p.is_arc ? p.cx + p.radius * std::cos(a) : (p.x0 + p.x1) / 2;
    const double my = p.is_arc ? p.cy + p.radius * std::sin(a) : (p.y0 + p.y1) / 2;
    EXPECT_NEAR(distance_to_outline(o, mx, my), i == 0 ? f : d, 1e-12) << i;
  }
  const double ri = (s * s / 4 + 1.2 * 1.2) / 2.4, yi = -h / 2 + ri, w = s / 2 - d;
  EXPECT_NEAR(invert_part_top(t), yi - std::sqrt((ri - f) * (ri - f) - w * w), 1e-12);
  t.invert_thickness = 0;  // the lining's
  EXPECT_NEAR(invert_part_top(t), tunnel_outline(t, d).pieces.front().y0, 1e-12);
  t.invert_rise = 0;  // flat floor
  t.invert_thickness = f;
  EXPECT_NEAR(invert_part_top(t), -h / 2 + f, 1e-12);
  t.invert_rise = 1.2;
  t.invert_thickness = 1.3;  // deeper than the invert
  EXPECT_THROW(lining_inner_outline(t), InputError);
}

TEST(TunnelOutline, rectangular_area_is_span_times_height) {
  EXPECT_NEAR(opening_area(shaped(TunnelShape::kRectangular, 7, 5)), 35, 1e-12);
}

// Inset by t: the horseshoe keeps its arch centre, so its inset is a
// horseshoe of span s - 2t whose walls are shorter by t (floor up by t).
TEST(TunnelOutline, horseshoe_inset_is_offset_horseshoe) {
  const double s = 11.3, h = 8.8, t = 0.2;
  const Outline in = tunnel_outline(shaped(TunnelShape::kHorseshoe, s, h), t);
  const double w = s - 2 * t, walls = h - s / 2 - t;
  EXPECT_NEAR(outline_area(in), w * walls + kPi * w * w / 8, 1e-10);
}

TEST(TunnelOutline, distance_to_circle_is_radial) {
  const Outline o = tunnel_outline(circular(2));
  EXPECT_NEAR(distance_to_outline(o, 3, 4), 3, 1e-12);
  EXPECT_NEAR(distance_to_outline(o, 0.5, 0), 1.5, 1e-12);
}

TEST(TunnelOutline, distance_to_horseshoe_uses_walls_floor_and_arch) {
  const Outline o = tunnel_outline(shaped(TunnelShape::kHorseshoe, 10, 8));
  // Arch centre at (0, -1), radius 5; walls from y = -4 to -1; floor y = -4.
  EXPECT_NEAR(distance_to_outline(o, 0, 6), 2, 1e-12);                  // above the crown
  EXPECT_NEAR(distance_to_outline(o, 7, -2), 2, 1e-12);                 // beside the wall
  EXPECT_NEAR(distance_to_outline(o, 0, -5), 1, 1e-12);                 // below the floor
  EXPECT_NEAR(distance_to_outline(o, 8, -7), std::hypot(3, 3), 1e-12);  // off the corner
}

TEST(TunnelOutline, inside_is_exact_for_every_shape) {
  const Outline c = tunnel_outline(circular(2));
  EXPECT_TRUE(inside_outline(c, 0, 1.99));
  EXPECT_TRUE(inside_outline(c, 0, -1.99));
  EXPECT_FALSE(inside_outline(c, 1.5, 1.5));
  const Outline a = tunnel_outline(shaped(TunnelShape::kArched, 8, 6, 1.5));
  EXPECT_TRUE(inside_outline(a, 0, 2.99));  // just under the crown (y = 3)
  EXPECT_FALSE(inside_outline(a, 0, 3.01));
  EXPECT_FALSE(inside_outline(a, 3.99, 1.6));  // above the spring line at the wall
  EXPECT_TRUE(inside_outline(a, 3.99, 1.4));
}

TEST(TunnelOutline, impossible_shapes_are_input_errors) {
  EXPECT_THROW(tunnel_outline(circular(0)), InputError);
  EXPECT_THROW(tunnel_outline(circular(1), 1.5), InputError);
  EXPECT_THROW(tunnel_outline(shaped(TunnelShape::kArched, 8, 6, 5)), InputError);
  EXPECT_THROW(tunnel_outline(shaped(TunnelShape::kHorseshoe, 10, 4)), InputError);
  TunnelSpec deep = shaped(TunnelShape::kHorseshoe, 10, 8);
  deep.invert_rise = 3.5;  // 5 + 3.5 > 8: no wall left
  EXPECT_THROW(tunnel_outline(deep), InputError);
}

}  // namespace
}  // namespace rockfdem::mesh
