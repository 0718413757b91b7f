// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bars of Penrose_Delaunay_triangulation_2, each against CGAL in the same
// process and on the same points, with Sequential_tag, or with Parallel_tag
// on at most T threads (tbb::global_control) after `--threads T`:
//   triangulation_benchmark [--threads T] MODE ...
//   triangulation_benchmark speed [N=1e6] [constant|ramp] [runs=5]
//       Penrose_Delaunay_triangulation_2 built from a sampler (it walks the
//       tile tree itself: sampling and triangulation in one pass), against
//       CGAL::Delaunay_triangulation_2 range insertion (spatial sort + insert)
//       and Triangulation_hierarchy_2 fed one point at a time in sampler order;
//       prints the medians and the ratios that the speed bars are about
//   triangulation_benchmark memory penrose|cgal [N=1e6]
//       peak resident bytes per point of one construction (run each in its own process)
//   triangulation_benchmark scaling [constant|ramp]
//       ns per point at 1e5 and 4e6, five constructions of each in this process
//   triangulation_benchmark once [N=1e6] [constant|ramp] [penrose|cgal]
//       ns per point of a single construction, the Penrose DT's (sampling
//       included) or CGAL's range insertion of the same points (sampling not
//       timed); run it in a loop for fresh processes, where no run inherits
//       the allocator's warm pages
//   triangulation_benchmark stages [N=1e6] [constant|ramp] [runs=5]
//       ms spent in each step of the construction (sampling included),
//       medians over the runs in this process, told apart by the advancement
//       that build()'s callback reports at the end of each step
//   triangulation_benchmark check [N=1e6] [constant|ramp|image|terrain] [IMAGE=data/test_image.png]
//       the tests' correctness checks at the bars' sizes, which the tests do
//       not reach, on the inputs of Figure 8: is_valid(), no more fallbacks
//       than 0.1% of the vertices, and every edge that of
//       CGAL::Delaunay_triangulation_2 and of Triangulation_hierarchy_2 on
//       the same points; exits 1 otherwise

#include <CGAL/Penrose_Delaunay_triangulation_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "benchmark_support.h"
#include "figure8_inputs.h"

#if defined(CGAL_LINKED_WITH_TBB)
#  include <tbb/global_control.h>
#endif

#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Penrose_importance_sampler<K> Sampler;
template <class ConcurrencyTag>
using Penrose_dt = CGAL::Penrose_Delaunay_triangulation_2<K, CGAL::Default, ConcurrencyTag>;
typedef CGAL::Delaunay_triangulation_2<K> Dt;
typedef benchmark_support::Hierarchy<K> Hierarchy;
using benchmark_support::median;
using benchmark_support::now;

// a number of points: at least 1, at most the sampler's maximum_number below
static bool is_size(const std::string& n)
{
  char* end = nullptr;
  const double v = std::strtod(n.c_str(), &end);
  return end != n.c_str() && *end == '\0' && v >= 1. && v <= 1e9;
}

