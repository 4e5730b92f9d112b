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

// The colours of the overlay's two kinds of things drawn.
constexpr double kBoltRgb[3] = {0.55, 0.0, 0.0};
constexpr double kKeyPointRgb[3] = {0.0, 0.2, 0.8};
constexpr double kInstrumentRgb[3] = {0.0, 0.45, 0.1};

vtkSmartPointer<vtkActor> segment_actor(const std::vector<MeshOverlay::Segment>& segments,
                                        double lift, const double* rgb) {
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
  auto actor = actor_of(poly, rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetLineWidth(3.0);
  return actor;
}

vtkSmartPointer<vtkActor> marker_actor(const std::vector<MeshOverlay::Marker>& markers, double lift,
                                       const double* rgb) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  for (const MeshOverlay::Marker& m : markers) {
    const vtkIdType id = points->InsertNextPoint(m.x, m.y, 2 * lift);
    verts->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(verts);
  auto actor = actor_of(poly, rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetPointSize(11.0);
  actor->GetProperty()->RenderPointsAsSpheresOn();
  return actor;
}

// A marker's label, placed beside it in world coordinates.
vtkSmartPointer<vtkTextActor> label_actor(const MeshOverlay::Marker& m, double lift,
                                          const double* rgb) {
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(m.label.c_str());
  text->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  text->GetPositionCoordinate()->SetValue(m.x, m.y, 2 * lift);
  vtkTextProperty* p = text->GetTextProperty();
  p->SetFontSize(15);
  p->SetColor(0.6 * rgb[0], 0.6 * rgb[1], 0.6 * rgb[2]);
  p->BoldOn();
  return text;
}

// The notes as one block of text on a white box at the lower left.
vtkSmartPointer<vtkTextActor> notes_actor(const std::vector<std::string>& notes) {
  std::string text;
  for (const std::string& n : notes) text += (text.empty() ? "" : "\n") + n;
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(0.01, 0.01);
  vtkTextProperty* p = actor->GetTextProperty();
  p->SetFontSize(13);
  p->SetColor(0.0, 0.0, 0.0);
  p->SetBackgroundColor(1.0, 1.0, 1.0);
  p->SetBackgroundOpacity(0.85);
  p->SetJustificationToLeft();
  p->SetVerticalJustificationToBottom();
  return actor;
}

void add_points(vtkRenderer* renderer, const std::vector<MeshOverlay::Marker>& markers, double lift,
                const double* rgb) {
  if (markers.empty()) return;
  renderer->AddActor(marker_actor(markers, lift, rgb));
  for (const MeshOverlay::Marker& m : markers) renderer->AddActor2D(label_actor(m, lift, rgb));
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
  if (!overlay.segments.empty())
    renderer->AddActor(segment_actor(overlay.segments, lift, kBoltRgb));
  if (!overlay.instrument_segments.empty())
    renderer->AddActor(segment_actor(overlay.instrument_segments, lift, kInstrumentRgb));
  add_points(renderer, overlay.markers, lift, kKeyPointRgb);
  add_points(renderer, overlay.instrument_markers, lift, kInstrumentRgb);
  if (!overlay.notes.empty()) renderer->AddActor2D(notes_actor(overlay.notes));
}

}  // namespace rockfdem::plots
