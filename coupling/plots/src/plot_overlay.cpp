#include "plot_overlay.hpp"

#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkVariant.h>

namespace rockfdem::plots {
namespace {

// Distinct colours for up to eight codes (light enough for the dark
// overlay lines to show on them), then repeated.
constexpr double kPalette[][3] = {{0.85, 0.80, 0.68}, {0.96, 0.65, 0.45}, {0.75, 0.87, 0.96},
                                  {0.62, 0.80, 0.55}, {0.85, 0.75, 0.90}, {0.95, 0.90, 0.55},
                                  {0.70, 0.70, 0.70}, {0.55, 0.75, 0.75}};

vtkSmartPointer<vtkActor> actor_of(vtkPolyData* poly, double r, double g, double b) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

vtkSmartPointer<vtkActor> segment_actor(const std::vector<MeshOverlay::Segment>& segments,
                                        double lift) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const MeshOverlay::Segment& s : segments) {
    const vtkIdType ids[2] = {points->InsertNextPoint(s.x0, s.y0, lift),
                              points->InsertNextPoint(s.x1, s.y1, lift)};
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  auto actor = actor_of(poly, 0.55, 0.0, 0.0);
  actor->GetProperty()->SetLineWidth(3.0);
  return actor;
}

vtkSmartPointer<vtkActor> marker_actor(const std::vector<MeshOverlay::Marker>& markers,
                                       double lift) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  for (const MeshOverlay::Marker& m : markers) {
    const vtkIdType id = points->InsertNextPoint(m.x, m.y, 2 * lift);
    verts->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(verts);
  auto actor = actor_of(poly, 0.0, 0.2, 0.8);
  actor->GetProperty()->SetPointSize(11.0);
  actor->GetProperty()->RenderPointsAsSpheresOn();
  return actor;
}

// A marker's label, placed beside it in world coordinates.
vtkSmartPointer<vtkTextActor> label_actor(const MeshOverlay::Marker& m, double lift) {
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(m.label.c_str());
  text->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  text->GetPositionCoordinate()->SetValue(m.x, m.y, 2 * lift);
  vtkTextProperty* p = text->GetTextProperty();
  p->SetFontSize(15);
  p->SetColor(0.0, 0.1, 0.5);
  p->BoldOn();
  return text;
}

}  // namespace

vtkSmartPointer<vtkLookupTable> category_colours(
    const std::vector<std::pair<int, std::string>>& categories) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->IndexedLookupOn();
  lut->SetNumberOfTableValues(static_cast<vtkIdType>(categories.size()));
  for (std::size_t i = 0; i < categories.size(); ++i) {
    const double* c = kPalette[i % (sizeof kPalette / sizeof kPalette[0])];
    lut->SetTableValue(static_cast<vtkIdType>(i), c[0], c[1], c[2], 1.0);
    // The field's values reach the table as doubles: annotate doubles.
    lut->SetAnnotation(vtkVariant(double(categories[i].first)), categories[i].second);
  }
  lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
  return lut;
}

void add_overlay(vtkRenderer* renderer, const MeshOverlay& overlay, double lift) {
  if (!overlay.segments.empty()) renderer->AddActor(segment_actor(overlay.segments, lift));
  if (overlay.markers.empty()) return;
  renderer->AddActor(marker_actor(overlay.markers, lift));
  for (const MeshOverlay::Marker& m : overlay.markers) renderer->AddActor2D(label_actor(m, lift));
}

}  // namespace rockfdem::plots
