// PNG plots: with a display they render a picture of the asked size that is
// not blank; without one they say why and write nothing. CTest runs this
// binary under `xvfb-run -a` when that exists (tests/coupling/CMakeLists.txt).
#include "rockfdem/plots/plot.hpp"

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstdlib>

#include "plot_ticks.hpp"
#include "temp_dir.hpp"

namespace rockfdem::plots {
namespace {
using coupling::scalar_array;
using coupling::tensor_array;

using coupling::testing::TempDir;

struct Picture {
  int width = 0, height = 0;
  double variance = 0;  ///< of the grey level over all pixels
  int n_black = 0;      ///< pixels with every channel below 40 (cracks, text)
  int n_magenta = 0;    ///< pixels with red and blue above 200, green below 60
  int n_green = 0;      ///< the instruments' dark green: red, blue below 50, green 80-150
  int n_white = 0;      ///< pixels with every channel above 235
};

Picture read_png(const std::string& path) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Picture p{dims[0], dims[1]};
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!pixels) return p;
  const int nc = pixels->GetNumberOfComponents();
  const vtkIdType n = pixels->GetNumberOfTuples();
  double sum = 0, sum2 = 0;
  for (vtkIdType i = 0; i < n; ++i) {
    double grey = 0;
    bool black = true;
    int rgb[3] = {0, 0, 0};
    for (int c = 0; c < std::min(nc, 3); ++c) {
      const int v = pixels->GetValue(i * nc + c);
      grey += v / 3.0;
      black = black && v < 40;
      rgb[c] = v;
    }
    p.n_magenta += rgb[0] > 200 && rgb[1] < 60 && rgb[2] > 200;
    p.n_green += rgb[0] < 50 && rgb[1] >= 80 && rgb[1] <= 150 && rgb[2] < 50;
    p.n_white += rgb[0] > 235 && rgb[1] > 235 && rgb[2] > 235;
    sum += grey;
    sum2 += grey * grey;
    p.n_black += black;
  }
  p.variance = sum2 / n - (sum / n) * (sum / n);
  return p;
}

// A 1 m x 1 m square split into 2 n^2 triangles, coloured by x + 2y, with a
// diagonal crack of n line cells.
VtkGrid cracked_square(int n) {
  VtkGrid g;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      g.x.push_back(double(i) / n);
      g.y.push_back(double(j) / n);
    }
  }
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  std::vector<double> field;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      g.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      field.push_back((i + 0.7) / n + 2.0 * (j + 0.3) / n);
      field.push_back((i + 0.3) / n + 2.0 * (j + 0.7) / n);
    }
  }
  for (int k = 0; k < n; ++k) g.lines.push_back({id(k, k), id(k + 1, k + 1)});
  std::vector<double> stress;
  for (double f : field) stress.insert(stress.end(), {-1e6 * f, -2e6, 1e5 * f});
  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("field", field)));
  g.cell_arrays.push_back(triangle_cell_array(g, tensor_array("stress", 3, stress)));
  return g;
}

// Skips the test when VTK cannot render here, unless the environment demands
// rendering (ROCKFDEM_REQUIRE_RENDERING, set by the xvfb-run CTest test).
#define SKIP_UNLESS_RENDERING()                                        \
  do {                                                                 \
    std::string reason;                                                \
    if (!rendering_available(&reason)) {                               \
      if (std::getenv("ROCKFDEM_REQUIRE_RENDERING")) FAIL() << reason; \
      GTEST_SKIP() << reason;                                          \
    }                                                                  \
  } while (false)

// Restores DISPLAY on scope exit.
class DisplayUnset {
 public:
  DisplayUnset() {
    if (const char* d = std::getenv("DISPLAY")) saved_ = d, had_ = true;
    ::unsetenv("DISPLAY");
  }
  ~DisplayUnset() {
    if (had_) ::setenv("DISPLAY", saved_.c_str(), 1);
  }

 private:
  std::string saved_;
  bool had_ = false;
};

