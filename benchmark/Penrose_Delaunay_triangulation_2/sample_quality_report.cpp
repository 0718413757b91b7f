// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality of one point set: normalised spacing, the radially averaged
// power spectrum with its anisotropy, the histogram of the Delaunay
// triangles' minimum angles, and the per-cell density error.
//
//   sample_quality_report DENSITY N CORRECTION OUT_PREFIX
//   DENSITY: constant | ramp; CORRECTION: 1 or 0
// writes OUT_PREFIX_summary.txt, OUT_PREFIX_spectrum.csv (frequency, power,
// anisotropy_db), OUT_PREFIX_angles.csv (degrees, fraction) and
// OUT_PREFIX_cells.csv (i, j, count, expected).

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include "point_set_quality.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
namespace Q = Penrose_quality;

int main(int argc, char** argv)
{
  if(argc < 5) {
    std::cerr << "usage: sample_quality_report constant|ramp N CORRECTION(1|0) OUT_PREFIX\n";
    return 2;
  }
  const std::string density = argv[1], prefix = argv[4];
  const std::size_t n = std::strtoul(argv[2], nullptr, 10);
  const bool correct = std::atoi(argv[3]) != 0;
  std::function<double(const Point&)> d;
  if(density == "ramp") d = [](const Point& p) { return p.x(); };
  else d = [](const Point&) { return 1.; };
  const CGAL::Penrose_importance_sampler<K> sampler(K::Iso_rectangle_2(0, 0, 1, 1), d,
    CGAL::parameters::use_correction_vectors(correct, CGAL::parameters::number_of_output_points(n)));
  const CGAL::Penrose_Delaunay_triangulation_2<K> dt(sampler);
  std::vector<Point> points;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) points.push_back(v->point());

  const Q::Rectangle unit{0, 0, 1, 1};
  const Q::Spacing s = Q::spacing(points, unit);

  // spectrum: the mean of the periodograms of 4 x 4 windows of about 4096 points each
  const double w = std::sqrt(4096. / points.size());
  Q::Radial_spectrum mean;
  int windows = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) {
      const double x0 = 0.05 + i * (0.9 - w) / 3., y0 = 0.05 + j * (0.9 - w) / 3.;
      const Q::Radial_spectrum r = Q::radial_power_spectrum(points, x0, y0, w, 96, 48);
      if(windows++ == 0) { mean = r; continue; }
      for(std::size_t k = 0; k < r.power.size(); ++k) {
        mean.power[k] += r.power[k];
        mean.anisotropy_db[k] += r.anisotropy_db[k];
      }
    }
  for(std::size_t k = 0; k < mean.power.size(); ++k) { mean.power[k] /= windows; mean.anisotropy_db[k] /= windows; }
  std::ofstream spectrum(prefix + "_spectrum.csv");
  spectrum << "frequency,power,anisotropy_db\n";
  double anisotropy = 0.;
  int rings = 0;
  for(std::size_t k = 0; k < mean.power.size(); ++k) {
    spectrum << mean.frequency[k] << ',' << mean.power[k] << ',' << mean.anisotropy_db[k] << '\n';
    if(mean.frequency[k] > 16.) { anisotropy += mean.anisotropy_db[k]; ++rings; }
  }
  anisotropy /= rings;

  // minimum angles of the Delaunay triangles, 1-degree bins; as for the
  // spacing, triangles within 2 d_max of the border (the hull's slivers) are left out
  std::vector<double> histogram(61, 0.);
  double smallest = 180.;
  std::size_t faces = 0;
  const double band = 2. * s.d_max;
  auto inside = [band](const Point& p) { return p.x() > band && p.x() < 1 - band && p.y() > band && p.y() < 1 - band; };
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    if(!inside(f->vertex(0)->point()) || !inside(f->vertex(1)->point()) || !inside(f->vertex(2)->point())) continue;
    double m = 180.;
    for(int i = 0; i < 3; ++i) {
      const Point& a = f->vertex(i)->point();
      const Point& b = f->vertex((i + 1) % 3)->point();
      const Point& c = f->vertex((i + 2) % 3)->point();
      const double u = std::atan2(b.y() - a.y(), b.x() - a.x()), v = std::atan2(c.y() - a.y(), c.x() - a.x());
      double angle = std::abs(u - v) * 180. / M_PI;
      if(angle > 180.) angle = 360. - angle;
      m = std::min(m, angle);
    }
    smallest = std::min(smallest, m);
    histogram[std::min(60, int(m))] += 1.;
    ++faces;
  }
  std::ofstream angles(prefix + "_angles.csv");
  angles << "degrees,fraction\n";
  for(int k = 0; k <= 60; ++k) angles << k + 0.5 << ',' << histogram[k] / double(faces) << '\n';

  // density per cell of a 16 x 16 grid against the integral of the scaled density
  const int g = 16;
  std::vector<double> count(g * g, 0.);
  for(const Point& p : points) count[std::min(g - 1, int(p.y() * g)) * g + std::min(g - 1, int(p.x() * g))] += 1.;
  std::ofstream cells(prefix + "_cells.csv");
  cells << "i,j,count,expected\n";
  double err = 0., norm = 0.;
  for(int j = 0; j < g; ++j)
    for(int i = 0; i < g; ++i) {
      const double x0 = double(i) / g, x1 = double(i + 1) / g;
      const double e = sampler.density_scale() / g * (density == "ramp" ? (x1 * x1 - x0 * x0) / 2. : (x1 - x0));
      cells << i << ',' << j << ',' << count[j * g + i] << ',' << e << '\n';
      err += (count[j * g + i] - e) * (count[j * g + i] - e);
      norm += e * e;
    }

  std::ostringstream summary;
  summary << "density " << density << ", " << points.size() << " points, correction " << (correct ? "on" : "off") << "\n"
          << "delta_min " << s.delta_min << "\ndelta_avg " << s.delta_avg << "\n"
          << "anisotropy_db (mean over rings above 16/w) " << anisotropy << "\n"
          << "smallest_triangle_angle_deg (away from the border) " << smallest << "\n"
          << "cell_density_relative_l2_error " << std::sqrt(err / norm) << "\n";
  std::ofstream(prefix + "_summary.txt") << summary.str();
  std::cout << summary.str();
  return 0;
}
