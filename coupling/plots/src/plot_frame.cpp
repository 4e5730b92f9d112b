#include "plot_frame.hpp"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>

#include "plot_ticks.hpp"

namespace rockfdem::plots {
namespace {

constexpr double kBlack[3] = {0.0, 0.0, 0.0};
constexpr double kTickPx = 6;   // tick marks' length
constexpr double kLabelPx = 9;  // tick values' distance from the axis

vtkSmartPointer<vtkActor2D> polygon_2d(const std::vector<std::array<double, 2>>& corners,
                                       const double* rgb, bool filled, double width) {
  vtkNew<vtkPoints> points;
  std::vector<vtkIdType> ids;
  for (const auto& c : corners) ids.push_back(points->InsertNextPoint(c[0], c[1], 0.0));
  vtkNew<vtkCellArray> cells;
  if (!filled) ids.push_back(ids.front());  // closed outline
  cells->InsertNextCell(vtkIdType(ids.size()), ids.data());
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  if (filled)
    poly->SetPolys(cells);
  else
    poly->SetLines(cells);
  vtkNew<vtkCoordinate> normalised;
  normalised->SetCoordinateSystemToNormalizedViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  mapper->SetTransformCoordinate(normalised);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

vtkSmartPointer<vtkTextActor> text_2d(const std::string& s, double x, double y, int size) {
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(s.c_str());
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* p = text->GetTextProperty();
  p->SetFontSize(size);
  p->SetColor(0.0, 0.0, 0.0);
  p->ShadowOff();
  p->BoldOff();
  p->ItalicOff();
  return text;
}

vtkSmartPointer<vtkRenderer> strip(double x0, double y0, double x1, double y1) {
  auto r = vtkSmartPointer<vtkRenderer>::New();
  r->SetViewport(x0, y0, x1, y1);
  r->SetBackground(1.0, 1.0, 1.0);
  return r;
}

// The y axis: a strip as tall as the mesh, ticks on its right edge.
vtkSmartPointer<vtkRenderer> y_axis(const Frame& f, double step) {
  auto r = strip(0.0, f.bottom, f.left, f.top);
  const double w = f.left * f.width;  // [px]
  const Ticks t = ticks_at(f.shown.y0, f.shown.y1, step);
  for (const double v : t.values) {
    const double y = (v - f.shown.y0) / (f.shown.y1 - f.shown.y0);
    add_line_2d(r, 1.0 - kTickPx / w, y, 1.0, y, kBlack, 1.5);
    auto label = text_2d(t.label(v), 1.0 - kLabelPx / w, y, 13);
    label->GetTextProperty()->SetJustificationToRight();
    label->GetTextProperty()->SetVerticalJustificationToCentered();
    r->AddActor2D(label);
  }
  auto title = text_2d("y [m]", 14.0 / w, 0.5, 15);
  title->GetTextProperty()->SetOrientation(90.0);
  title->GetTextProperty()->SetJustificationToCentered();
  title->GetTextProperty()->SetVerticalJustificationToCentered();
  r->AddActor2D(title);
  return r;
}

// The x axis: a strip across the window's foot, ticks on its top edge
// under the mesh.
vtkSmartPointer<vtkRenderer> x_axis(const Frame& f, double step) {
  auto r = strip(0.0, 0.0, 1.0, f.bottom);
  const double h = f.bottom * f.height;  // [px]
  const Ticks t = ticks_at(f.shown.x0, f.shown.x1, step);
  for (const double v : t.values) {
    const double x = f.left + (v - f.shown.x0) / (f.shown.x1 - f.shown.x0) * (f.right - f.left);
    add_line_2d(r, x, 1.0 - kTickPx / h, x, 1.0, kBlack, 1.5);
    auto label = text_2d(t.label(v), x, 1.0 - kLabelPx / h, 13);
    label->GetTextProperty()->SetJustificationToCentered();
    label->GetTextProperty()->SetVerticalJustificationToTop();
    r->AddActor2D(label);
  }
  auto title = text_2d("x [m]", 0.5 * (f.left + f.right), 6.0 / h, 15);
  title->GetTextProperty()->SetJustificationToCentered();
  title->GetTextProperty()->SetVerticalJustificationToBottom();
  r->AddActor2D(title);
  return r;
}

}  // namespace

MeshView shown_window(const Frame& f, double cx, double cy, double parallel_scale) {
  const double vw = (f.right - f.left) * f.width, vh = (f.top - f.bottom) * f.height;
  const double hw = parallel_scale * vw / vh;
  return {cx - hw, cx + hw, cy - parallel_scale, cy + parallel_scale};
}

void add_line_2d(vtkRenderer* r, double x0, double y0, double x1, double y1, const double* rgb,
                 double width) {
  r->AddActor2D(polygon_2d({{x0, y0}, {x1, y1}}, rgb, false, width));
}

void add_axes(vtkRenderWindow* window, const Frame& f) {
  // One step on both axes (the picture's scale is the same in x and y),
  // about eight ticks along the longer side.
  const double longer = std::max(f.shown.x1 - f.shown.x0, f.shown.y1 - f.shown.y0);
  const double step = nice_ticks(0.0, longer, 8).step;
  window->AddRenderer(y_axis(f, step));
  window->AddRenderer(x_axis(f, step));
}

void add_scale_bar(vtkRenderer* mesh, const Frame& f) {
  // The box round the viewport: half a pixel in, or the viewport clips it.
  const double ex = 0.5 / ((f.right - f.left) * f.width),
               ey = 0.5 / ((f.top - f.bottom) * f.height);
  mesh->AddActor2D(
      polygon_2d({{ex, ey}, {1 - ex, ey}, {1 - ex, 1 - ey}, {ex, 1 - ey}}, kBlack, false, 1.5));
  const double width = f.shown.x1 - f.shown.x0;
  const double length = round_length(0.2 * width);
  if (!(length > 0)) return;
  const double x1 = 0.96, x0 = x1 - length / width, y = 0.05;
  constexpr double kWhite[3] = {1.0, 1.0, 1.0};
  mesh->AddActor2D(
      polygon_2d({{x0 - 0.02, 0.015}, {x1 + 0.02, 0.015}, {x1 + 0.02, 0.11}, {x0 - 0.02, 0.11}},
                 kWhite, true, 1.0));
  add_line_2d(mesh, x0, y, x1, y, kBlack, 4.0);
  add_line_2d(mesh, x0, y - 0.012, x0, y + 0.012, kBlack, 2.0);
  add_line_2d(mesh, x1, y - 0.012, x1, y + 0.012, kBlack, 2.0);
  const Ticks t = nice_ticks(0, length, 2);
  auto label = text_2d(t.label(length) + " m", 0.5 * (x0 + x1), y + 0.018, 14);
  label->GetTextProperty()->SetJustificationToCentered();
  label->GetTextProperty()->SetVerticalJustificationToBottom();
  mesh->AddActor2D(label);
}

}  // namespace rockfdem::plots