TEST(Plot, without_display_rendering_is_refused_with_a_reason_and_nothing_written) {
  const DisplayUnset no_display;
  std::string why;
  EXPECT_FALSE(rendering_available(&why));
  EXPECT_NE(why.find("DISPLAY"), std::string::npos) << why;
  const TempDir dir;
  why.clear();
  EXPECT_FALSE(
      plot_xy_png("t", "x", "y", {{"s", {0, 1}, {0, 1}}}, dir.file("p.png"), 320, 240, &why));
  EXPECT_FALSE(why.empty());
  why.clear();
  EXPECT_FALSE(
      render_mesh_png(cracked_square(4), "field", 0, dir.file("m.png"), "t", 320, 240, &why));
  EXPECT_FALSE(why.empty());
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Plot, bad_arguments_throw_before_any_rendering) {
  const TempDir dir;
  EXPECT_THROW(plot_xy_png("t", "x", "y", {}, dir.file("p.png")), std::invalid_argument);
  try {
    plot_xy_png("t", "x", "y", {{"convergence", {0, 1, 2}, {0, 1}}}, dir.file("p.png"));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'convergence'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(render_mesh_png(cracked_square(2), "nope", 0, dir.file("m.png"), "t"),
               std::invalid_argument);
  EXPECT_THROW(render_mesh_png(cracked_square(2), "stress", 3, dir.file("m.png"), "t"),
               std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Plot, xy_plot_png_has_the_asked_size_and_is_not_blank) {
  SKIP_UNLESS_RENDERING();
  std::string why;
  const TempDir dir;
  std::vector<PlotSeries> series(2);
  series[0].name = "vault settlement";
  series[1].name = "shoulder convergence";
  for (int i = 0; i <= 50; ++i) {
    const double t = 0.02 * i;
    series[0].x.push_back(t), series[0].y.push_back(226.6 * (1 - std::exp(-4 * t)));
    series[1].x.push_back(t), series[1].y.push_back(207.2 * (1 - std::exp(-3 * t)));
  }
  ASSERT_TRUE(plot_xy_png("Convergence", "time [s]", "displacement [mm]", series,
                          dir.file("convergence.png"), 640, 420, &why))
      << why;
  const Picture p = read_png(dir.file("convergence.png"));
  EXPECT_EQ(p.width, 640);
  EXPECT_EQ(p.height, 420);
  EXPECT_GT(p.variance, 10.0);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"convergence.png"}));
}

// Xvfb resets whenever its last client leaves, and a connection made during
// the reset fails (VTK then aborts or crashes). A run draws several pictures
// in a row, each after a display check: that pattern must hold up.
TEST(Plot, pictures_in_a_row_survive_xvfb_resets) {
  SKIP_UNLESS_RENDERING();
  const TempDir dir;
  for (int i = 0; i < 8; ++i) {
    std::string why;
    ASSERT_TRUE(rendering_available(&why)) << "picture " << i << ": " << why;
    const std::string name = "p" + std::to_string(i) + ".png";
    ASSERT_TRUE(
        plot_xy_png("t", "x", "y", {{"s", {0, 1, 2}, {0, 1, 4}}}, dir.file(name), 200, 150, &why))
        << "picture " << i << ": " << why;
    EXPECT_EQ(read_png(dir.file(name)).width, 200);
  }
}

// Per pixel column, how many pixels differ between two pictures of the same size.
std::vector<int> differing_columns(const std::string& a, const std::string& b) {
  vtkNew<vtkPNGReader> ra, rb;
  ra->SetFileName(a.c_str());
  rb->SetFileName(b.c_str());
  ra->Update();
  rb->Update();
  int dims[3];
  ra->GetOutput()->GetDimensions(dims);
  auto* pa = vtkUnsignedCharArray::SafeDownCast(ra->GetOutput()->GetPointData()->GetScalars());
  auto* pb = vtkUnsignedCharArray::SafeDownCast(rb->GetOutput()->GetPointData()->GetScalars());
  const int nc = pa->GetNumberOfComponents();
  std::vector<int> count(dims[0], 0);
  for (int j = 0; j < dims[1]; ++j)
    for (int i = 0; i < dims[0]; ++i)
      for (int c = 0; c < nc; ++c) {
        const vtkIdType k = (vtkIdType(j) * dims[0] + i) * nc + c;
        if (pa->GetValue(k) != pb->GetValue(k)) {
          ++count[i];
          break;
        }
      }
  return count;
}