template <class Pdt>
static int speed(double n, const std::string& input, int runs)
{
  std::vector<double> tp, ts, tc, th;
  for(int r = 0; r < runs; ++r) {
    const Sampler sampler = benchmark_support::unit_square_sampler<K>(input, n);
    double t0 = now();
    std::vector<Point> points;
    points.reserve(std::size_t(sampler.expected_number_of_points() * 1.05));
    sampler(std::back_inserter(points));
    ts.push_back(now() - t0);

    t0 = now();
    Pdt pdt(sampler);
    tp.push_back(now() - t0);

    t0 = now();
    Dt dt;
    dt.insert(points.begin(), points.end());
    tc.push_back(now() - t0);

    if(r < 3) {
      t0 = now();
      Hierarchy h;
      for(const Point& p : points) h.insert(p);
      th.push_back(now() - t0);
    }
    std::cout << "run " << r << ": " << points.size() << " points; sampling " << ts.back() << " s, Penrose DT "
              << tp.back() << " s (" << pdt.number_of_flips() << " flips, " << pdt.number_of_fallbacks()
              << " fallbacks), CGAL range insertion " << tc.back() << " s";
    if(r < 3) std::cout << ", hierarchy one by one " << th.back() << " s";
    std::cout << "\n";
    if(pdt.number_of_vertices() != dt.number_of_vertices()) { std::cerr << "vertex counts differ\n"; return 1; }
  }
  const double c = median(tc);
  std::cout << input << " " << n << ": medians: sampling " << median(ts) << " s, Penrose DT " << median(tp)
            << " s, CGAL range insertion " << c << " s, hierarchy " << median(th) << " s\n"
            // the construction samples as it goes: the triangulation alone is its time less the sampler's
            << "ratios to CGAL range insertion: sampling " << median(ts) / c << ", end to end (Penrose DT) "
            << median(tp) / c << " (bar 0.5), triangulation alone " << (median(tp) - median(ts)) / c
            << " (bar 0.3); hierarchy / Penrose DT " << median(th) / median(tp) << " (paper: at least 2)\n";
  return 0;
}

// CGAL's range insertion (spatial sort and insert) of the sampler's points:
// returns the number of vertices, and the time of the insertion alone in
// `seconds`.
static std::size_t triangulate_with_cgal(const Sampler& sampler, double& seconds)
{
  std::vector<Point> points;
  sampler(std::back_inserter(points));
  const double t0 = now();
  Dt dt;
  dt.insert(points.begin(), points.end());
  seconds = now() - t0;
  return dt.number_of_vertices();
}

template <class Pdt>
static int memory(const std::string& which, double n)
{
  const Sampler sampler = benchmark_support::unit_square_sampler<K>("constant", n);
  std::size_t count = 0;
  if(which == "penrose") {
    Pdt pdt(sampler);
    count = pdt.number_of_vertices();
  } else {
    double seconds;
    count = triangulate_with_cgal(sampler, seconds);
  }
  const double peak = benchmark_support::peak_resident_bytes();
  std::cout << which << ": " << count << " points, peak resident " << peak << " bytes, "
            << peak / count << " bytes per point\n";
  return 0;
}

template <class Pdt>
static int scaling(const std::string& input)
{
  const double sizes[2] = {1e5, 4e6};
  double per[2];
  for(int i = 0; i < 2; ++i) {
    std::vector<double> t;
    std::size_t count = 0;
    for(int r = 0; r < 5; ++r) {
      const Sampler sampler = benchmark_support::unit_square_sampler<K>(input, sizes[i]);
      const double t0 = now();
      Pdt pdt(sampler);
      t.push_back(now() - t0);
      count = pdt.number_of_vertices();
    }
    per[i] = median(t) / count * 1e9;
    std::cout << count << " points: " << per[i] << " ns per point (median of 5)\n";
  }
  std::cout << "ratio 4e6 / 1e5: " << per[1] / per[0] << "\n";
  return 0;
}

// The steps of the construction, each with the advancement that its end
// reports (Triangulation_construction.h; the base mesh's own end is not
// reported apart); the last one ends with build().
struct Step
{
  const char* name;
  double ends_at;
};
static const Step steps[] = {{"base mesh (sampling included), vertices that are no samples removed", 0.61},
                             {"moves to the corrected positions", 0.66},
                             {"Lawson flips (TDS reserved beside them)", 0.84},
                             {"writing the TDS", 0.99},
                             {"fallbacks and removal of the frame", 1.}};

