// Line plots with vtkChartXY in an offscreen vtkContextView.
#include <vtkActor2D.h>
#include <vtkAxis.h>
#include <vtkCellArray.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkPropCollection.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "plot_display.hpp"
#include "plot_png.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::plots {
namespace {

// Tableau's ten colours: distinguishable, and printable in grey scale.
constexpr std::array<std::array<unsigned char, 3>, 10> kPalette{{{31, 119, 180},
                                                                 {255, 127, 14},
                                                                 {44, 160, 44},
                                                                 {214, 39, 40},
                                                                 {148, 103, 189},
                                                                 {140, 86, 75},
                                                                 {227, 119, 194},
                                                                 {127, 127, 127},
                                                                 {188, 189, 34},
                                                                 {23, 190, 207}}};

void check_series(const std::vector<PlotSeries>& series) {
  if (series.empty()) throw std::invalid_argument("plot has no series");
  for (const PlotSeries& s : series) {
    if (s.x.size() != s.y.size()) {
      throw std::invalid_argument("plot series '" + s.name + "': " + std::to_string(s.x.size()) +
                                  " x values but " + std::to_string(s.y.size()) + " y values");
    }
  }
}

vtkSmartPointer<vtkDoubleArray> column(const char* name, const std::vector<double>& v) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfValues(static_cast<vtkIdType>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), v[i]);
  return a;
}

vtkPlot* add_line(vtkChart* chart, const std::string& label, const std::vector<double>& x,
                  const std::vector<double>& y, bool points) {
  vtkNew<vtkTable> table;  // the plot keeps a reference to it
  table->AddColumn(column("x", x));
  table->AddColumn(column(label.c_str(), y));
  vtkPlot* line = chart->AddPlot(points ? vtkChart::POINTS : vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  line->SetLabel(label);
  return line;
}

// `marks`: drawn as unjoined circles whatever the series says.
void add_series(vtkChart* chart, const PlotSeries& s, std::size_t index, bool marks = false) {
  const std::string label = s.name.empty() ? "series " + std::to_string(index + 1) : s.name;
  const bool points = s.points || marks;
  vtkPlot* line = add_line(chart, label, s.x, s.y, points);
  const auto& c = kPalette[index % kPalette.size()];
  line->SetColor(c[0], c[1], c[2], 255);
  line->SetWidth(points ? 4.0 : 2.0);
  if (s.points) vtkPlotPoints::SafeDownCast(line)->SetMarkerSize(12.0);
  if (marks) vtkPlotPoints::SafeDownCast(line)->SetMarkerStyle(vtkPlotPoints::CIRCLE);
}

// The finite range of the series' y (or x) values; (inf, -inf) when none.
std::pair<double, double> data_range(const std::vector<PlotSeries>& series, bool x) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PlotSeries& s : series)
    for (double v : x ? s.x : s.y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  return {lo, hi};
}

// Fixes the y axis with a quarter of room above the data, so the legend
// (drawn in the top right corner, on an opaque box) does not hide the
// curves' ends; returns the range (markers span it).
std::pair<double, double> leave_room_for_legend(vtkAxis* axis,
                                                const std::vector<PlotSeries>& series) {
  auto [lo, hi] = data_range(series, false);
  if (lo > hi) lo = 0, hi = 1;  // no finite data
  if (lo == hi)
    lo -= 0.5 * std::max(1.0, std::abs(lo)), hi += std::max(1.0, std::abs(hi));
  else
    hi += 0.25 * (hi - lo);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(lo, hi);
  return {lo, hi};
}

// Fixes the x axis to the series' range (a little wider where a series is
// drawn as marks, which would sit half outside on its ends); returns the
// markers within it.
std::vector<PlotMarker> fix_x_range(vtkAxis* axis, const std::vector<PlotSeries>& series,
                                    const std::vector<PlotMarker>& markers) {
  auto [lo, hi] = data_range(series, true);
  if (!(hi > lo)) return {};  // VTK's automatic range for a single abscissa
  const bool marks =
      std::any_of(series.begin(), series.end(), [](const PlotSeries& s) { return s.points; });
  const double pad = marks ? 0.03 * (hi - lo) : 0.0;
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(lo - pad, hi + pad);
  std::vector<PlotMarker> inside;
  for (const PlotMarker& m : markers)
    if (m.x >= lo && m.x <= hi) inside.push_back(m);
  return inside;
}

// Dashed grey verticals over the whole y range, out of the legend.
void add_marker_lines(vtkChartXY* chart, const std::vector<PlotMarker>& markers,
                      std::pair<double, double> y) {
  for (const PlotMarker& m : markers) {
    vtkPlot* line = add_line(chart, m.label, {m.x, m.x}, {y.first, y.second}, false);
    line->SetColor(90, 90, 90, 255);
    line->SetWidth(1.5);
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
    line->SetLegendVisibility(false);
  }
}