// A PNG's pixels: rgb(i, j) of column i, row j (from the bottom, as VTK
// stores them).
class Pixels {
 public:
  explicit Pixels(const std::string& path) {
    reader_->SetFileName(path.c_str());
    reader_->Update();
    int dims[3];
    reader_->GetOutput()->GetDimensions(dims);
    width = dims[0], height = dims[1];
    px_ = vtkUnsignedCharArray::SafeDownCast(reader_->GetOutput()->GetPointData()->GetScalars());
    nc_ = px_->GetNumberOfComponents();
  }
  std::array<int, 3> rgb(int i, int j) const {
    const vtkIdType k = (vtkIdType(j) * width + i) * nc_;
    return {px_->GetValue(k), px_->GetValue(k + 1), px_->GetValue(k + 2)};
  }
  int width = 0, height = 0;

 private:
  vtkNew<vtkPNGReader> reader_;
  vtkUnsignedCharArray* px_ = nullptr;
  int nc_ = 3;
};

// Per pixel column, how many pixels have the colour `rgb` (within 3 per channel).
std::vector<int> columns_of_colour(const std::string& path, std::array<int, 3> rgb) {
  const Pixels png(path);
  std::vector<int> count(png.width, 0);
  for (int j = 0; j < png.height; ++j)
    for (int i = 0; i < png.width; ++i) {
      const auto p = png.rgb(i, j);
      bool match = true;
      for (int c = 0; c < 3; ++c) match = match && std::abs(p[c] - rgb[c]) <= 3;
      count[i] += match;
    }
  return count;
}

// Stage markers are vertical lines at their abscissae: drawn over a plot
// whose x axis spans [0, 1], markers at 0.2, 0.4 and 0.8 change three
// narrow bands of pixel columns over most of the plot's height (the dashed
// line, half its pixels), whose spacings are in the ratio of the abscissae's,
// (0.8 - 0.4) / (0.4 - 0.2) = 2, whatever the axes' layout; a marker
// outside the axis (1.5) draws nothing.
TEST(Plot, stage_markers_are_vertical_lines_at_their_abscissae) {
  SKIP_UNLESS_RENDERING();
  const TempDir dir;
  const std::vector<PlotSeries> series{{"broken", {0.0, 0.5, 1.0}, {0.0, 10.0, 4.0}}};
  std::string why;
  ASSERT_TRUE(plot_xy_png("t", "time [s]", "count", series, dir.file("plain.png"), 800, 500, &why))
      << why;
  ASSERT_TRUE(plot_xy_png("t", "time [s]", "count", series, dir.file("marked.png"), 800, 500, &why,
                          {{0.2, "lining"}, {0.4, "grout"}, {0.8, "equilibrium"}, {1.5, "none"}}))
      << why;
  const std::vector<int> diff = differing_columns(dir.file("plain.png"), dir.file("marked.png"));
  // Columns where over a third of the picture's height changed: the lines
  // (the labels, 13 px text, change fewer).
  std::vector<double> bands;  // centre column of each band of such columns
  for (int i = 0; i < int(diff.size()); ++i) {
    if (diff[i] < 500 / 3) continue;
    int j = i;
    while (j + 1 < int(diff.size()) && diff[j + 1] >= 500 / 3) ++j;
    bands.push_back(0.5 * (i + j));
    EXPECT_LE(j - i, 4) << "band at column " << i << " is " << j - i + 1 << " px wide";
    i = j;
  }
  ASSERT_EQ(bands.size(), 3u);
  EXPECT_NEAR((bands[2] - bands[1]) / (bands[1] - bands[0]), 2.0, 0.05);
  // The labels: text next to each line, so the changed pixels extend beyond the bands.
  int near_first = 0;
  for (int i = int(bands[0]) - 20; i <= int(bands[0]) + 20; ++i) near_first += diff[i];
  EXPECT_GT(near_first, diff[int(bands[0])] + 50);
}