template <class Pdt>
static int stages(double n, const std::string& input, int runs)
{
  constexpr std::size_t count = sizeof(steps) / sizeof(steps[0]);
  std::vector<std::vector<double>> ms(count);
  std::vector<double> total;
  const Sampler sampler = benchmark_support::unit_square_sampler<K>(input, n);
  for(int r = 0; r < runs; ++r) {
    std::vector<double> end(count, 0.);
    std::size_t step = 0;
    const double t0 = now();
    const std::function<bool(double)> callback = [&](double advancement) {
      // the first report at or past a step's end is that step's end
      for(; step < count && advancement >= steps[step].ends_at; ++step) end[step] = now();
      return true;
    };
    Pdt pdt;
    pdt.build(sampler, [](double x, double y) { return Point(x, y); },
              [](typename Pdt::Vertex_handle, const Sampler::Sample&) {}, CGAL::parameters::callback(callback));
    total.push_back((now() - t0) * 1e3);
    for(std::size_t i = 0; i < count; ++i) ms[i].push_back((end[i] - (i == 0 ? t0 : end[i - 1])) * 1e3);
  }
  for(std::size_t i = 0; i < count; ++i) std::cout << steps[i].name << ": " << median(ms[i]) << " ms\n";
  std::cout << "construction: " << median(total) << " ms (median of " << runs << ")\n";
  return 0;
}

template <class Pdt>
static int once(double n, const std::string& input, const std::string& method)
{
  const Sampler sampler = benchmark_support::unit_square_sampler<K>(input, n);
  double t = 0.;
  std::size_t count = 0;
  if(method == "penrose") {
    const double t0 = now();
    Pdt pdt(sampler);
    t = now() - t0;
    count = pdt.number_of_vertices();
  } else {
    count = triangulate_with_cgal(sampler, t);
  }
  std::cout << input << " " << count << " points: " << t / count * 1e9 << " ns per point (" << method << ")\n";
  return 0;
}

// Whether `t` has the same number of finite edges as `pdt`, and each edge of
// `pdt` between the same two points. Each vertex of `t` is found by its point
// (the sampler's points are distinct), each edge by Triangulation_2::is_edge().
template <class Pdt, class Triangulation>
static bool has_the_edges_of(const Pdt& pdt, const Triangulation& t)
{
  if(t.number_of_vertices() != pdt.number_of_vertices()) return false;
  auto hash = [](const Point& p) { return std::hash<double>()(p.x()) ^ (std::hash<double>()(p.y()) * 31); };
  std::unordered_map<Point, typename Triangulation::Vertex_handle, decltype(hash)> vertex_at(t.number_of_vertices(), hash);
  for(auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) vertex_at.emplace(v->point(), v);
  std::size_t edges = 0;
  for(auto e = pdt.finite_edges_begin(); e != pdt.finite_edges_end(); ++e, ++edges) {
    const auto a = vertex_at.find(e->first->vertex(pdt.cw(e->second))->point());
    const auto b = vertex_at.find(e->first->vertex(pdt.ccw(e->second))->point());
    if(a == vertex_at.end() || b == vertex_at.end() || !t.is_edge(a->second, b->second)) return false;
  }
  return edges == std::size_t(std::distance(t.finite_edges_begin(), t.finite_edges_end()));
}

template <class Pdt>
static int check(double n, const std::string& input, const std::string& image)
{
  const Sampler sampler = benchmark_support::figure8_sampler<K>(input, n, image);
  const Pdt pdt(sampler);
  std::vector<Point> points;
  sampler(std::back_inserter(points));
  const Dt dt(points.begin(), points.end());
  Hierarchy hierarchy;
  for(const Point& p : points) hierarchy.insert(p);
  const bool valid = pdt.is_valid();
  const bool few_fallbacks = double(pdt.number_of_fallbacks()) <= 0.001 * double(pdt.number_of_vertices());
  const bool as_dt = has_the_edges_of(pdt, dt), as_hierarchy = has_the_edges_of(pdt, hierarchy);
  std::cout << input << " " << n << ": " << pdt.number_of_vertices() << " vertices, " << pdt.number_of_faces()
            << " faces, " << pdt.number_of_flips() << " flips, " << pdt.number_of_fallbacks() << " fallbacks; "
            << "is_valid() " << (valid ? "yes" : "NO") << ", edges of Delaunay_triangulation_2 "
            << (as_dt ? "yes" : "NO") << ", of Triangulation_hierarchy_2 " << (as_hierarchy ? "yes" : "NO") << "\n";
  return valid && few_fallbacks && as_dt && as_hierarchy ? 0 : 1;
}

