// The mesh coloured by one component of a cell field, with cracks (the grid's
// line cells) in black on top: the "final cracked mesh" picture of a run.
//
// Layout: three renderers side by side in one offscreen window: the mesh
// (left, most of it), the colour bar (right strip) and the title (top strip),
// so the bar never covers the mesh.
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
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
#include "plot_overlay.hpp"
#include "plot_png.hpp"
#include "rockfdem/coupling/plot.hpp"

namespace rockfdem::coupling {
namespace {

constexpr double kMeshRight = 0.84;  // the colour bar takes the strip right of this
constexpr double kMeshTop = 0.92;    // the title takes the strip above this

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

vtkSmartPointer<vtkLookupTable> blue_to_red(std::pair<double, double> range) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.667, 0.0);
  lut->SetNumberOfTableValues(256);
  lut->SetTableRange(range.first, range.second);
  lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkActor> triangle_actor(const VtkGrid& grid, const std::vector<double>& values,
                                         vtkLookupTable* lut) {
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(grid_points(grid, 0.0));
  poly->SetPolys(cell_array(grid.triangles));
  vtkNew<vtkDoubleArray> field;
  field->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t t = 0; t < values.size(); ++t)
    field->SetValue(static_cast<vtkIdType>(t), values[t]);
  poly->GetCellData()->SetScalars(field);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScalarModeToUseCellData();
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// Cracks sit slightly above the triangles (towards the camera), so they are
// drawn over them without depth fighting.
vtkSmartPointer<vtkActor> crack_actor(const VtkGrid& grid, double lift) {
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(grid_points(grid, lift));
  poly->SetLines(cell_array(grid.lines));
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  actor->GetProperty()->SetLineWidth(2.0);
  return actor;
}

// The grid's bounding box.
MeshView whole(const VtkGrid& grid) {
  const auto [x0, x1] = std::minmax_element(grid.x.begin(), grid.x.end());
  const auto [y0, y1] = std::minmax_element(grid.y.begin(), grid.y.end());
  return {*x0, *x1, *y0, *y1};
}

// NaN for the triangles whose centroid lies outside `v`: the colour scale
// then spans what the picture shows.
std::vector<double> inside_only(const VtkGrid& grid, std::vector<double> values,
                                const MeshView& v) {
  for (std::size_t t = 0; t < grid.n_triangles(); ++t) {
    const auto& tri = grid.triangles[t];
    const double cx = (grid.x[tri[0]] + grid.x[tri[1]] + grid.x[tri[2]]) / 3;
    const double cy = (grid.y[tri[0]] + grid.y[tri[1]] + grid.y[tri[2]]) / 3;
    if (cx < v.x0 || cx > v.x1 || cy < v.y0 || cy > v.y1) values[t] = std::nan("");
  }
  return values;
}

// Looks straight down z with a parallel projection just large enough for
// the window `v` in a viewport of the given pixel size.
void fit_camera(vtkRenderer* renderer, const MeshView& v, double view_w, double view_h) {
  const double cx = 0.5 * (v.x0 + v.x1), cy = 0.5 * (v.y0 + v.y1);
  const double half_w = 0.5 * (v.x1 - v.x0), half_h = 0.5 * (v.y1 - v.y0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 1.0 + 4.0 * std::max(half_w, half_h));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(1.05 * std::max({half_h, half_w * view_h / view_w, 1e-12}));
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkRenderer> colour_bar(vtkLookupTable* lut, const std::string& label) {
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle(label.c_str());
  bar->SetNumberOfLabels(6);
  bar->SetLabelFormat("%-#8.3g");
  bar->SetPosition(0.05, 0.05);
  bar->SetWidth(0.9);
  bar->SetHeight(0.9);
  bar->UnconstrainedFontSizeOn();  // fixed point sizes, not scaled up to the bar's width
  for (vtkTextProperty* p : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    p->SetColor(0.0, 0.0, 0.0);
    p->ShadowOff();
    p->ItalicOff();
    p->BoldOff();
    p->SetFontSize(14);
  }
  bar->GetTitleTextProperty()->SetFontSize(16);
  if (lut->GetIndexedLookup()) {  // named swatches: leave room for the names beside them
    bar->SetPosition(0.15, 0.05);
    bar->SetWidth(0.15);
    bar->SetTextPositionToPrecedeScalarBar();  // annotations go on the other side: the right
    bar->GetAnnotationTextProperty()->SetColor(0.0, 0.0, 0.0);
    bar->GetAnnotationTextProperty()->SetFontSize(14);
    bar->GetAnnotationTextProperty()->ItalicOff();
  }
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(kMeshRight, 0.0, 1.0, kMeshTop);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor2D(bar);
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

}  // namespace

bool render_mesh_png(const VtkGrid& grid, const std::string& cell_field, int component,
                     const std::string& path, const std::string& title, int width, int height,
                     std::string* why, const MeshView* view, const MeshOverlay* overlay) {
  grid.validate();
  const VtkArray& field = field_to_draw(grid, cell_field, component);
  check_image_size(width, height);
  if (grid.n_points() == 0) throw std::invalid_argument("mesh plot: the grid has no points");
  const DisplayConnection display;  // held until the PNG is written
  if (!display.ok()) {
    if (why) *why = display.reason();
    return false;
  }

  const std::vector<double> values = triangle_values(grid, field, component);
  const MeshView shown = view ? *view : whole(grid);
  const auto lut =
      overlay && !overlay->categories.empty()
          ? category_colours(overlay->categories)
          : blue_to_red(finite_range(view ? inside_only(grid, values, shown) : values));

  vtkNew<vtkRenderer> mesh;
  mesh->SetViewport(0.0, 0.0, kMeshRight, kMeshTop);
  mesh->SetBackground(1.0, 1.0, 1.0);
  mesh->AddActor(triangle_actor(grid, values, lut));
  fit_camera(mesh, shown, kMeshRight * width, kMeshTop * height);
  const double lift = 1e-3 * mesh->GetActiveCamera()->GetParallelScale();
  mesh->AddActor(crack_actor(grid, lift));
  if (overlay) add_overlay(mesh, *overlay, lift);
  mesh->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(mesh);
  window->AddRenderer(colour_bar(lut, component_name(field, component)));
  window->AddRenderer(title_strip(title, width, height));
  save_window_png(window, path);
  return true;
}

}  // namespace rockfdem::coupling