// Stage bands shade their share of the x axis behind the curves: a plot
// over [0, 1] with one band over [0.5, 1] has its light blue shade only in
// the right half of the plot area, over most of its height.
TEST(Plot, stage_bands_shade_their_part_of_the_x_axis) {
  SKIP_UNLESS_RENDERING();
  const TempDir dir;
  const std::vector<PlotSeries> series{{"broken", {0.0, 0.5, 1.0}, {0.0, 10.0, 4.0}}};
  std::string why;
  ASSERT_TRUE(plot_xy_png("t", "step", "count", series, dir.file("banded.png"), 800, 500, &why, {},
                          {{0.5, 1.0, "2 equilibrium"}}))
      << why;
  const std::vector<int> shaded = columns_of_colour(dir.file("banded.png"), {222, 232, 245});
  int first = -1, last = -1;
  for (int i = 0; i < int(shaded.size()); ++i)
    if (shaded[i] > 500 / 3) {
      if (first < 0) first = i;
      last = i;
    }
  ASSERT_GE(first, 0) << "no shaded column";
  // The plot area spans roughly 10%-95% of the width: the band its right half.
  EXPECT_GT(first, 800 * 0.4);
  EXPECT_GT(last, 800 * 0.85);
  EXPECT_GT(last - first, 800 * 0.3);
}

// Stacked charts shade the bands behind each chart (the run's stages on
// lining_history.png): a band over the right half of [0, 1] shades the
// right half of both charts, the upper and the lower half of the picture,
// and nothing without bands.
TEST(Plot, panels_shade_the_bands_behind_every_chart) {
  SKIP_UNLESS_RENDERING();
  const TempDir dir;
  const std::vector<PlotPanel> panels{
      {"thrust [kN/m]", {{"N", {0.0, 0.5, 1.0}, {0.0, 900.0, 1200.0}}}, {}},
      {"safety factor", {{"SF", {0.0, 0.5, 1.0}, {5.0, 2.0, 1.5}}}, {}}};
  std::string why;
  ASSERT_TRUE(plot_panels_png("t", "step", panels, dir.file("plain.png"), 800, 700, &why)) << why;
  ASSERT_TRUE(plot_panels_png("t", "step", panels, dir.file("banded.png"), 800, 700, &why,
                              {{0.5, 1.0, "2 equilibrium"}}))
      << why;
  const PngPixels plain = read_png_pixels(dir.file("plain.png"));
  const PngPixels banded = read_png_pixels(dir.file("banded.png"));
  EXPECT_LT(plain.count({222, 232, 245}), 50);
  // Shaded pixels per half of the picture, and left or right of its middle.
  int upper = 0, lower = 0, left = 0;
  for (int j = 0; j < banded.height; ++j)
    for (int i = 0; i < banded.width; ++i) {
      const std::size_t k = 3 * (std::size_t(j) * std::size_t(banded.width) + std::size_t(i));
      const bool shade = std::abs(banded.rgb[k] - 222) <= 3 &&
                         std::abs(banded.rgb[k + 1] - 232) <= 3 &&
                         std::abs(banded.rgb[k + 2] - 245) <= 3;
      if (!shade) continue;
      (j < banded.height / 2 ? lower : upper) += 1;
      left += i < banded.width * 0.4;
    }
  // Each chart's band: about 350 px wide and over 150 px high.
  EXPECT_GT(upper, 30000) << lower;
  EXPECT_GT(lower, 30000) << upper;
  EXPECT_EQ(left, 0);
}

// Tick values are round multiples of 1, 2 or 5 times a power of ten,
// written with the decimals the step needs: the colour bar of a range
// 8.48-166.2 reads 20, 40, ..., 160, never "166." or "8.48".
TEST(PlotTicks, round_values_written_as_the_step_needs) {
  const Ticks t = nice_ticks(8.48, 166.2);
  EXPECT_EQ(t.step, 20.0);
  ASSERT_EQ(t.values.size(), 8u);
  EXPECT_EQ(t.label(t.values.front()), "20");
  EXPECT_EQ(t.label(t.values.back()), "160");
  const Ticks small = nice_ticks(-0.013, 0.11, 6);
  EXPECT_EQ(small.step, 0.02);
  EXPECT_EQ(small.label(small.values.front()), "0");  // not "-0.00"
  EXPECT_EQ(small.label(0.06), "0.06");
  // A range just short of two multiples gets a finer step.
  EXPECT_GE(nice_ticks(1.1, 1.9, 2).values.size(), 2u);
  EXPECT_TRUE(nice_ticks(1.0, 1.0).values.empty());
  EXPECT_EQ(round_length(0.225), 0.2);
  EXPECT_EQ(round_length(7.3), 5.0);
  EXPECT_EQ(round_length(1.0), 1.0);
}

