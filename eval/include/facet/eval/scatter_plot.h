// An SVG plot of error against cost, the Pareto front joined in red: `matc eval`'s plot.svg and
// `matc tune`'s (docs/eval.md, docs/tune.md). Deterministic bytes: the same plot gives the same text.
#pragma once

#include <string>
#include <vector>

namespace facet::eval {

struct PlotPoint {
  double x = 0;             // cost
  double y = 0;             // PSNR, dB; +inf (identical images) sits on a band above the finite range
  std::string name;         // points at the same (x, y) share one label, their names joined by " = "
  bool front = false;       // on the Pareto front: red, joined by the front's line, labelled first
  bool labelled = true;     // false: the name is the point's tooltip only
  bool upperBound = false;  // y only bounds the figure: drawn hollow
};

// A marked configuration (a tier before or after tuning): its own shape and colour, labelled
// before any point.
struct PlotMark {
  enum class Shape { Square, Diamond };
  double x = 0, y = 0;
  std::string label;
  std::string colour;  // an SVG colour, e.g. "#1f77b4"
  Shape shape = Shape::Square;
};

// A dashed line across the plot: a PSNR (horizontal) or a cost (vertical), labelled at its end.
struct PlotLine {
  bool horizontal = true;
  double at = 0;
  std::string label;
  std::string colour;
};

struct ScatterPlot {
  std::string title;   // the first line
  std::string note;    // a smaller second line, if any
  std::string xLabel;  // e.g. "estimated fragment cycles (...)"
  std::string yLabel;
  std::vector<PlotPoint> points;
  std::vector<PlotMark> marks;
  std::vector<PlotLine> lines;
};

std::string scatterPlotSvg(const ScatterPlot& plot);

std::string xmlEscape(const std::string& text);

}  // namespace facet::eval
