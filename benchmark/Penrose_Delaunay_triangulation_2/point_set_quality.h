// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Measures of how well a 2D point set is spread: normalised nearest-neighbour
// distances (Lagae and Dutre 2008), coverage, and the radially averaged power
// spectrum with its anisotropy, for the benchmarks and the tests; a fixed
// kernel, Epick, is enough for that.

#ifndef PENROSE_BENCHMARK_POINT_SET_QUALITY_H
#define PENROSE_BENCHMARK_POINT_SET_QUALITY_H

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace Penrose_quality {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> Delaunay;

/// An axis-parallel rectangle: the window measured.
struct Rectangle
{
  double xmin; ///< west
  double ymin; ///< south
  double xmax; ///< east
  double ymax; ///< north
  /// Its area.
  double area() const { return (xmax - xmin) * (ymax - ymin); }
};

/// What `spacing()` measures, distances in units of `d_max` (Lagae and Dutre 2008).
struct Spacing
{
  double d_max;      ///< sqrt(2 A / (sqrt(3) N)): the spacing of a hexagonal packing
  double delta_min;  ///< smallest nearest-neighbour distance over d_max
  double delta_avg;  ///< mean nearest-neighbour distance over d_max
  std::size_t measured; ///< points farther than 2 d_max from the border
};

/// The spacing of `n` points in a hexagonal packing of `area`: sqrt(2 `area` / (sqrt(3) `n`)).
inline double packing_distance(std::size_t n, double area)
{
  return std::sqrt(2. * area / (std::sqrt(3.) * double(n)));
}

/// Nearest-neighbour statistics of `points` (anything with `x()` and `y()`)
/// in `r`, ignoring a band of 2 d_max along the border.
template <class PointRange>
Spacing spacing(const PointRange& points, const Rectangle& r)
{
  std::vector<K::Point_2> p;
  for(const auto& q : points) p.emplace_back(q.x(), q.y());
  Spacing s{packing_distance(p.size(), r.area()), 0., 0., 0};
  Delaunay dt(p.begin(), p.end());
  const double band = 2. * s.d_max;
  double mn = std::numeric_limits<double>::infinity(), sum = 0.;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const K::Point_2& a = v->point();
    if(a.x() < r.xmin + band || a.x() > r.xmax - band || a.y() < r.ymin + band || a.y() > r.ymax - band)
      continue;
    double nn = std::numeric_limits<double>::infinity();
    auto w = dt.incident_vertices(v), done = w;
    do {
      if(!dt.is_infinite(w)) nn = (std::min)(nn, CGAL::squared_distance(a, w->point()));
    } while(++w != done);
    nn = std::sqrt(nn);
    mn = (std::min)(mn, nn);
    sum += nn;
    ++s.measured;
  }
  s.delta_min = mn / s.d_max;
  s.delta_avg = s.measured ? sum / double(s.measured) / s.d_max : 0.;
  return s;
}

/// Radius of the largest empty circle centred in `r`, over d_max. Voronoi
/// vertices inside `r` are exact; the border is scanned in steps of d_max / 64.
template <class PointRange>
double coverage_radius(const PointRange& points, const Rectangle& r)
{
  std::vector<K::Point_2> p;
  for(const auto& q : points) p.emplace_back(q.x(), q.y());
  const double d_max = packing_distance(p.size(), r.area());
  Delaunay dt(p.begin(), p.end());
  double best = 0.;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const K::Point_2 c = dt.circumcenter(f);
    if(c.x() >= r.xmin && c.x() <= r.xmax && c.y() >= r.ymin && c.y() <= r.ymax)
      best = (std::max)(best, CGAL::squared_distance(c, f->vertex(0)->point()));
  }
  const double step = d_max / 64.;
  auto scan = [&](double x0, double y0, double x1, double y1) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int n = int(std::ceil(len / step));
    Delaunay::Vertex_handle hint;
    for(int i = 0; i <= n; ++i) {
      const K::Point_2 q(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n);
      hint = dt.nearest_vertex(q, hint == Delaunay::Vertex_handle() ? Delaunay::Face_handle() : hint->face());
      best = (std::max)(best, CGAL::squared_distance(q, hint->point()));
    }
  };
  scan(r.xmin, r.ymin, r.xmax, r.ymin);
  scan(r.xmax, r.ymin, r.xmax, r.ymax);
  scan(r.xmax, r.ymax, r.xmin, r.ymax);
  scan(r.xmin, r.ymax, r.xmin, r.ymin);
  return std::sqrt(best) / d_max;
}

/// What `radial_power_spectrum()` measures: one entry per ring that holds
/// at least two frequencies.
struct Radial_spectrum
{
  std::vector<double> frequency;      ///< the ring's middle, in units of 1/w
  std::vector<double> power;          ///< the mean power over the ring, 1 for white noise
  std::vector<double> anisotropy_db;  ///< the variance of the power over its squared mean, in dB
};

/// Radially averaged periodogram of `points` (anything with `x()` and
/// `y()`) in the square window [x0, x0 + w]^2, on `rings` rings of
/// frequency up to `max_frequency` (in units of 1/w), with the anisotropy
/// of each ring.
template <class PointRange>
Radial_spectrum radial_power_spectrum(const PointRange& points, double x0, double y0, double w,
                                      int max_frequency, int rings)
{
  std::vector<std::pair<double, double>> p;
  for(const auto& q : points) {
    const double x = (q.x() - x0) / w, y = (q.y() - y0) / w;
    if(x >= 0 && x < 1 && y >= 0 && y < 1) p.emplace_back(x, y);
  }
  const int n = max_frequency;
  std::vector<double> sum(rings, 0.), sum2(rings, 0.);
  std::vector<int> count(rings, 0);
  const double two_pi = 6.283185307179586;
  // exp(-2 pi i (fx x + fy y)) built by repeated products, one row at a time
  std::vector<std::complex<double>> ex(p.size()), row(p.size());
  for(std::size_t k = 0; k < p.size(); ++k) ex[k] = std::polar(1., -two_pi * p[k].first);
  for(int fy = -n; fy <= n; ++fy) {
    for(std::size_t k = 0; k < p.size(); ++k)
      row[k] = std::polar(1., -two_pi * (fy * p[k].second - n * p[k].first));
    for(int fx = -n; fx <= n; ++fx) {
      std::complex<double> s = 0.;
      for(std::size_t k = 0; k < p.size(); ++k) { s += row[k]; row[k] *= ex[k]; }
      const double f = std::hypot(double(fx), double(fy));
      const int ring = int(f / n * rings);
      if(ring >= rings || (fx == 0 && fy == 0)) continue;
      const double pw = std::norm(s) / double(p.size());
      sum[ring] += pw; sum2[ring] += pw * pw; ++count[ring];
    }
  }
  Radial_spectrum out;
  for(int i = 0; i < rings; ++i) {
    if(count[i] < 2) continue;
    const double mean = sum[i] / count[i];
    const double var = sum2[i] / count[i] - mean * mean;
    out.frequency.push_back((i + 0.5) * n / rings);
    out.power.push_back(mean);
    out.anisotropy_db.push_back(10. * std::log10((std::max)(var, 1e-300) / (mean * mean)));
  }
  return out;
}

} // namespace Penrose_quality

#endif // PENROSE_BENCHMARK_POINT_SET_QUALITY_H
