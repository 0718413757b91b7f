// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bars of the sampler, each measured against a reference in the same
// process:
//   sampler_benchmark speed [N=1e6] [runs=5]   sampling time / CGAL range insertion time
//   sampler_benchmark memory [N=1e6]           peak resident bytes per output point
//   sampler_benchmark scaling                  ns per point at 1e5 and 4e6
//   sampler_benchmark quality [N=65536] [corrections=1] [densities=21]
//                                              delta_min, delta_avg, anisotropy over one level

#include <CGAL/Penrose_importance_sampler.h>
#include "point_set_quality.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "benchmark_support.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Penrose_importance_sampler<K> Sampler;
namespace Q = Penrose_quality;

using benchmark_support::median;
using benchmark_support::now;

static std::vector<K::Point_2> sample(double n, double* seconds = nullptr, bool correct = true)
{
  const K::Iso_rectangle_2 unit(0, 0, 1, 1);
  std::vector<K::Point_2> p;
  const double t0 = now();
  Sampler s(unit, [](const K::Point_2&) { return 1.; },
            CGAL::parameters::use_correction_vectors(correct, benchmark_support::sampling_parameters(n)));
  p.reserve(std::size_t(s.expected_number_of_points() * 1.02));
  s(std::back_inserter(p));
  if(seconds) *seconds = now() - t0;
  return p;
}

static int speed(double n, int runs)
{
  std::vector<double> ratio, ts, tc;
  for(int r = 0; r < runs; ++r) {
    double t;
    const std::vector<K::Point_2> p = sample(n, &t);
    const double t0 = now();
    CGAL::Delaunay_triangulation_2<K> dt;
    dt.insert(p.begin(), p.end());
    const double tcgal = now() - t0;
    ts.push_back(t); tc.push_back(tcgal); ratio.push_back(t / tcgal);
    std::cout << "run " << r << ": " << p.size() << " points, sampling " << t << " s, CGAL insertion "
              << tcgal << " s, ratio " << t / tcgal << "\n";
  }
  std::cout << "median: sampling " << median(ts) << " s, CGAL " << median(tc) << " s, ratio "
            << median(ratio) << "\n";
  return 0;
}

static int memory(double n)
{
  const std::vector<K::Point_2> p = sample(n);
  const double peak = benchmark_support::peak_resident_bytes();
  std::cout << p.size() << " points, peak resident " << peak << " bytes, "
            << peak / p.size() << " bytes per point\n";
  return 0;
}

static int scaling()
{
  double per[2];
  const double sizes[2] = {1e5, 4e6};
  for(int i = 0; i < 2; ++i) {
    std::vector<double> t;
    std::size_t count = 0;
    for(int r = 0; r < 5; ++r) { double s; count = sample(sizes[i], &s).size(); t.push_back(s); }
    per[i] = median(t) / count * 1e9;
    std::cout << count << " points: " << per[i] << " ns per point (median of 5)\n";
  }
  std::cout << "ratio 4e6 / 1e5: " << per[1] / per[0] << "\n";
  return 0;
}

static int quality(double n, bool correct, int densities)
{
  // densities spread over one factor phi^2, as the importance index runs
  const double phi2 = 2.6180339887498949;
  double worst = 1e9, mean_avg = 0., mean_aniso = 0.;
  for(int k = 0; k < densities; ++k) {
    const double target = n * std::pow(phi2, (k + 0.5) / densities);
    const std::vector<K::Point_2> p = sample(target, nullptr, correct);
    const Q::Spacing s = Q::spacing(p, Q::Rectangle{0, 0, 1, 1});
    const double w = std::sqrt(4096. / p.size());  // a window of about 4096 points
    const Q::Radial_spectrum sp = Q::radial_power_spectrum(p, 0.5 - w / 2, 0.5 - w / 2, w, 64, 32);
    double aniso = 0.;
    int m = 0;
    for(std::size_t i = 0; i < sp.frequency.size(); ++i)
      if(sp.frequency[i] > 16) { aniso += sp.anisotropy_db[i]; ++m; }
    aniso /= m;
    worst = std::min(worst, s.delta_min);
    mean_avg += s.delta_avg / densities;
    mean_aniso += aniso / densities;
    std::cout << "density " << k << ": " << p.size() << " points, delta_min " << s.delta_min
              << ", delta_avg " << s.delta_avg << ", anisotropy " << aniso << " dB\n";
  }
  std::cout << "worst delta_min " << worst << ", mean delta_avg " << mean_avg
            << ", mean anisotropy " << mean_aniso << " dB\n";
  return 0;
}

int main(int argc, char** argv)
{
  const std::string mode = argc > 1 ? argv[1] : "speed";
  const double n = argc > 2 ? std::atof(argv[2]) : 0.;
  if(mode == "speed") return speed(n > 0 ? n : 1e6, argc > 3 ? std::atoi(argv[3]) : 5);
  if(mode == "memory") return memory(n > 0 ? n : 1e6);
  if(mode == "scaling") return scaling();
  if(mode == "quality")
    return quality(n > 0 ? n : 65536, argc > 3 ? std::atoi(argv[3]) != 0 : true, argc > 4 ? std::atoi(argv[4]) : 21);
  std::cerr << "usage: sampler_benchmark speed|memory|scaling|quality [N] [runs|corrections] [densities]\n";
  return 2;
}
