// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points along the border of a rectangle at the local density, so that a
// triangulation of the samples and of these points covers the rectangle, and
// the samples too close to the border to make well-shaped triangles with them.

#ifndef PENROSE_TOOLS_BORDER_POINTS_H
#define PENROSE_TOOLS_BORDER_POINTS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace penrose_tools {

// The mean distance of blue-noise samples of `points_per_unit_area`: that of
// a hexagonal packing.
inline double sample_spacing(double points_per_unit_area) { return 1.07 / std::sqrt(points_per_unit_area); }

// A sample closer to the border than this fraction of the border points'
// spacing is dropped: the nearest row of a hexagonal packing parallel to the
// border is at 0.87 spacings, and a sample at less than a quarter spacing
// from a border edge makes an angle under 15 degrees with it.
constexpr double border_clearance = 0.5;

/*
Calls `add(x, y)` for the points strictly inside the segment from (ax, ay)
to (bx, by), in this order, at the local spacing of `points_per_unit_area(x, y)`:
the segment is cut into the whole number of spacings nearest to the
integral of 1 / spacing along it, each part holding an equal share of that
integral, so that no part at a corner is much shorter than its neighbours.
The points depend on the segment and the density alone, so that two tiles
that share an edge and walk it in the same direction find the same points,
bit for bit. A horizontal or vertical segment's points lie exactly on it.
A density that is negative, NaN or above `most` (a function that misbehaves
on the border alone, which the sampler never saw) throws
std::invalid_argument at once, before the walk places billions of points.
*/
template <class Density, class Add>
void for_each_edge_point(double ax, double ay, double bx, double by, const Density& points_per_unit_area, double most,
                         Add&& add)
{
  const double length = std::hypot(bx - ax, by - ay);
  if(!(length > 0.)) return;
  auto at = [&](double u) { return std::make_pair(ax + u * (bx - ax), ay + u * (by - ay)); };
  auto per_length = [&](double u) {  // spacings per unit length
    const auto [x, y] = at(u);
    const double rho = points_per_unit_area(x, y);
    if(!(rho >= 0. && rho <= most)) {
      std::ostringstream m;
      m.precision(17);
      m << "the density on the border at (" << x << ", " << y << ") is " << rho << " points per unit area once scaled: ";
      m.precision(3);
      if(std::isfinite(rho) && rho > 0.) m << "more than the " << most << " that the sampler could represent here";
      else m << "it must be finite and non-negative";
      throw std::invalid_argument(m.str());
    }
    return rho > 0. ? 1. / sample_spacing(rho) : 0.;
  };
  // The integral by the trapezoid rule, in steps of at most a quarter spacing
  // and a 256th of the segment, at least 2^-20 of it.
  std::vector<std::pair<double, double>> walk{{0., 0.}};  // (u, spacings from a)
  double f = per_length(0.);
  for(double u = 0.; u < 1.;) {
    double du = 1. / 256.;
    if(f > 0.) du = (std::min)(du, 0.25 / (f * length));
    du = (std::min)(1. - u, (std::max)(du, 1. / 1048576.));
    const double next = u + du, g = per_length(next);
    walk.emplace_back(next, walk.back().second + 0.5 * (f + g) * du * length);
    u = next;
    f = g;
  }
  const double total = walk.back().second;
  if(!(total < 4e9)) return;  // NaN or beyond what the sampler can place, which it refuses
  const long parts = (std::max)(1L, std::lround(total));
  std::size_t step = 1;
  for(long k = 1; k < parts; ++k) {
    const double target = total * double(k) / double(parts);
    while(walk[step].second < target) ++step;
    const auto& [u0, c0] = walk[step - 1];
    const auto& [u1, c1] = walk[step];
    const double u = u0 + (u1 - u0) * (target - c0) / (c1 - c0);
    const auto [x, y] = at(u);
    add(x, y);
  }
}

// Whether (x, y) lies on the border of region = {x0, y0, x1, y1}.
inline bool is_on_border(const std::array<double, 4>& region, double x, double y)
{
  return x == region[0] || y == region[1] || x == region[2] || y == region[3];
}

/*
The points along the border of region = {x0, y0, x1, y1}: its corners and
the points of its sides (see for_each_edge_point()), each side walked from
west to east or from south to north, so that a rectangle that shares a side
with this one has the same points there. The density may reach 10^12 / L^2
points per unit area, L the region's longer side: the sampler represents
about 4 x 10^11 / L^2 at most.
*/
class Border
{
public:
  template <class Density>
  Border(const std::array<double, 4>& region, const Density& points_per_unit_area) : region_(region)
  {
    const double x0 = region[0], y0 = region[1], x1 = region[2], y1 = region[3];
    const double ends[4][4] = {{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x0, y1, x1, y1}, {x0, y0, x0, y1}};
    const double longer = (std::max)(x1 - x0, y1 - y0), most = 1e12 / (longer * longer);
    for(int s = 0; s < 4; ++s) {
      std::vector<double>& p = side_[std::size_t(s)];
      const double* e = ends[s];
      p.push_back(s % 2 == 0 ? e[0] : e[1]);
      for_each_edge_point(e[0], e[1], e[2], e[3], points_per_unit_area, most,
                          [&p, s](double x, double y) { p.push_back(s % 2 == 0 ? x : y); });
      p.push_back(s % 2 == 0 ? e[2] : e[3]);
    }
  }

