// The mesh coloured by one component of a cell field, with cracks (the grid's
// line cells) in black on top: the "final cracked mesh" picture of a run.
//
// Layout: renderers side by side in one offscreen window: the mesh (most of
// it), the axes in metres (strips left of and under it, plot_frame), the
// colour bar (right strip) and the title (top strip), so nothing covers the
// mesh but its scale bar.
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plot_display.hpp"
#include "plot_frame.hpp"
#include "plot_overlay.hpp"
#include "plot_png.hpp"
#include "plot_ticks.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::plots {
namespace {

constexpr double kMeshLeft = 0.075;    // the y axis takes the strip left of this
constexpr double kMeshBottom = 0.075;  // the x axis takes the strip below this (full width)
constexpr double kMeshRight = 0.80;    // the colour bar takes the strip right of this
constexpr double kMeshTop = 0.92;      // the title takes the strip above this

// Per-triangle values of one component of a cell array, as doubles.
std::vector<double> triangle_values(const VtkGrid& grid, const VtkArray& a, int component) {
  std::vector<double> out(grid.n_triangles());
  std::visit(
      [&](const auto& v) {
        for (std::size_t t = 0; t < out.size(); ++t) {
          out[t] = static_cast<double>(v[t * a.n_components + component]);
        }
      },
      a.values);
  return out;
}

std::string component_name(const VtkArray& a, int component) {
  static const char* vector[] = {"x", "y", "z"};
  static const char* tensor3[] = {"xx", "yy", "xy"};
  static const char* tensor4[] = {"xx", "yy", "zz", "xy"};
  switch (a.kind) {
    case VtkKind::scalar:
      return a.name;
    case VtkKind::vector:
      return a.name + " " + vector[component];
    case VtkKind::symmetric_tensor:
      return a.name + " " + (a.n_components == 3 ? tensor3 : tensor4)[component];
  }
  return a.name;
}

// Range of the finite values; widened when flat so the colour map is defined.
std::pair<double, double> finite_range(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : v) {
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  if (lo > hi) return {0.0, 1.0};
  if (lo == hi)
    return {lo - 0.5 * std::max(1.0, std::abs(lo)), hi + 0.5 * std::max(1.0, std::abs(hi))};
  return {lo, hi};
}

vtkSmartPointer<vtkPoints> grid_points(const VtkGrid& grid, double z) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(grid.n_points()));
  for (std::size_t i = 0; i < grid.n_points(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), grid.x[i], grid.y[i], z);
  }
  return points;
}

template <std::size_t N>
vtkSmartPointer<vtkCellArray> cell_array(const std::vector<std::array<int, N>>& cells) {
  auto out = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& c : cells) {
    vtkIdType ids[N];
    std::copy(c.begin(), c.end(), ids);
    out->InsertNextCell(static_cast<vtkIdType>(N), ids);
  }
  return out;
}

// Blue to red through the rainbow; or, for a magnitude, pale yellow to
// dark red, which leaves black, blue and green free for lines drawn over it.
vtkSmartPointer<vtkLookupTable> colour_map(std::pair<double, double> range, bool magnitude) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(magnitude ? 0.16 : 0.667, 0.0);
  if (magnitude) {
    lut->SetSaturationRange(0.15, 1.0);
    lut->SetValueRange(1.0, 0.55);
  }
  lut->SetNumberOfTableValues(256);
  lut->SetTableRange(range.first, range.second);
  lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkDoubleArray> double_array(const std::vector<double>& values) {
  auto field = vtkSmartPointer<vtkDoubleArray>::New();
  field->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    field->SetValue(static_cast<vtkIdType>(i), values[i]);
  return field;
}

