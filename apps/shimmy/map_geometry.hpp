// The geometry of a map's pictures: the stability boundary as the interpolated zero contour of
// the growth rate (marching squares over cells whose four corners were computed), the unstable
// lobes (4-connected regions of shimmy cells) and where to label each inside the plot.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "contensou/gear/stability_map.hpp"

namespace contensou::app {

// Segments (x0, y0, x1, y1) of growth = 0, linear interpolation along the cells' edges.
inline std::vector<std::array<double, 4>> zero_contour(const StabilityMap& m) {
  std::vector<std::array<double, 4>> out;
  const int nx = m.x.points, ny = m.y.points;
  const auto cell = [&](int i, int j) -> const MapCell& {
    return m.cells[static_cast<std::size_t>(j * nx + i)];
  };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const MapCell* c[4] = {&cell(i, j), &cell(i + 1, j), &cell(i + 1, j + 1), &cell(i, j + 1)};
      bool ok = true;
      for (const MapCell* p : c) ok = ok && p->valid && std::isfinite(p->growth_rate_per_s);
      if (!ok) continue;
      // The crossings on the square's four edges, in order around it.
      std::vector<std::array<double, 2>> cross;
      for (int e = 0; e < 4; ++e) {
        const MapCell &a = *c[e], &b = *c[(e + 1) % 4];
        const double ga = a.growth_rate_per_s, gb = b.growth_rate_per_s;
        if ((ga > 0.0) == (gb > 0.0)) continue;
        const double s = ga / (ga - gb);
        cross.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
      }
      // Two crossings: one segment; four (a saddle): pair them by the centre's sign.
      if (cross.size() == 2) out.push_back({cross[0][0], cross[0][1], cross[1][0], cross[1][1]});
      if (cross.size() == 4) {
        out.push_back({cross[0][0], cross[0][1], cross[1][0], cross[1][1]});
        out.push_back({cross[2][0], cross[2][1], cross[3][0], cross[3][1]});
      }
    }
  return out;
}

// The unstable lobes: 4-connected regions of valid shimmy cells, as cell indices.
inline std::vector<std::vector<int>> unstable_lobes(const StabilityMap& m) {
  const int nx = m.x.points, n = static_cast<int>(m.cells.size());
  std::vector<int> region(static_cast<std::size_t>(n), -1);
  std::vector<std::vector<int>> lobes;
  const auto unstable = [&](int k) {
    const MapCell& c = m.cells[static_cast<std::size_t>(k)];
    return c.valid && c.shimmy;
  };
  for (int k = 0; k < n; ++k) {
    if (!unstable(k) || region[static_cast<std::size_t>(k)] >= 0) continue;
    lobes.emplace_back();
    std::vector<int> stack{k};
    region[static_cast<std::size_t>(k)] = static_cast<int>(lobes.size()) - 1;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      lobes.back().push_back(c);
      const int i = c % nx, j = c / nx;
      const int next[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
      for (const auto& q : next) {
        if (q[0] < 0 || q[0] >= nx || q[1] < 0 || q[1] >= m.y.points) continue;
        const int d = q[1] * nx + q[0];
        if (unstable(d) && region[static_cast<std::size_t>(d)] < 0) {
          region[static_cast<std::size_t>(d)] = region[static_cast<std::size_t>(k)];
          stack.push_back(d);
        }
      }
    }
  }
  return lobes;
}

// The lobe's cell nearest its centroid (in axis-scaled units): a point inside it.
inline const MapCell& lobe_centre(const StabilityMap& m, const std::vector<int>& lobe) {
  double cx = 0.0, cy = 0.0;
  for (int k : lobe) {
    cx += m.cells[static_cast<std::size_t>(k)].x;
    cy += m.cells[static_cast<std::size_t>(k)].y;
  }
  cx /= static_cast<double>(lobe.size());
  cy /= static_cast<double>(lobe.size());
  const double sx = std::abs(m.x.to - m.x.from) + 1e-300, sy = std::abs(m.y.to - m.y.from) + 1e-300;
  const MapCell* best = &m.cells[static_cast<std::size_t>(lobe.front())];
  double best_d = 1e300;
  for (int k : lobe) {
    const MapCell& c = m.cells[static_cast<std::size_t>(k)];
    const double d = std::hypot((c.x - cx) / sx, (c.y - cy) / sy);
    if (d < best_d) {
      best = &c;
      best_d = d;
    }
  }
  return *best;
}

// A label's anchor kept clear of the frame: between 3 % and 97 % of each axis, and the
// alignment that keeps its text inside (left in the left third, right in the right third).
struct LabelAnchor {
  double x = 0.0, y = 0.0;
  const char* align = "center";
};
inline LabelAnchor inside_frame(const StabilityMap& m, double x, double y) {
  const auto clamp = [](double v, double a, double b) {
    const double lo = a + 0.03 * (b - a), hi = a + 0.97 * (b - a);
    return lo <= hi ? std::min(std::max(v, lo), hi) : std::min(std::max(v, hi), lo);
  };
  LabelAnchor l{clamp(x, m.x.from, m.x.to), clamp(y, m.y.from, m.y.to), "center"};
  const double span = m.x.to - m.x.from;
  const double rel = span != 0.0 ? (l.x - m.x.from) / span : 0.5;
  l.align = rel < 0.3 ? "left" : rel > 0.7 ? "right" : "center";
  // Keep the text off the frame's top and bottom lines too.
  l.y = clamp(l.y, m.y.from + 0.02 * (m.y.to - m.y.from), m.y.to - 0.02 * (m.y.to - m.y.from));
  return l;
}

// Labels already placed on a map, as boxes in fractions of its frame (0..1 on each axis).
struct PlacedLabels {
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> boxes;
};

// `a` (from inside_frame) moved down, a line at a time (up once the bottom is reached), until a
// text of `chars` characters at font 9 clears every label placed before; then recorded. The box
// is estimated from the map pictures' 820 x 660 terminal (a frame of about 630 x 530 pixels,
// 6 pixels a character, 16 a line).
inline LabelAnchor place_clear(const StabilityMap& m, LabelAnchor a, std::size_t chars,
                               PlacedLabels& placed) {
  const double sx = m.x.to - m.x.from, sy = m.y.to - m.y.from;
  if (sx == 0.0 || sy == 0.0) return a;
  const double w = 6.0 * static_cast<double>(chars) / 630.0, h = 16.0 / 530.0;
  const double rx = (a.x - m.x.from) / sx;
  const std::string align = a.align;
  const double x0 = align == "left" ? rx : align == "right" ? rx - w : rx - 0.5 * w;
  const auto clear = [&](double ry) {
    for (const PlacedLabels::Box& b : placed.boxes)
      if (x0 < b.x1 && x0 + w > b.x0 && ry - 0.5 * h < b.y1 && ry + 0.5 * h > b.y0) return false;
    return true;
  };
  const double start = (a.y - m.y.from) / sy;
  // Lines below the start down to 3 % of the frame, then lines above it.
  const int below = std::max(0, static_cast<int>(std::floor((start - 0.03) / h)));
  double ry = start;
  for (int k = 1; !clear(ry) && k < 60; ++k)
    ry = k <= below ? start - k * h : start + (k - below) * h;
  placed.boxes.push_back({x0, x0 + w, ry - 0.5 * h, ry + 0.5 * h});
  a.y = m.y.from + ry * sy;
  return a;
}

}  // namespace contensou::app