// The markers' labels, written upwards right of each line, down from the
// top of the plot area (curves mostly start low on the left); a label that
// would overlap the one before moves right by a line of text. Placed in
// pixels, so after a first render has laid out the axes.
void add_marker_labels(vtkContextView* view, vtkChartXY* chart,
                       const std::vector<PlotMarker>& markers) {
  if (markers.empty()) return;
  constexpr double kTextHeight = 16;  // [px] of a 13 pt line, with a gap
  view->GetRenderWindow()->Render();
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  const float* p1 = x->GetPoint1();
  const float* p2 = x->GetPoint2();
  const double x0 = x->GetMinimum(), x1 = x->GetMaximum();
  const double top = chart->GetAxis(vtkAxis::LEFT)->GetPoint2()[1];
  double last = -1e300;  // the previous label's left edge [px]
  for (const PlotMarker& m : markers) {
    const double px = p1[0] + (m.x - x0) / (x1 - x0) * (p2[0] - p1[0]);
    last = std::max(px + 3, last + kTextHeight);
    vtkNew<vtkTextActor> text;
    text->SetInput(m.label.c_str());
    vtkTextProperty* p = text->GetTextProperty();
    p->SetFontSize(13);
    p->SetColor(0.25, 0.25, 0.25);
    // Turned a quarter: right-justified ends the text at the top,
    // top-justified lays it right of the anchor.
    p->SetOrientation(90.0);
    p->SetJustificationToRight();
    p->SetVerticalJustificationToTop();
    text->SetDisplayPosition(static_cast<int>(last), static_cast<int>(top) - 4);
    view->GetRenderer()->AddActor2D(text);
  }
}

// A rectangle from pixel (x0, y0) to (x1, y1), filled with `rgb`.
vtkSmartPointer<vtkActor2D> pixel_box(double x0, double y0, double x1, double y1,
                                      const unsigned char* rgb) {
  vtkNew<vtkPoints> points;
  for (const auto& c : {std::array<double, 2>{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}})
    points->InsertNextPoint(c[0], c[1], 0.0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  cells->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(cells);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
  return actor;
}

// Puts `under` beneath everything the renderer draws in 2D so far (the
// chart): 2D props are drawn in the order they were added.
void add_under(vtkRenderer* renderer, const std::vector<vtkSmartPointer<vtkActor2D>>& under) {
  std::vector<vtkSmartPointer<vtkProp>> before;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* p = props->GetNextProp()) before.emplace_back(p);
  for (const auto& p : before) renderer->RemoveViewProp(p);
  for (const auto& a : under) renderer->AddViewProp(a);
  for (const auto& p : before) renderer->AddViewProp(p);
}

// The bands: light shades over the plot area's height, alternating, under
// the chart (whose plot area is transparent); their labels horizontal at
// each band's top left, a label that would run into an earlier one in its
// row a row lower. Placed in pixels, after a first render has laid out the axes.
// The shaded boxes are appended to `boxes`, for the caller to put under
// the charts at once (add_under): a second call would lift the first's
// boxes over the charts.
void add_bands(vtkContextView* view, vtkChartXY* chart, const std::vector<PlotBand>& bands,
               std::vector<vtkSmartPointer<vtkActor2D>>& boxes) {
  if (bands.empty()) return;
  constexpr unsigned char kShade[2][3] = {{222, 232, 245}, {240, 240, 240}};
  constexpr double kRow = 17;  // [px] of a 13 pt line, with a gap
  view->GetRenderWindow()->Render();
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  const double px0 = x->GetPoint1()[0], px1 = x->GetPoint2()[0];
  const double bottom = y->GetPoint1()[1], top = y->GetPoint2()[1];
  const double x0 = x->GetMinimum(), x1 = x->GetMaximum();
  const auto pixel = [&](double v) {
    return px0 + (std::clamp(v, x0, x1) - x0) / (x1 - x0) * (px1 - px0);
  };
  std::vector<double> row_end;  // per row, the right edge of its last label [px]
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const PlotBand& b = bands[i];
    if (b.x1 < x0 || b.x0 > x1) continue;
    boxes.push_back(pixel_box(pixel(b.x0), bottom, pixel(b.x1), top, kShade[i % 2]));
    if (b.label.empty()) continue;
    vtkNew<vtkTextActor> text;
    text->SetInput(b.label.c_str());
    vtkTextProperty* p = text->GetTextProperty();
    p->SetFontSize(13);
    p->SetColor(0.2, 0.2, 0.2);
    p->SetVerticalJustificationToTop();
    double box[4];
    text->GetBoundingBox(view->GetRenderer(), box);
    const double left = pixel(b.x0) + 4;
    std::size_t row = 0;
    while (row < row_end.size() && left < row_end[row] + 6) ++row;
    if (row == row_end.size()) row_end.push_back(0);
    row_end[row] = left + (box[1] - box[0]);
    text->SetDisplayPosition(static_cast<int>(left), static_cast<int>(top - 4 - kRow * row));
    view->GetRenderer()->AddActor2D(text);
  }
}