// The triangles not hidden, coloured by the picture's values (per cell or
// per point).
vtkSmartPointer<vtkActor> triangle_actor(const VtkGrid& grid, const MeshPicture& p,
                                         vtkLookupTable* lut) {
  std::vector<std::array<int, 3>> shown;
  std::vector<double> cell_values;
  for (std::size_t t = 0; t < grid.n_triangles(); ++t) {
    if (!p.hidden.empty() && p.hidden[t]) continue;
    shown.push_back(grid.triangles[t]);
    if (!p.per_point) cell_values.push_back(p.values[t]);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(grid_points(grid, 0.0));
  poly->SetPolys(cell_array(shown));
  vtkNew<vtkPolyDataMapper> mapper;
  if (p.per_point) {
    poly->GetPointData()->SetScalars(double_array(p.values));
    mapper->SetScalarModeToUsePointData();
  } else {
    poly->GetCellData()->SetScalars(double_array(cell_values));
    mapper->SetScalarModeToUseCellData();
  }
  mapper->SetInputData(poly);
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (p.edges) {
    actor->GetProperty()->EdgeVisibilityOn();
    actor->GetProperty()->SetEdgeColor(0.35, 0.35, 0.35);
    actor->GetProperty()->SetLineWidth(1.0f);
  }
  return actor;
}

// Lines sit slightly above the triangles (towards the camera), so they are
// drawn over them without depth fighting; later sets a little higher.
vtkSmartPointer<vtkActor> lines_actor(const PictureLines& l, double lift) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (const auto& s : l.segments) {
    const vtkIdType ids[2] = {points->InsertNextPoint(s[0], s[1], lift),
                              points->InsertNextPoint(s[2], s[3], lift)};
    cells->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(l.rgb[0], l.rgb[1], l.rgb[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(l.width));
  return actor;
}

// The grid's bounding box.
MeshView whole(const VtkGrid& grid) {
  const auto [x0, x1] = std::minmax_element(grid.x.begin(), grid.x.end());
  const auto [y0, y1] = std::minmax_element(grid.y.begin(), grid.y.end());
  return {*x0, *x1, *y0, *y1};
}

// The values of the drawn triangles whose centroid lies in `v` (all drawn
// ones without a window): what the colour scale spans.
std::vector<double> values_shown(const VtkGrid& grid, const MeshPicture& p) {
  std::vector<double> out;
  for (std::size_t t = 0; t < grid.n_triangles(); ++t) {
    if (!p.hidden.empty() && p.hidden[t]) continue;
    const auto& tri = grid.triangles[t];
    if (p.view) {
      const MeshView& v = *p.view;
      const double cx = (grid.x[tri[0]] + grid.x[tri[1]] + grid.x[tri[2]]) / 3;
      const double cy = (grid.y[tri[0]] + grid.y[tri[1]] + grid.y[tri[2]]) / 3;
      if (cx < v.x0 || cx > v.x1 || cy < v.y0 || cy > v.y1) continue;
    }
    if (!p.per_point)
      out.push_back(p.values[t]);
    else
      for (int k : tri) out.push_back(p.values[k]);
  }
  return out;
}

// Looks straight down z with a parallel projection just large enough for
// the window `v` in the frame's viewport; returns the window shown.
MeshView fit_camera(vtkRenderer* renderer, const MeshView& v, const Frame& f) {
  const double view_w = (f.right - f.left) * f.width, view_h = (f.top - f.bottom) * f.height;
  const double cx = 0.5 * (v.x0 + v.x1), cy = 0.5 * (v.y0 + v.y1);
  const double half_w = 0.5 * (v.x1 - v.x0), half_h = 0.5 * (v.y1 - v.y0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 1.0 + 4.0 * std::max(half_w, half_h));
  camera->SetViewUp(0.0, 1.0, 0.0);
  const double scale = 1.05 * std::max({half_h, half_w * view_h / view_w, 1e-12});
  camera->SetParallelScale(scale);
  renderer->ResetCameraClippingRange();
  return shown_window(f, cx, cy, scale);
}

void plain_text(vtkTextProperty* p, int size) {
  p->SetColor(0.0, 0.0, 0.0);
  p->ShadowOff();
  p->ItalicOff();
  p->BoldOff();
  p->SetFontSize(size);
}

vtkSmartPointer<vtkScalarBarActor> scalar_bar(vtkLookupTable* lut, const std::string& label,
                                              double y0, double height) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(lut);
  bar->SetTitle(label.c_str());
  // Round values at the ticks ("-20", "2.5"), not six evenly spaced ones ("166.").
  const Ticks ticks = nice_ticks(lut->GetRange()[0], lut->GetRange()[1]);
  vtkNew<vtkDoubleArray> at;
  for (const double v : ticks.values) at->InsertNextValue(v);
  bar->SetCustomLabels(at);
  bar->SetUseCustomLabels(!ticks.values.empty() && !lut->GetIndexedLookup());
  bar->SetLabelFormat(("%." + std::to_string(ticks.decimals) + "f").c_str());
  bar->SetPosition(0.05, y0);
  bar->SetWidth(0.9);
  bar->SetHeight(height);
  bar->UnconstrainedFontSizeOn();  // fixed point sizes, not scaled up to the bar's width
  plain_text(bar->GetLabelTextProperty(), 14);
  plain_text(bar->GetTitleTextProperty(), 16);
  if (lut->GetIndexedLookup()) {  // named swatches: leave room for the names beside them
    bar->SetWidth(0.25);
    bar->SetTextPositionToPrecedeScalarBar();  // annotations go on the other side: the right
    plain_text(bar->GetAnnotationTextProperty(), 14);
  }
  return bar;
}

// A stroke in a line set's colour from (x0, y) to (x1, y), in the
// viewport's normalised coordinates.
vtkSmartPointer<vtkActor2D> stroke(const PictureLines& l, double x0, double x1, double y) {
  vtkNew<vtkPoints> ends;
  ends->InsertNextPoint(x0, y, 0.0);
  ends->InsertNextPoint(x1, y, 0.0);
  vtkNew<vtkCellArray> cell;
  const vtkIdType ids[2] = {0, 1};
  cell->InsertNextCell(2, ids);
  vtkNew<vtkPolyData> line;
  line->SetPoints(ends);
  line->SetLines(cell);
  vtkNew<vtkCoordinate> normalised;
  normalised->SetCoordinateSystemToNormalizedViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(line);
  mapper->SetTransformCoordinate(normalised);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(l.rgb[0], l.rgb[1], l.rgb[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(std::max(3.0, l.width)));
  return actor;
}

// One entry per labelled line set, top down from `top`: a stroke in its
// colour and the label in black.
void add_legend(vtkRenderer* renderer, const std::vector<PictureLines>& lines, double top) {
  const auto n = std::count_if(lines.begin(), lines.end(),
                               [](const PictureLines& l) { return !l.label.empty(); });
  const double gap = std::min(0.04, (top - 0.01) / double(std::max<long>(n, 1)));
  double y = top;
  for (const PictureLines& l : lines) {
    if (l.label.empty()) continue;
    renderer->AddActor2D(stroke(l, 0.04, 0.2, y));
    vtkNew<vtkTextActor> text;
    text->SetInput(l.label.c_str());
    plain_text(text->GetTextProperty(), 13);
    text->GetTextProperty()->SetVerticalJustificationToCentered();
    text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    text->GetPositionCoordinate()->SetValue(0.24, y);
    renderer->AddActor2D(text);
    y -= gap;  // nine entries fit below the bar at 0.04; more closer together
  }
}

// The strip right of the mesh: the colour bar, and below it the legend of
// the labelled lines where there are any.
vtkSmartPointer<vtkRenderer> side_strip(vtkLookupTable* lut, const MeshPicture& p) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(kMeshRight, kMeshBottom, 1.0, kMeshTop);
  renderer->SetBackground(1.0, 1.0, 1.0);
  const bool any_label = std::any_of(p.lines.begin(), p.lines.end(),
                                     [](const PictureLines& l) { return !l.label.empty(); });
  renderer->AddActor2D(any_label ? scalar_bar(lut, p.bar_title, 0.42, 0.55)
                                 : scalar_bar(lut, p.bar_title, 0.05, 0.9));
  if (any_label) add_legend(renderer, p.lines, 0.36);
  return renderer;
}

vtkSmartPointer<vtkRenderer> title_strip(const std::string& title, int width, int height) {
  vtkNew<vtkTextActor> text;
  text->SetInput(title.c_str());
  vtkTextProperty* p = text->GetTextProperty();
  p->SetFontSize(20);
  p->SetColor(0.0, 0.0, 0.0);
  p->SetJustificationToCentered();
  p->SetVerticalJustificationToCentered();
  text->SetDisplayPosition(width / 2, static_cast<int>(height * (1.0 - 0.5 * (1.0 - kMeshTop))));
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(0.0, kMeshTop, 1.0, 1.0);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor2D(text);
  return renderer;
}

const VtkArray& field_to_draw(const VtkGrid& grid, const std::string& name, int component) {
  const VtkArray* a = grid.find_cell_array(name);
  if (!a) throw std::invalid_argument("mesh plot: no cell array named '" + name + "'");
  if (component < 0 || component >= a->n_components) {
    throw std::invalid_argument("mesh plot: cell array '" + name + "' has no component " +
                                std::to_string(component) + " (it has " +
                                std::to_string(a->n_components) + ")");
  }
  return *a;
}

void check_picture(const VtkGrid& grid, const MeshPicture& p) {
  grid.validate();
  if (grid.n_points() == 0) throw std::invalid_argument("mesh plot: the grid has no points");
  const std::size_t n = p.per_point ? grid.n_points() : grid.n_triangles();
  if (p.values.size() != n)
    throw std::invalid_argument("mesh plot '" + p.title + "': " + std::to_string(p.values.size()) +
                                " values for " + std::to_string(n) +
                                (p.per_point ? " points" : " triangles"));
  if (!p.hidden.empty() && p.hidden.size() != grid.n_triangles())
    throw std::invalid_argument("mesh plot '" + p.title + "': " + std::to_string(p.hidden.size()) +
                                " hidden flags for " + std::to_string(grid.n_triangles()) +
                                " triangles");
}

}  // namespace

