// Line plots with vtkChartXY in an offscreen vtkContextView.
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "plot_display.hpp"
#include "plot_png.hpp"
#include "rockfdem/coupling/plot.hpp"

namespace rockfdem::coupling {
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

void add_series(vtkChart* chart, const PlotSeries& s, std::size_t index, bool markers = false) {
  const std::string label = s.name.empty() ? "series " + std::to_string(index + 1) : s.name;
  vtkNew<vtkTable> table;  // the plot keeps a reference to it
  table->AddColumn(column("x", s.x));
  table->AddColumn(column(label.c_str(), s.y));
  vtkPlot* line = chart->AddPlot(markers ? vtkChart::POINTS : vtkChart::LINE);
  if (markers) static_cast<vtkPlotPoints*>(line)->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  line->SetInputData(table, 0, 1);
  line->SetLabel(label);
  const auto& c = kPalette[index % kPalette.size()];
  line->SetColor(c[0], c[1], c[2], 255);
  line->SetWidth(2.0);
}

// Extends the y axis by a quarter above the data, so the legend (drawn in the
// top right corner, on an opaque box) does not hide the curves' ends.
void leave_room_for_legend(vtkAxis* axis, const std::vector<PlotSeries>& series) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PlotSeries& s : series) {
    for (double y : s.y) {
      if (std::isfinite(y)) lo = std::min(lo, y), hi = std::max(hi, y);
    }
  }
  if (!(hi > lo)) return;  // no data or flat: VTK's automatic range is fine
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(lo, hi + 0.25 * (hi - lo));
}

void label_axis(vtkAxis* axis, const std::string& title) {
  axis->SetTitle(title);
  axis->GetTitleProperties()->SetFontSize(16);
  axis->GetLabelProperties()->SetFontSize(13);
}

// A white offscreen view of width x height pixels: `draw` fills its scene,
// then the window goes to `path` as PNG. False (reason in *why) and nothing
// written without a display.
bool render_png(int width, int height, const std::string& path, std::string* why,
                const std::function<void(vtkContextScene*)>& draw) {
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
  draw(view->GetScene());
  save_window_png(view->GetRenderWindow(), path);
  return true;
}

}  // namespace

bool plot_xy_png(const std::string& title, const std::string& x_label, const std::string& y_label,
                 const std::vector<PlotSeries>& series, const std::string& path, int width,
                 int height, std::string* why) {
  check_series(series);
  return render_png(width, height, path, why, [&](vtkContextScene* scene) {
    vtkNew<vtkChartXY> chart;  // the scene keeps it
    scene->AddItem(chart);
    chart->SetTitle(title);
    chart->GetTitleProperties()->SetFontSize(18);
    label_axis(chart->GetAxis(vtkAxis::BOTTOM), x_label);
    label_axis(chart->GetAxis(vtkAxis::LEFT), y_label);
    for (std::size_t i = 0; i < series.size(); ++i) add_series(chart, series[i], i);
    leave_room_for_legend(chart->GetAxis(vtkAxis::LEFT), series);
    chart->SetShowLegend(true);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
  });
}

bool plot_panels_png(const std::string& title, const std::string& x_label,
                     const std::vector<PlotPanel>& panels, const std::string& path, int width,
                     int height, std::string* why) {
  if (panels.empty()) throw std::invalid_argument("plot has no panels");
  for (const PlotPanel& p : panels) {
    check_series(p.lines.empty() ? p.markers : p.lines);
    if (!p.markers.empty()) check_series(p.markers);
  }
  return render_png(width, height, path, why, [&](vtkContextScene* scene) {
    vtkNew<vtkChartMatrix> matrix;  // the scene keeps it
    scene->AddItem(matrix);
    const int n = int(panels.size());
    matrix->SetSize(vtkVector2i(1, n));
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
      std::size_t k = 0;
      for (const PlotSeries& s : p.lines) add_series(chart, s, k++);
      for (const PlotSeries& s : p.markers) add_series(chart, s, k++, true);
      chart->SetShowLegend(p.lines.size() + p.markers.size() > 1);
      chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
    }
  });
}

}  // namespace rockfdem::coupling