void label_axis(vtkAxis* axis, const std::string& title) {
  axis->SetTitle(title);
  axis->GetTitleProperties()->SetFontSize(16);
  axis->GetLabelProperties()->SetFontSize(13);
}

// A white offscreen view of width x height pixels: `draw` fills it, then
// the window goes to `path` as PNG. False (reason in *why) and nothing
// written without a display.
bool render_png(int width, int height, const std::string& path, std::string* why,
                const std::function<void(vtkContextView*)>& draw) {
  check_image_size(width, height);
  const DisplayConnection display;  // held until the PNG is written
  if (!display.ok()) {
    if (why) *why = display.reason();
    return false;
  }
  vtkNew<vtkContextView> view;
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(width, height);
  draw(view);
  save_window_png(view->GetRenderWindow(), path);
  return true;
}

}  // namespace

bool plot_xy_png(const std::string& title, const std::string& x_label, const std::string& y_label,
                 const std::vector<PlotSeries>& series, const std::string& path, int width,
                 int height, std::string* why, const std::vector<PlotMarker>& markers,
                 const std::vector<PlotBand>& bands) {
  check_series(series);
  return render_png(width, height, path, why, [&](vtkContextView* view) {
    vtkNew<vtkChartXY> chart;  // the scene keeps it
    view->GetScene()->AddItem(chart);
    chart->SetTitle(title);
    chart->GetTitleProperties()->SetFontSize(18);
    label_axis(chart->GetAxis(vtkAxis::BOTTOM), x_label);
    label_axis(chart->GetAxis(vtkAxis::LEFT), y_label);
    const auto y_range = leave_room_for_legend(chart->GetAxis(vtkAxis::LEFT), series);
    const std::vector<PlotMarker> shown =
        fix_x_range(chart->GetAxis(vtkAxis::BOTTOM), series, markers);
    for (std::size_t i = 0; i < series.size(); ++i) add_series(chart, series[i], i);
    add_marker_lines(chart, shown, y_range);
    chart->SetShowLegend(true);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
    std::vector<vtkSmartPointer<vtkActor2D>> boxes;
    add_bands(view, chart, bands, boxes);
    add_under(view->GetRenderer(), boxes);
    add_marker_labels(view, chart, shown);
  });
}

bool plot_panels_png(const std::string& title, const std::string& x_label,
                     const std::vector<PlotPanel>& panels, const std::string& path, int width,
                     int height, std::string* why, const std::vector<PlotBand>& bands) {
  if (panels.empty()) throw std::invalid_argument("plot has no panels");
  for (const PlotPanel& p : panels) {
    check_series(p.lines.empty() ? p.markers : p.lines);
    if (!p.markers.empty()) check_series(p.markers);
  }
  std::vector<PlotSeries> all;
  for (const PlotPanel& p : panels) {
    all.insert(all.end(), p.lines.begin(), p.lines.end());
    all.insert(all.end(), p.markers.begin(), p.markers.end());
  }
  return render_png(width, height, path, why, [&](vtkContextView* view) {
    vtkNew<vtkChartMatrix> matrix;  // the scene keeps it
    view->GetScene()->AddItem(matrix);
    const int n = int(panels.size());
    matrix->SetSize(vtkVector2i(1, n));
    // Room for the y axis titles (VTK's default border clips their first
    // letter) and between charts for the x tick values of the one above.
    matrix->SetBorders(80, 60, 30, 40);
    matrix->SetGutterY(45);
    for (int i = 0; i < n; ++i) {
      const PlotPanel& p = panels[std::size_t(i)];
      vtkChart* chart = matrix->GetChart(vtkVector2i(0, n - 1 - i));  // row 0 is the bottom
      if (i == 0) {
        chart->SetTitle(title);
        chart->GetTitleProperties()->SetFontSize(18);
      }
      // The x axis is shared: its title under the last chart only.
      label_axis(chart->GetAxis(vtkAxis::BOTTOM), i + 1 == n ? x_label : "");
      label_axis(chart->GetAxis(vtkAxis::LEFT), p.y_label);
      // One x range for every chart, the data's (VTK's own would round it
      // out, 360 deg to 400).
      fix_x_range(chart->GetAxis(vtkAxis::BOTTOM), all, {});
      std::size_t k = 0;
      for (const PlotSeries& s : p.lines) add_series(chart, s, k++);
      for (const PlotSeries& s : p.markers) add_series(chart, s, k++, true);
      chart->SetShowLegend(p.lines.size() + p.markers.size() > 1);
      chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
    }
    // The bands behind every chart (the stages of a run's curves), their
    // labels on the first only.
    std::vector<vtkSmartPointer<vtkActor2D>> boxes;
    for (int i = 0; i < n && !bands.empty(); ++i) {
      auto* chart = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, n - 1 - i)));
      if (!chart) continue;
      std::vector<PlotBand> shaded = bands;
      if (i > 0)
        for (PlotBand& b : shaded) b.label.clear();
      add_bands(view, chart, shaded, boxes);
    }
    add_under(view->GetRenderer(), boxes);
  });
}

}  // namespace rockfdem::plots