bool render_picture_png(const VtkGrid& grid, const MeshPicture& p, const std::string& path,
                        int width, int height, std::string* why) {
  check_picture(grid, p);
  check_image_size(width, height);
  const DisplayConnection display;  // held until the PNG is written
  if (!display.ok()) {
    if (why) *why = display.reason();
    return false;
  }
  const auto& categories =
      !p.categories.empty() || !p.overlay ? p.categories : p.overlay->categories;
  const auto lut = !categories.empty()
                       ? category_colours(categories)
                       : colour_map(finite_range(values_shown(grid, p)), p.magnitude);
  vtkNew<vtkRenderer> mesh;
  mesh->SetViewport(kMeshLeft, kMeshBottom, kMeshRight, kMeshTop);
  mesh->SetBackground(1.0, 1.0, 1.0);
  mesh->AddActor(triangle_actor(grid, p, lut));
  Frame frame{kMeshLeft, kMeshBottom, kMeshRight, kMeshTop, {}, width, height};
  frame.shown = fit_camera(mesh, p.view ? *p.view : whole(grid), frame);
  const double lift = 1e-3 * mesh->GetActiveCamera()->GetParallelScale();
  for (std::size_t i = 0; i < p.lines.size(); ++i)
    mesh->AddActor(lines_actor(p.lines[i], lift * double(i + 1)));
  if (p.overlay) add_overlay(mesh, *p.overlay, lift * double(p.lines.size() + 1));
  add_scale_bar(mesh, frame);
  mesh->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(mesh);
  window->AddRenderer(side_strip(lut, p));
  window->AddRenderer(title_strip(p.title, width, height));
  add_axes(window, frame);
  save_window_png(window, path);
  return true;
}

bool render_mesh_png(const VtkGrid& grid, const std::string& cell_field, int component,
                     const std::string& path, const std::string& title, int width, int height,
                     std::string* why, const MeshView* view, const MeshOverlay* overlay) {
  grid.validate();
  const VtkArray& field = field_to_draw(grid, cell_field, component);
  MeshPicture p;
  p.title = title;
  p.bar_title = component_name(field, component);
  p.values = triangle_values(grid, field, component);
  if (view) p.view = *view;
  p.overlay = overlay;
  PictureLines cracks;
  for (const auto& l : grid.lines)
    cracks.segments.push_back({grid.x[l[0]], grid.y[l[0]], grid.x[l[1]], grid.y[l[1]]});
  p.lines.push_back(std::move(cracks));
  return render_picture_png(grid, p, path, width, height, why);
}

}  // namespace rockfdem::plots