// The mode of the command line `argv`, with the Penrose DT `Pdt`.
template <class Pdt>
static int run(int argc, char** argv)
{
  const std::string mode = argc > 1 ? argv[1] : "speed";
  auto arg = [&](int i, const char* otherwise) { return std::string(argc > i ? argv[i] : otherwise); };
  if(mode == "speed") return speed<Pdt>(std::atof(arg(2, "1e6").c_str()), arg(3, "constant"), std::atoi(arg(4, "5").c_str()));
  if(mode == "memory") return memory<Pdt>(arg(2, "penrose"), std::atof(arg(3, "1e6").c_str()));
  if(mode == "scaling") return scaling<Pdt>(arg(2, "constant"));
  if(mode == "stages") return stages<Pdt>(std::atof(arg(2, "1e6").c_str()), arg(3, "constant"), std::atoi(arg(4, "5").c_str()));
  if(mode == "check") {
    try {
      return check<Pdt>(std::atof(arg(2, "1e6").c_str()), arg(3, "constant"), arg(4, "data/test_image.png"));
    } catch(const std::exception& e) {  // an unreadable image
      std::cerr << "triangulation_benchmark: " << e.what() << "\n";
      return 2;
    }
  }
  return once<Pdt>(std::atof(arg(2, "1e6").c_str()), arg(3, "constant"), arg(4, "penrose"));
}

int main(int argc, char** argv)
{
  // --threads T: Parallel_tag on at most T threads; 0, or none, Sequential_tag
  int threads = 0;
  if(argc > 2 && std::string(argv[1]) == "--threads") {
    threads = std::atoi(argv[2]);
    argc -= 2;
    argv += 2;
  }
  const std::string mode = argc > 1 ? argv[1] : "speed";
  auto arg = [&](int i, const char* otherwise) { return std::string(argc > i ? argv[i] : otherwise); };
  const bool valid = threads >= 0 &&
    ((mode == "speed" && is_size(arg(2, "1e6")) && benchmark_support::is_unit_square_input(arg(3, "constant")) && std::atoi(arg(4, "5").c_str()) >= 1) ||
     (mode == "memory" && (arg(2, "penrose") == "penrose" || arg(2, "penrose") == "cgal") && is_size(arg(3, "1e6"))) ||
     (mode == "scaling" && benchmark_support::is_unit_square_input(arg(2, "constant"))) ||
     (mode == "stages" && is_size(arg(2, "1e6")) && benchmark_support::is_unit_square_input(arg(3, "constant")) && std::atoi(arg(4, "5").c_str()) >= 1) ||
     (mode == "once" && is_size(arg(2, "1e6")) && benchmark_support::is_unit_square_input(arg(3, "constant")) &&
      (arg(4, "penrose") == "penrose" || arg(4, "penrose") == "cgal")) ||
     (mode == "check" && is_size(arg(2, "1e6")) && benchmark_support::is_figure8_input(arg(3, "constant"))));
#if !defined(CGAL_LINKED_WITH_TBB)
  if(threads > 0) {
    std::cerr << "triangulation_benchmark: built without TBB, no --threads\n";
    return 2;
  }
#endif
  if(!valid) {
    std::cerr << "usage: triangulation_benchmark [--threads T] speed [N] [constant|ramp] [runs] | memory penrose|cgal [N] | "
                 "scaling [constant|ramp] | stages [N] [constant|ramp] [runs] | once [N] [constant|ramp] [penrose|cgal] | "
                 "check [N] [constant|ramp|image|terrain] [IMAGE]\n";
    return 2;
  }
#if defined(CGAL_LINKED_WITH_TBB)
  if(threads > 0) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    return run<Penrose_dt<CGAL::Parallel_tag>>(argc, argv);
  }
#endif
  return run<Penrose_dt<CGAL::Sequential_tag>>(argc, argv);
}