// Longest run of black pixels (every channel below 40) along one row in
// the window x in [x0, x1), y in [y0, y1) of a PNG (rows from the bottom);
// and the number of black pixels there.
struct BlackRuns {
  int longest = 0;
  int count = 0;
};
BlackRuns black_in(const std::string& path, int x0, int x1, int y0, int y1) {
  const Pixels png(path);
  BlackRuns out;
  for (int j = y0; j < y1; ++j) {
    int run = 0;
    for (int i = x0; i < x1; ++i) {
      const auto p = png.rgb(i, j);
      const bool black = p[0] < 40 && p[1] < 40 && p[2] < 40;
      run = black ? run + 1 : 0;
      out.count += black;
      out.longest = std::max(out.longest, run);
    }
  }
  return out;
}

// A mesh picture has axes in metres: tick values (black text, antialiased:
// about 100 pixels fully black on each axis) in the strip
// left of the mesh and in the strip under it, where the picture was white
// before; and a scale bar at the mesh's lower right, a black bar as long as
// its round length: the 1 m square fills the mesh viewport's height (676 px
// of 800 at 0.075-0.92, with 5% margin: 1.05 m), so 1 m is 643.8 px, the
// viewport (725 px wide) shows 1.126 m and the bar is round_length(0.225 m)
// = 0.2 m: 129 px.
TEST(Plot, mesh_picture_has_axes_in_metres_and_a_scale_bar) {
  SKIP_UNLESS_RENDERING();
  const TempDir dir;
  std::string why;
  const VtkGrid g = cracked_square(6);  // its crack runs far from the bar
  ASSERT_TRUE(render_mesh_png(g, "field", 0, dir.file("m.png"), "Axes", 1000, 800, &why)) << why;
  const std::string png = dir.file("m.png");
  EXPECT_GT(black_in(png, 0, 70, 80, 730).count, 50) << "no y axis values";
  EXPECT_GT(black_in(png, 80, 790, 0, 55).count, 50) << "no x axis values";
  // The mesh viewport spans x 75-800, y 60-736 (from the bottom); the bar
  // lies in its lower right corner, 4 px thick.
  const BlackRuns bar = black_in(png, 560, 795, 62, 120);
  EXPECT_NEAR(bar.longest, 129, 4);
}

TEST(Plot, mesh_png_has_the_asked_size_colours_and_black_cracks) {
  SKIP_UNLESS_RENDERING();
  std::string why;
  const TempDir dir;
  ASSERT_TRUE(render_mesh_png(cracked_square(24), "stress", 0, dir.file("mesh.png"),
                              "Final mesh: stress xx", 800, 600, &why))
      << why;
  const Picture p = read_png(dir.file("mesh.png"));
  EXPECT_EQ(p.width, 800);
  EXPECT_EQ(p.height, 600);
  EXPECT_GT(p.variance, 100.0);
  // The diagonal crack alone is about 2 px x 500 px of black.
  EXPECT_GT(p.n_black, 500);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"mesh.png"}));
}

// A picture with values per point, a hidden triangle left white, and two
// labelled line sets in their colours with a legend.
TEST(Plot, picture_with_point_values_hidden_triangles_and_coloured_lines) {
  SKIP_UNLESS_RENDERING();
  const VtkGrid g = cracked_square(8);
  MeshPicture p;
  p.title = "Displacement magnitude |u| [mm]";
  p.bar_title = "|u| [mm]";
  p.per_point = true;
  for (std::size_t i = 0; i < g.n_points(); ++i) p.values.push_back(g.x[i] + g.y[i]);
  p.hidden.assign(g.n_triangles(), 0);
  p.hidden[0] = 1;
  p.lines.push_back({"mode I", {1.0, 0.0, 1.0}, 3, {{0.1, 0.9, 0.9, 0.9}}});
  p.lines.push_back({"", {0.0, 0.0, 0.0}, 2, {{0.1, 0.1, 0.9, 0.1}}});
  const TempDir dir;
  std::string why;
  ASSERT_TRUE(render_picture_png(g, p, dir.file("u.png"), 600, 400, &why)) << why;
  const Picture pic = read_png(dir.file("u.png"));
  EXPECT_EQ(pic.width, 600);
  EXPECT_GT(pic.variance, 100.0);
  // The magenta line, 0.8 of the square's width (about 280 px) and 3 px
  // wide, and its legend stroke; the colour map has no magenta.
  EXPECT_GT(pic.n_magenta, 500);
  p.values.pop_back();
  EXPECT_THROW(render_picture_png(g, p, dir.file("bad.png"), 600, 400), std::invalid_argument);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"u.png"}));
}

