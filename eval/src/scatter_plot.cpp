#include "facet/eval/scatter_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace facet::eval {
namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string scatterPlotSvg(const ScatterPlot& plot) {
  const double W = 820, H = 520, left = 64, right = 24, top = 40, bottom = 56;
  double minX = 1e9, maxX = 0, minY = 1e9, maxY = -1e9;
  auto include = [&](double x, double y) {
    minX = std::min(minX, x);
    maxX = std::max(maxX, x);
    if (!std::isinf(y)) {
      minY = std::min(minY, y);
      maxY = std::max(maxY, y);
    }
  };
  for (const PlotPoint& p : plot.points) include(p.x, p.y);
  for (const PlotMark& m : plot.marks) include(m.x, m.y);
  for (const PlotLine& l : plot.lines) {
    if (l.horizontal) {
      minY = std::min(minY, l.at);
      maxY = std::max(maxY, l.at);
    } else {
      minX = std::min(minX, l.at);
      maxX = std::max(maxX, l.at);
    }
  }
  if (minY > maxY) minY = maxY = 40;
  // The cost axis spans the points (with room for labels on the right), in steps of a round size.
  const double span = std::max(maxX - std::min(minX, maxX), 0.1);
  const double step = span > 4 ? 1.0 : span > 2 ? 0.5 : span > 0.8 ? 0.25 : 0.1;
  const double x0 = std::max(0.0, std::floor((std::min(minX, maxX) - 0.5 * step) / step) * step);
  const double x1 = std::ceil((maxX + 0.2 * span + 0.5 * step) / step) * step;
  const double y0 = std::floor((minY - 2) / 5) * 5, y1 = std::ceil((maxY + 2) / 5) * 5;
  const double plotTop = top + 24;  // identical images ("∞") sit on a band above the finite range
  auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (W - left - right); };
  auto py = [&](double y) {
    if (std::isinf(y)) return top + 8;
    return plotTop + (y1 - y) / (y1 - y0) * (H - plotTop - bottom);
  };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt("%.0f", W) + "\" height=\"" +
                  fmt("%.0f", H) + "\" viewBox=\"0 0 " + fmt("%.0f", W) + " " + fmt("%.0f", H) +
                  "\" font-family=\"sans-serif\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + fmt("%.0f", left) + "\" y=\"20\" font-size=\"14\">" + xmlEscape(plot.title) + "</text>\n";
  if (!plot.note.empty())
    s += "<text x=\"" + fmt("%.0f", left) + "\" y=\"34\" font-size=\"10\" fill=\"#555\">" + xmlEscape(plot.note) +
         "</text>\n";
  // Axes, grid and ticks.
  s += "<g stroke=\"#ccc\" stroke-width=\"1\">\n";
  for (double y = y0; y <= y1 + 1e-9; y += 5)
    s += "<line x1=\"" + fmt("%.1f", left) + "\" y1=\"" + fmt("%.1f", py(y)) + "\" x2=\"" + fmt("%.1f", W - right) +
         "\" y2=\"" + fmt("%.1f", py(y)) + "\"/>\n";
  for (double x = x0; x <= x1 + 1e-9; x += step)
    s += "<line x1=\"" + fmt("%.1f", px(x)) + "\" y1=\"" + fmt("%.1f", plotTop) + "\" x2=\"" + fmt("%.1f", px(x)) +
         "\" y2=\"" + fmt("%.1f", H - bottom) + "\"/>\n";
  s += "</g>\n<g font-size=\"11\" fill=\"#333\">\n";
  for (double y = y0; y <= y1 + 1e-9; y += 5)
    s += "<text x=\"" + fmt("%.1f", left - 6) + "\" y=\"" + fmt("%.1f", py(y) + 4) + "\" text-anchor=\"end\">" +
         fmt("%.0f", y) + "</text>\n";
  s += "<text x=\"" + fmt("%.1f", left - 6) + "\" y=\"" + fmt("%.1f", top + 12) + "\" text-anchor=\"end\">∞</text>\n";
  for (double x = x0; x <= x1 + 1e-9; x += step)
    s += "<text x=\"" + fmt("%.1f", px(x)) + "\" y=\"" + fmt("%.1f", H - bottom + 16) + "\" text-anchor=\"middle\">" +
         fmt(step < 0.25 ? "%.1f" : "%.2f", x) + "</text>\n";
  s += "<text x=\"" + fmt("%.1f", (left + W - right) / 2) + "\" y=\"" + fmt("%.1f", H - 14) +
       "\" text-anchor=\"middle\">" + xmlEscape(plot.xLabel) + "</text>\n";
  s += "<text transform=\"translate(16 " + fmt("%.1f", (plotTop + H - bottom) / 2) +
       ") rotate(-90)\" text-anchor=\"middle\">" + xmlEscape(plot.yLabel) + "</text>\n</g>\n";
  // Labels go to the first of a few places around their point that overlaps no label or point
  // placed before (text width estimated at 5.2 px per character of the 9 px font), else to the
  // right.
  struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& b) const { return x0 < b.x1 && b.x0 < x1 && y0 < b.y1 && b.y0 < y1; }
  };
  std::vector<Box> taken;
  auto place = [&](double x, double y, const std::string& label) {
    const double width = 5.2 * double(label.size());
    // (dx, dy) of the text's baseline start; anchor end when the label sits left of its point.
    const std::pair<double, double> places[] = {{6, -4},  {6, 10}, {-6, -4},  {-6, 10},
                                                {6, -14}, {6, 20}, {-6, -14}, {-6, 20}};
    double dx = 6, dy = -4;
    for (const auto& [cx, cy] : places) {
      const double start = cx > 0 ? x + cx : x + cx - width;
      Box box{start, y + cy - 8, start + width, y + cy + 2};
      if (box.x0 < 0 || box.x1 > W ||
          std::any_of(taken.begin(), taken.end(), [&](const Box& b) { return box.overlaps(b); }))
        continue;
      dx = cx;
      dy = cy;
      break;
    }
    const double start = dx > 0 ? x + dx : x + dx - width;
    taken.push_back({start, y + dy - 8, start + width, y + dy + 2});
    return "<text x=\"" + fmt("%.1f", x + dx) + "\" y=\"" + fmt("%.1f", y + dy) + "\"" +
           (dx < 0 ? " text-anchor=\"end\"" : "");
  };
  // The budgets' lines, dashed, labelled at the right or top end.
  if (!plot.lines.empty()) {
    s += "<g font-size=\"9\">\n";
    for (const PlotLine& l : plot.lines) {
      const std::string colour = xmlEscape(l.colour);
      if (l.horizontal) {
        const double y = py(l.at);
        s += "<line x1=\"" + fmt("%.1f", left) + "\" y1=\"" + fmt("%.1f", y) + "\" x2=\"" + fmt("%.1f", W - right) +
             "\" y2=\"" + fmt("%.1f", y) + "\" stroke=\"" + colour + "\" stroke-dasharray=\"6 4\"/>\n";
        s += "<text x=\"" + fmt("%.1f", W - right - 2) + "\" y=\"" + fmt("%.1f", y - 3) +
             "\" text-anchor=\"end\" fill=\"" + colour + "\">" + xmlEscape(l.label) + "</text>\n";
      } else {
        const double x = px(l.at);
        s += "<line x1=\"" + fmt("%.1f", x) + "\" y1=\"" + fmt("%.1f", plotTop) + "\" x2=\"" + fmt("%.1f", x) +
             "\" y2=\"" + fmt("%.1f", H - bottom) + "\" stroke=\"" + colour + "\" stroke-dasharray=\"6 4\"/>\n";
        s += "<text x=\"" + fmt("%.1f", x + 3) + "\" y=\"" + fmt("%.1f", plotTop + 10) + "\" fill=\"" + colour + "\">" +
             xmlEscape(l.label) + "</text>\n";
      }
    }
    s += "</g>\n";
  }
  // The Pareto front, cheapest first.
  std::vector<const PlotPoint*> front;
  for (const PlotPoint& p : plot.points)
    if (p.front) front.push_back(&p);
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->x < b->x || (a->x == b->x && a->y < b->y); });
  if (front.size() > 1) {
    s += "<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\"";
    for (size_t i = 0; i < front.size(); ++i)
      s += (i ? " " : "") + fmt("%.1f", px(front[i]->x)) + "," + fmt("%.1f", py(front[i]->y));
    s += "\"/>\n";
  }
  // Points, one per distinct (x, y); points at the same place share a label.
  std::map<std::pair<double, double>, std::vector<const PlotPoint*>> points;
  std::vector<std::pair<double, double>> order;
  for (const PlotPoint& p : plot.points) {
    auto key = std::make_pair(p.x, p.y);
    if (!points.count(key)) order.push_back(key);
    points[key].push_back(&p);
  }
  for (const auto& key : order)
    taken.push_back({px(key.first) - 4, py(key.second) - 4, px(key.first) + 4, py(key.second) + 4});
  for (const PlotMark& m : plot.marks) taken.push_back({px(m.x) - 5, py(m.y) - 5, px(m.x) + 5, py(m.y) + 5});
  // The marks' labels are placed first, then the front's, so that those are the ones that stay
  // readable; the marks are drawn last, over the points.
  std::string marks;
  if (!plot.marks.empty()) {
    marks += "<g font-size=\"9\" font-weight=\"bold\">\n";
    for (const PlotMark& m : plot.marks) {
      const double x = px(m.x), y = py(m.y);
      const std::string colour = xmlEscape(m.colour);
      if (m.shape == PlotMark::Shape::Square)
        marks += "<rect x=\"" + fmt("%.1f", x - 5) + "\" y=\"" + fmt("%.1f", y - 5) +
                 "\" width=\"10\" height=\"10\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\">";
      else
        marks += "<polygon points=\"" + fmt("%.1f", x) + "," + fmt("%.1f", y - 6) + " " + fmt("%.1f", x + 6) + "," +
                 fmt("%.1f", y) + " " + fmt("%.1f", x) + "," + fmt("%.1f", y + 6) + " " + fmt("%.1f", x - 6) + "," +
                 fmt("%.1f", y) + "\" fill=\"" + colour + "\">";
      marks += "<title>" + xmlEscape(m.label) + "</title>" +
               (m.shape == PlotMark::Shape::Square ? "</rect>\n" : "</polygon>\n");
      marks += place(x, y, m.label) + " fill=\"" + colour + "\">" + xmlEscape(m.label) + "</text>\n";
    }
    marks += "</g>\n";
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](const auto& a, const auto& b) { return points[a].front()->front && !points[b].front()->front; });
  s += "<g font-size=\"9\">\n";
  for (const auto& key : order) {
    const auto& members = points[key];
    const PlotPoint& first = *members.front();
    const bool onFront = first.front;
    std::string label;
    for (size_t i = 0; i < members.size(); ++i) label += (i ? " = " : "") + members[i]->name;
    const double x = px(key.first), y = py(key.second);
    const std::string colour = onFront ? "#d62728" : "#7f7f7f";
    s += "<circle cx=\"" + fmt("%.1f", x) + "\" cy=\"" + fmt("%.1f", y) + "\" r=\"" + (onFront ? "4.5" : "3.5") +
         "\" fill=\"" + (first.upperBound ? "white\" stroke=\"" + colour : colour) + "\"><title>" +
         xmlEscape(first.upperBound ? "≤ " + label : label) + "</title></circle>\n";
    if (!first.labelled) continue;
    s += place(x, y, label) + " fill=\"" + (onFront ? "#a01010" : "#555") + "\">" + xmlEscape(label) + "</text>\n";
  }
  s += "</g>\n" + marks + "</svg>\n";
  return s;
}

}  // namespace facet::eval