  /*
  Adds points to the sides where the linear interpolation of `height(x, y)`
  between their points misses it by more than `max_error` at one of the
  abscissas (bottom and top sides) or ordinates (right and left) `at[0]` or
  `at[1]`, sorted: the worst of a side's edge first, then again on either
  half (greedy insertion along the side, as that of a terrain's cells). `at`
  depends on the region alone (the centres of a raster's cells), so that two
  tiles that share a side find the same points there.
  */
  template <class Height>
  void fit(const Height& height, double max_error, const std::array<std::vector<double>, 2>& at)
  {
    for(int s = 0; s < 4; ++s) {
      const std::vector<double>& t = at[std::size_t(s % 2)];
      const double across = s == 0 ? region_[1] : s == 1 ? region_[2] : s == 2 ? region_[3] : region_[0];
      auto h = [&](double along) { return s % 2 == 0 ? height(along, across) : height(across, along); };
      std::vector<double>& p = side_[std::size_t(s)];
      const auto first = std::upper_bound(t.begin(), t.end(), p.front());
      const auto last = std::lower_bound(first, t.end(), p.back());
      std::vector<double> heights;  // at t in (p.front(), p.back())
      for(auto u = first; u != last; ++u) heights.push_back(h(*u));
      std::vector<double> fitted{p.front()};
      // the edges still to fit, as pairs of positions, the next one last
      std::vector<std::pair<double, double>> todo;
      for(std::size_t k = p.size() - 1; k > 0; --k) todo.emplace_back(p[k - 1], p[k]);
      while(!todo.empty()) {
        const auto [a, b] = todo.back();
        todo.pop_back();
        const double ha = h(a), hb = h(b);
        double worst = max_error;
        auto split = last;
        for(auto u = std::upper_bound(first, last, a); u != last && *u < b; ++u) {
          const double e = std::abs(heights[std::size_t(u - first)] - (ha + (hb - ha) * (*u - a) / (b - a)));
          if(e > worst) {
            worst = e;
            split = u;
          }
        }
        if(split == last) {
          fitted.push_back(b);
          continue;
        }
        todo.emplace_back(*split, b);
        todo.emplace_back(a, *split);
      }
      p.swap(fitted);
    }
  }

  // Calls `add(x, y)` for the four corners, then for the points inside the
  // bottom, right, top and left sides.
  template <class Add>
  void for_each_point(Add add) const
  {
    const double x0 = region_[0], y0 = region_[1], x1 = region_[2], y1 = region_[3];
    add(x0, y0);
    add(x1, y0);
    add(x1, y1);
    add(x0, y1);
    for(int s = 0; s < 4; ++s) {
      const std::vector<double>& p = side_[std::size_t(s)];
      for(std::size_t k = 1; k + 1 < p.size(); ++k)
        if(s % 2 == 0) add(p[k], s == 0 ? y0 : y1);
        else add(s == 1 ? x1 : x0, p[k]);
    }
  }

  /*
  Whether a sample at (x, y), `spacing` away from its neighbours, lies closer
  to a side than border_clearance times the smaller of `spacing` and the
  length of the side's edge beside it (between the border points on either
  side of its foot): it would make a sliver with that edge. A long edge
  alone does not count, where the density is higher inside than on the
  border: the border's refinement splits it.
  */
  bool is_near(double x, double y, double spacing) const
  {
    const double inward[4] = {y - region_[1], region_[2] - x, region_[3] - y, x - region_[0]};
    for(int s = 0; s < 4; ++s) {
      if(inward[s] <= 0.) return true;  // on the border: a window's closed side
      if(!(inward[s] < border_clearance * spacing)) continue;
      const std::vector<double>& p = side_[std::size_t(s)];
      auto next = std::upper_bound(p.begin(), p.end(), s % 2 == 0 ? x : y);
      if(next == p.end()) --next;
      if(next == p.begin()) ++next;
      if(inward[s] < border_clearance * (*next - *(next - 1))) return true;
    }
    return false;
  }

private:
  std::array<double, 4> region_;
  // the positions of the points of each side, corners included, in increasing
  // order: their abscissas (bottom, top) or ordinates (right, left)
  std::array<std::vector<double>, 4> side_;
};

/*
Removes from the triangulation `t` the vertices of `samples` that lie near
`border` (see Border::is_near()), their spacing the mean length of their
edges, and from `samples`, which keeps the others in their order. The
spacing so measured needs no evaluation of the density (a Python function's
costs a call a point).
*/
template <class Triangulation>
void remove_samples_near_border(Triangulation& t, std::vector<typename Triangulation::Vertex_handle>& samples,
                                const Border& border)
{
  std::size_t kept = 0;
  for(const auto v : samples) {
    const double x = v->point().x(), y = v->point().y();
    double length = 0.;
    int edges = 0;
    auto w = t.incident_vertices(v), done = w;
    if(w != nullptr) do
      if(!t.is_infinite(w)) {
        length += std::hypot(w->point().x() - x, w->point().y() - y);
        ++edges;
      }
    while(++w != done);
    if(edges && border.is_near(x, y, length / edges)) t.remove(v);
    else samples[kept++] = v;
  }
  samples.resize(kept);
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_BORDER_POINTS_H