// A picture of the mesh itself: with `edges`, every triangle's edges in
// grey (89, 89, 89) over the colours of its `categories`; without, none.
TEST(Plot, mesh_picture_with_edges_draws_the_triangles_edges_in_grey) {
  SKIP_UNLESS_RENDERING();
  const VtkGrid g = cracked_square(8);
  MeshPicture p;
  p.title = "Final mesh";
  p.bar_title = "zone";
  for (std::size_t t = 0; t < g.n_triangles(); ++t) p.values.push_back(double(t % 2));
  p.categories = {{0, "rock, cracks"}, {1, "rock, no cracks"}};
  const TempDir dir;
  std::string why;
  ASSERT_TRUE(render_picture_png(g, p, dir.file("plain.png"), 600, 500, &why)) << why;
  p.edges = true;
  ASSERT_TRUE(render_picture_png(g, p, dir.file("edges.png"), 600, 500, &why)) << why;
  int plain = 0, edged = 0;
  for (const int n : columns_of_colour(dir.file("plain.png"), {89, 89, 89})) plain += n;
  for (const int n : columns_of_colour(dir.file("edges.png"), {89, 89, 89})) edged += n;
  // 8 x 8 squares, 3 edges each of about 50 px (the diagonals longer): thousands.
  EXPECT_LT(plain, 50);
  EXPECT_GT(edged, 2000) << "plain " << plain;
}

TEST(Plot, mesh_png_of_an_uncracked_int_field_renders) {
  SKIP_UNLESS_RENDERING();
  std::string why;
  const TempDir dir;
  VtkGrid g = cracked_square(6);
  g.lines.clear();
  g.cell_arrays.clear();
  std::vector<std::int32_t> zone(g.n_triangles());
  for (std::size_t t = 0; t < zone.size(); ++t) zone[t] = 1 + static_cast<int>(t % 3);
  g.cell_arrays.push_back(scalar_array("zone", zone));
  ASSERT_TRUE(render_mesh_png(g, "zone", 0, dir.file("zones.png"), "Zones", 400, 300, &why)) << why;
  const Picture p = read_png(dir.file("zones.png"));
  EXPECT_EQ(p.width, 400);
  EXPECT_GT(p.variance, 10.0);
}

// The overlay's instruments are drawn in their dark green (an extensometer
// line 0.8 of the square's width, 3 px wide: about 480 px at 400 x 300),
// and its notes in a white box; without either, neither colour appears.
TEST(Plot, overlay_draws_instruments_in_green_and_notes_on_white) {
  SKIP_UNLESS_RENDERING();
  VtkGrid g = cracked_square(6);
  g.lines.clear();
  g.cell_arrays.clear();
  std::vector<std::int32_t> zone(g.n_triangles(), 1);
  g.cell_arrays.push_back(scalar_array("zone", zone));
  MeshOverlay bare;
  bare.categories = {{1, "rock"}};
  MeshOverlay full = bare;
  full.instrument_segments.push_back({0.1, 0.6, 0.9, 0.6});
  full.instrument_markers.push_back({0.9, 0.6, "ext"});
  full.notes = {"Box 80 x 80 m: rollers in the explicit stages",
                "Stages: 0 insitu, 1 remove_core, 2 equilibrium"};
  const TempDir dir;
  std::string why;
  ASSERT_TRUE(
      render_mesh_png(g, "zone", 0, dir.file("bare.png"), "Bare", 400, 300, &why, nullptr, &bare))
      << why;
  ASSERT_TRUE(
      render_mesh_png(g, "zone", 0, dir.file("full.png"), "Full", 400, 300, &why, nullptr, &full))
      << why;
  const Picture b = read_png(dir.file("bare.png")), f = read_png(dir.file("full.png"));
  EXPECT_LT(b.n_green, 20);
  EXPECT_GT(f.n_green, 250) << "bare " << b.n_green;
  // The notes' box: about 4,000 px of (near) white between its letters.
  EXPECT_GT(f.n_white, b.n_white + 2000) << f.n_white << " against " << b.n_white;
}

}  // namespace
}  // namespace rockfdem::plots
