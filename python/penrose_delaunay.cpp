// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module penrose_delaunay: blue-noise samples of a density and
// their Delaunay triangulation as numpy arrays.

#include "density_table.h"
#include "../tools/border_points.h"
#include "../tools/border_refinement.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_Delaunay_border_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_Delaunay_window_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#if defined(CGAL_LINKED_WITH_TBB)
#  include <tbb/global_control.h>
#endif

#include <boost/iterator/function_output_iterator.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace penrose_python {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef K::Iso_rectangle_2 Rectangle;
typedef CGAL::Penrose_importance_sampler<K> Sampler;
typedef CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, K> Vb;
typedef CGAL::Triangulation_face_base_with_info_2<std::int32_t, K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Penrose_Delaunay_triangulation_2<K, Tds> Triangulation;
#if defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Penrose_Delaunay_triangulation_2<K, Tds, CGAL::Parallel_tag> Parallel_triangulation;
#endif

// What the Python functions were asked for, checked.
struct Request
{
  std::array<double, 4> region;
  std::optional<std::size_t> n;
  double scale = 1.;
  bool correction = true;
  std::optional<std::array<double, 4>> window;  // the part of the region sampled, if not all of it
  long long threads = 1;                         // 1: Sequential_tag; 0: as many as TBB allows
  std::optional<double> integral;                // of the density over the region, if known
  std::size_t most_points = 100000000;           // of the region: a window holds its part only
};

void check_rectangle(const char* name, const std::array<double, 4>& r)
{
  if(!(r[0] <= r[2] && r[1] <= r[3] && std::isfinite(r[2] - r[0]) && std::isfinite(r[3] - r[1])))
    throw std::invalid_argument(std::string("the ") + name + " must be (x0, y0, x1, y1), finite, with x0 <= x1 and y0 <= y1");
}

// The density in the sampler's terms: its value, a bound over boxes where
// one is known, and how the walk along the border evaluates it where that
// differs from `value`.
struct Density
{
  std::function<double(const Point&)> value;
  std::function<double(const Rectangle&)> upper_bound;  // empty: the sampler probes
  std::function<double(double, double)> on_border;      // empty: `value`
  bool thread_safe = true;  // whether `value` may be called from TBB's threads

  double at_border(double x, double y) const { return on_border ? on_border(x, y) : value(Point(x, y)); }
};

// A numpy array that owns `v`, without a copy.
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& v, std::size_t rows, std::size_t columns)
{
  auto* owner = new std::vector<T>(std::move(v));
  py::capsule free_when_done(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({rows, columns}, owner->data(), free_when_done);
}

template <class NamedParameters>
std::unique_ptr<Sampler> make_sampler_with(const Rectangle& region, const Density& d, const NamedParameters& np)
{
  using CGAL::parameters::density_upper_bound;
  if(d.upper_bound) return std::make_unique<Sampler>(region, d.value, density_upper_bound(d.upper_bound, np));
  return std::make_unique<Sampler>(region, d.value, np);
}

template <class NamedParameters>
std::unique_ptr<Sampler> make_sampler_integrated(const Request& r, const Density& d, const NamedParameters& np)
{
  const Rectangle region(r.region[0], r.region[1], r.region[2], r.region[3]);
  if(r.integral) return make_sampler_with(region, d, CGAL::parameters::density_integral(*r.integral, np));
  return make_sampler_with(region, d, np);
}

std::unique_ptr<Sampler> make_sampler(const Request& r, const Density& d)
{
  using namespace CGAL::parameters;
  const auto np = use_correction_vectors(r.correction).density_control_factor(r.scale).maximum_number(r.most_points);
  if(r.n) return make_sampler_integrated(r, d, np.number_of_output_points(*r.n));
  return make_sampler_integrated(r, d, np);
}

// The samples, x and y interleaved.
std::vector<double> sample_coordinates(const Request& r, const Density& d)
{
  const std::unique_ptr<Sampler> sampler = make_sampler(r, d);
  std::vector<double> xy;
  auto out = boost::make_function_output_iterator([&xy](const Point& p) {
    xy.push_back(p.x());
    xy.push_back(p.y());
  });
  if(!r.window) {
    xy.reserve(2 * std::size_t(sampler->expected_number_of_points() * 1.05 + 16));
    (*sampler)(out);
  } else {
    const std::array<double, 4>& w = *r.window;
    (*sampler)(Rectangle(Point(w[0], w[1]), Point(w[2], w[3])), out);
  }
  return xy;
}

struct Mesh
{
  std::vector<double> xy;                  // the vertices' points, x and y interleaved
  std::vector<std::int32_t> simplices;     // three vertices a face, counter-clockwise
  std::vector<std::int32_t> neighbors;     // the face opposite each vertex of each face, or -1
};

// The vertices are numbered in the order the construction reports them, then
// the border points and the points that shape the triangles at the border;
// the finite faces in the triangulation's order.
template <class Triangulation>
Mesh triangulate_samples_with(const Request& r, const Density& d, bool boundary, bool neighbors)
{
  const std::unique_ptr<Sampler> sampler = make_sampler(r, d);
  Mesh m;
  m.xy.reserve(2 * std::size_t(sampler->expected_number_of_points() * 1.05 + 16));
  Triangulation t;
  auto number = [&m](typename Triangulation::Vertex_handle v, const Point& p) {
    v->info() = std::int32_t(m.xy.size() / 2);
    m.xy.push_back(p.x());
    m.xy.push_back(p.y());
  };
  auto lift = [](double x, double y) { return Point(x, y); };
  std::vector<typename Triangulation::Vertex_handle> samples;
  t.build(*sampler, lift, [&samples](typename Triangulation::Vertex_handle v, const Sampler::Sample&) { samples.push_back(v); });
  const double scale = sampler->density_scale();
  std::optional<penrose_tools::Border> border;
  if(boundary) {
    border.emplace(r.region, [&](double x, double y) { return scale * d.at_border(x, y); });
    penrose_tools::remove_samples_near_border(t, samples, *border);
  }
  for(const auto v : samples) number(v, v->point());
  if(boundary) {
    typename Triangulation::Face_handle hint;
    border->for_each_point([&](double x, double y) {
      const std::size_t before = t.number_of_vertices();
      const typename Triangulation::Vertex_handle v = t.insert(Point(x, y), hint);
      if(t.number_of_vertices() > before) number(v, v->point());
      hint = v->face();
    });
    penrose_tools::refine_border_triangles(t, r.region, {true, true, true, true}, lift,
                                           [&number](typename Triangulation::Vertex_handle v) { number(v, v->point()); });
  }
  for(auto f : t.all_face_handles()) f->info() = -1;
  std::int32_t faces = 0;
  for(auto f : t.finite_face_handles()) f->info() = faces++;
  m.simplices.reserve(3 * std::size_t(faces));
  if(neighbors) m.neighbors.reserve(3 * std::size_t(faces));
  for(auto f : t.finite_face_handles())
    for(int i = 0; i < 3; ++i) {
      m.simplices.push_back(f->vertex(i)->info());
      if(neighbors) m.neighbors.push_back(f->neighbor(i)->info());
    }
  return m;
}

// With Sequential_tag, or Parallel_tag on `r.threads` threads (0: as many
// as TBB allows) where TBB is linked and the density is thread-safe: the
// same mesh either way.
Mesh triangulate_samples(const Request& r, const Density& d, bool boundary, bool neighbors)
{
#if defined(CGAL_LINKED_WITH_TBB)
  if(r.threads != 1 && d.thread_safe) {
    if(r.threads == 0) return triangulate_samples_with<Parallel_triangulation>(r, d, boundary, neighbors);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(r.threads));
    return triangulate_samples_with<Parallel_triangulation>(r, d, boundary, neighbors);
  }
#endif
  return triangulate_samples_with<Triangulation>(r, d, boundary, neighbors);
}

// Evaluates the pending points of `table` with `f`, in blocks.
void evaluate_pending(Density_table& table, const py::function& f)
{
  const std::size_t pending = table.number_of_pending();
  std::vector<double> values;
  values.reserve(pending);
  constexpr std::size_t block = std::size_t(1) << 20;
  for(std::size_t first = 0; first < pending; first += block) {
    const std::size_t count = std::min(block, pending - first);
    py::array_t<double> x(count), y(count);
    double* px = x.mutable_data();
    double* py_ = y.mutable_data();
    for(std::size_t k = 0; k < count; ++k) std::tie(px[k], py_[k]) = table.pending(first + k);
    const py::array_t<double, py::array::forcecast> v = f(x, y);
    if(v.ndim() > 1 || (v.size() != py::ssize_t(count) && v.size() != 1))
      throw std::invalid_argument("the density function returned " + std::to_string(v.size())
                                  + " values for arrays of " + std::to_string(count) + " points");
    const double* pv = v.data();
    for(std::size_t k = 0; k < count; ++k) values.push_back(v.size() == 1 ? pv[0] : pv[k]);
  }
  table.set_pending_values(values);
}

// Runs `construct` on a density that a Python function gives in blocks (see
// Density_table), until a run asks for no point that was not evaluated yet.
template <class Construct>
auto run_on_table(Density_table& table, const py::function& f, Construct construct)
{
  for(;;) {
    std::optional<decltype(construct())> result;
    std::exception_ptr error;
    table.rewind();
    {
      py::gil_scoped_release release;
      try {
        result.emplace(construct());
      } catch(...) {
        error = std::current_exception();
      }
    }
    if(table.number_of_pending() == 0) {
      if(error) std::rethrow_exception(error);
      return std::move(*result);
    }
    // A run that met points not yet evaluated decided on guesses there: what it threw does not count.
    evaluate_pending(table, f);
  }
}

// The table's guess: `f` on the grid of midpoints on which the sampler
// estimates the integral (which then finds them known), interpolated; 0
// where `f` is not a density there, so that the sampler reports that.
std::function<double(double, double)> grid_guess(Density_table& table, const py::function& f, const Request& r)
{
  constexpr std::size_t n = 512;
  const double x0 = r.region[0], y0 = r.region[1], x1 = r.region[2], y1 = r.region[3];
  const double dx = (x1 - x0) / n, dy = (y1 - y0) / n;
  auto at_node = [&](std::size_t i, std::size_t j) { return table(x0 + (double(i) + 0.5) * dx, y0 + (double(j) + 0.5) * dy); };
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) at_node(i, j);
  evaluate_pending(table, f);
  table.rewind();
  std::vector<double> values(n * n);
  double sum = 0.;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) sum += values[(n - 1 - j) * n + i] = at_node(i, j);
  // The tree asks for about five points a sample (4.3 x 10^6 for 10^6 samples of a ramp).
  const double expected = (r.n ? double(*r.n) : sum * dx * dy) * r.scale;
  if(expected < 1e8) table.reserve(std::size_t(5 * expected) + n * n);
  try {
    auto raster = std::make_shared<const CGAL::Raster_density_2<K>>(n, n, std::move(values), Rectangle(x0, y0, x1, y1));
    return [raster](double x, double y) { return (*raster)(Point(x, y)); };
  } catch(const std::invalid_argument&) {
    return [](double, double) { return 0.; };
  }
}

// Calls `construct(density)` with the density that `object` describes: a
// number, a raster (a 2D array over the region, row 0 at the top) or a
// Python function f(x, y) of arrays. The region defaults to the unit
// square, and to (0, 0, width, height) for a raster: one unit a pixel.
// A function is first evaluated where sampling needs it, when `construct`
// costs more than sampling.
template <class Construct>
auto with_density(const py::object& object, std::optional<std::array<double, 4>> region, Request& r,
                  bool sample_first, Construct construct)
{
  if(region) {
    check_rectangle("region", *region);
    if(!((*region)[0] < (*region)[2] && (*region)[1] < (*region)[3])) throw std::invalid_argument("the region is empty");
  }
  if(py::isinstance<py::function>(object)) {
    r.region = region.value_or(std::array<double, 4>{0., 0., 1., 1.});
    const py::function f = py::reinterpret_borrow<py::function>(object);
    std::function<double(double, double)> guess = [](double, double) { return 0.; };
    auto table = std::make_shared<Density_table>([&guess](double x, double y) { return guess(x, y); });
    guess = grid_guess(*table, f, r);
    // The border is walked point after point, each step set by the density
    // at the last point: a few thousand calls, made one at a time.
    auto on_border = [&f](double x, double y) {
      py::gil_scoped_acquire acquire;
      const py::array_t<double, py::array::forcecast> v =
        f(py::array_t<double>(1, &x), py::array_t<double>(1, &y));
      if(v.size() != 1) throw std::invalid_argument("the density function did not return one value for one point");
      return *v.data();
    };
    // the table notes the points it does not know: the calling thread's only
    const Density d{[table](const Point& p) { return (*table)(p.x(), p.y()); }, {}, on_border, false};
    if(sample_first) run_on_table(*table, f, [&] { return sample_coordinates(r, d).size(); });
    return run_on_table(*table, f, [&] { return construct(d); });
  }
  if(py::isinstance<py::array>(object)) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if(!a || a.ndim() != 2)
      throw std::invalid_argument("a raster density must be a 2D array of numbers (rows from the top)");
    const std::size_t height = std::size_t(a.shape(0)), width = std::size_t(a.shape(1));
    r.region = region.value_or(std::array<double, 4>{0., 0., double(width), double(height)});
    // Raster_density_2 checks the values and the region.
    const auto raster = std::make_shared<CGAL::Raster_density_2<K>>(
      width, height, std::vector<double>(a.data(), a.data() + a.size()),
      Rectangle(r.region[0], r.region[1], r.region[2], r.region[3]));
    const Density d{[raster](const Point& p) { return (*raster)(p); },
                    [raster](const Rectangle& b) { return raster->upper_bound(b); }, {}};
    py::gil_scoped_release release;
    return construct(d);
  }
  double c;
  try {
    c = object.cast<double>();
  } catch(const py::cast_error&) {
    throw std::invalid_argument("the density must be a number, a 2D array or a function f(x, y)");
  }
  if(!(c >= 0. && std::isfinite(c)))
    throw std::invalid_argument("the density must be finite and non-negative, not " + std::to_string(c));
  r.region = region.value_or(std::array<double, 4>{0., 0., 1., 1.});
  const Density d{[c](const Point&) { return c; }, [c](const Rectangle&) { return c; }, {}};
  py::gil_scoped_release release;
  return construct(d);
}

Request make_request(const std::optional<py::object>& n, const std::optional<double>& scale, bool correction)
{
  Request r;
  if(n && !n->is_none()) {
    long long count;
    try {
      count = n->cast<long long>();
    } catch(const py::cast_error&) {
      throw std::invalid_argument("n must be a non-negative integer");
    }
    if(count < 0) throw std::invalid_argument("n must be a non-negative integer, not " + std::to_string(count));
    r.n = std::size_t(count);
  }
  if(scale) {
    if(!(*scale >= 0. && std::isfinite(*scale)))
      throw std::invalid_argument("scale must be finite and non-negative, not " + std::to_string(*scale));
    r.scale = *scale;
  }
  r.correction = correction;
  return r;
}

py::array_t<double> sample(const py::object& density, const std::optional<std::array<double, 4>>& region,
                           const std::optional<py::object>& n, const std::optional<double>& scale, bool correction,
                           const std::optional<std::array<double, 4>>& window)
{
  Request r = make_request(n, scale, correction);
  if(window) check_rectangle("window", *window);
  r.window = window;
  std::vector<double> xy = with_density(density, region, r, false, [&r](const Density& d) {
    return sample_coordinates(r, d);
  });
  const std::size_t rows = xy.size() / 2;
  return to_numpy(std::move(xy), rows, 2);
}

py::tuple triangulate(const py::object& density, const std::optional<std::array<double, 4>>& region,
                      const std::optional<py::object>& n, const std::optional<double>& scale, bool correction,
                      bool boundary, bool neighbors, long long threads)
{
  Request r = make_request(n, scale, correction);
  if(threads < 0) throw std::invalid_argument("threads must be 0 (all) or a positive number, not " + std::to_string(threads));
  r.threads = threads;
  Mesh m = with_density(density, region, r, true, [&](const Density& d) {
    return triangulate_samples(r, d, boundary, neighbors);
  });
  const std::size_t vertices = m.xy.size() / 2, faces = m.simplices.size() / 3;
  py::array_t<double> points = to_numpy(std::move(m.xy), vertices, 2);
  py::array_t<std::int32_t> simplices = to_numpy(std::move(m.simplices), faces, 3);
  if(!neighbors) return py::make_tuple(points, simplices);
  return py::make_tuple(points, simplices, to_numpy(std::move(m.neighbors), faces, 3));
}

// A window's part of the triangulation (see Penrose_Delaunay_window_2) and,
// where asked, the border's (Penrose_Delaunay_border_2): the samples in the
// window by key, their keys, the triangles as key triples, and the other
// vertices of those triangles by key.
struct Piece
{
  std::vector<double> xy;
  std::vector<std::uint64_t> keys;
  std::vector<std::uint64_t> triangles;
  std::vector<double> foreign_xy;
  std::vector<std::uint64_t> foreign_keys;
  std::vector<std::uint64_t> hull;
  std::vector<std::uint32_t> local;  // the triangles as indices into the samples, then the foreign vertices
};

template <class Pairs>
void add_foreign(Piece& p, const Pairs& vertices)
{
  for(const auto& [k, q] : vertices) {
    p.foreign_keys.push_back(k);
    p.foreign_xy.push_back(q.x());
    p.foreign_xy.push_back(q.y());
  }
}

Piece window_piece(const Request& r, const Density& d, bool border, double margin)
{
  const std::unique_ptr<Sampler> sampler = make_sampler(r, d);
  Piece p;
  if(r.window) {
    const std::array<double, 4>& w = *r.window;
    const Rectangle window(Point(w[0], w[1]), Point(w[2], w[3]));
    const CGAL::Penrose_Delaunay_window_2<K> part =
      margin > 0. ? CGAL::Penrose_Delaunay_window_2<K>(*sampler, window, CGAL::parameters::window_margin(margin))
                  : CGAL::Penrose_Delaunay_window_2<K>(*sampler, window);
    for(const Point& q : part.points()) { p.xy.push_back(q.x()); p.xy.push_back(q.y()); }
    p.keys = part.keys();
    for(const auto& t : part.triangles()) p.triangles.insert(p.triangles.end(), t.begin(), t.end());
    for(const auto& t : part.triangle_indices()) p.local.insert(p.local.end(), t.begin(), t.end());
    add_foreign(p, part.foreign_vertices());
  }
  if(border) {
    const CGAL::Penrose_Delaunay_border_2<K> part(*sampler);
    // the border's vertices among the window's samples and foreign vertices, or foreign to both
    std::unordered_map<std::uint64_t, std::uint32_t> index;
    for(std::size_t i = 0; i < p.keys.size(); ++i) index.emplace(p.keys[i], std::uint32_t(i));
    for(std::size_t j = 0; j < p.foreign_keys.size(); ++j) index.emplace(p.foreign_keys[j], std::uint32_t(p.keys.size() + j));
    for(const auto& [k, q] : part.vertices())
      if(index.emplace(k, std::uint32_t(p.keys.size() + p.foreign_keys.size())).second) add_foreign(p, std::array{std::make_pair(k, q)});
    for(const auto& t : part.triangles()) {
      p.triangles.insert(p.triangles.end(), t.begin(), t.end());
      for(std::uint64_t k : t) p.local.push_back(index.at(k));
    }
    p.hull = part.hull();
  }
  return p;
}

// Whether the window holds the region's lower left corner: the one window of
// a partition that also gives the border's triangles.
bool holds_lower_left_corner(const std::array<double, 4>& region, const std::array<double, 4>& w)
{
  const double x = region[0], y = region[1];
  return w[0] <= x && w[1] <= y && (x < w[2] || w[2] >= region[2]) && (y < w[3] || w[3] >= region[3]);
}

py::tuple window_triangles(const py::object& density, const std::optional<std::array<double, 4>>& region,
                           const std::optional<py::object>& n, const std::optional<std::array<double, 4>>& window,
                           const std::optional<double>& scale, bool correction, const std::optional<double>& integral,
                           const std::optional<bool>& border, double margin, bool foreign)
{
  Request r = make_request(n, scale, correction);
  if(window) check_rectangle("window", *window);
  if(integral && !(*integral >= 0. && std::isfinite(*integral)))
    throw std::invalid_argument("integral must be finite and non-negative");
  if(!(margin >= 0. && std::isfinite(margin))) throw std::invalid_argument("margin must be finite and non-negative");
  r.window = window;
  r.integral = integral;
  // a window's construction checks what it can hold (MemoryError beyond)
  r.most_points = std::numeric_limits<std::size_t>::max();
  Piece p = with_density(density, region, r, true, [&](const Density& d) {
    const bool with_border = border.value_or(!window || holds_lower_left_corner(r.region, *window));
    return window_piece(r, d, with_border, margin);
  });
  const std::size_t own = p.keys.size(), triangles = p.triangles.size() / 3, others = p.foreign_keys.size();
  py::tuple t = py::make_tuple(to_numpy(std::move(p.xy), own, 2), to_numpy(std::move(p.keys), own, 1).reshape({own}),
                               to_numpy(std::move(p.triangles), triangles, 3));
  if(!foreign) return t;
  const std::size_t h = p.hull.size();
  return py::make_tuple(t[0], t[1], t[2], to_numpy(std::move(p.foreign_xy), others, 2),
                        to_numpy(std::move(p.foreign_keys), others, 1).reshape({others}),
                        to_numpy(std::move(p.hull), h, 1).reshape({h}), to_numpy(std::move(p.local), triangles, 3));
}

double density_integral(const py::object& density, const std::optional<std::array<double, 4>>& region)
{
  Request r = make_request(std::nullopt, std::nullopt, true);
  return with_density(density, region, r, false, [&](const Density& d) { return make_sampler(r, d)->density_integral(); });
}

} // namespace penrose_python

PYBIND11_MODULE(_core, m)
{
  using namespace pybind11::literals;
  // The docstrings give the signatures, in Python's terms.
  py::options options;
  options.disable_function_signatures();
  m.doc() = R"doc(Blue-noise points that follow a density, and their Delaunay triangulation.

The points are those of the Penrose-tiling importance sampler of Ostromoukhov,
Donohue and Jodoin (SIGGRAPH 2004), and the triangulation is derived from the
sampler's tile tree, in time linear in the number of points, without locating
a point: it is exactly the Delaunay triangulation of the points, equal to
CGAL's and to scipy.spatial.Delaunay's where no four points are cocircular.
The module wraps the C++ package CGAL::Penrose_Delaunay_triangulation_2.

The density is a number of points per unit area, given as
- a number: a constant density;
- a 2D numpy array: a raster stretched over the region, row 0 at the top
  (as an image), interpolated bilinearly between pixel centres; values
  finite and non-negative;
- a function f(x, y) of two float64 arrays returning an array of as many
  densities (or one number). It is called in blocks of points while the
  sampler is run again on the values known so far, until a run needs no new
  value: slower than a raster (a few times the construction, plus f), but
  exact. f is only ever called with the GIL held.

Both functions release the GIL while the C++ code runs, and both are
deterministic: the same arguments give the same points, bit for bit.
Errors: ValueError for a bad density, region, count or scale (with the C++
message), MemoryError for a request larger than 10^8 points or than the
machine's memory; what the density function raises is raised as it is.)doc";

  py::register_local_exception_translator([](std::exception_ptr p) {
    try {
      if(p) std::rethrow_exception(p);
    } catch(const std::length_error& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    } catch(const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "penrose_delaunay: out of memory");
    } catch(const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch(const std::range_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.def("sample", &penrose_python::sample, "density"_a, "region"_a = py::none(), "n"_a = py::none(),
        "scale"_a = py::none(), "correction"_a = true, "window"_a = py::none(),
        R"doc(sample(density, region=None, n=None, scale=None, correction=True, window=None) -> ndarray (N, 2) float64

Blue-noise samples of `density` over the rectangle `region` = (x0, y0, x1, y1),
in the depth-first order of the tile tree.

region: default (0, 0, 1, 1), or (0, 0, width, height) for a raster density.
n: the number of points wanted: the density is scaled so that its integral
   over the region (estimated on a 512 x 512 grid) is n. Default: the
   integral of the density itself.
scale: a factor applied to the density, after n. Default 1.
correction: whether the samples are moved by the sampler's correction
   vectors (better blue noise); without, they lie on tile vertices.
window: (x0, y0, x1, y1): only the samples of the region that lie in this
   rectangle, bit for bit those of the whole sample, in time proportional to
   their number. A window is closed on the region's border and open on its
   other sides, so that the windows of a partition of the region give each
   sample once: tiles that match at their borders.)doc");

  m.def("window_triangles", &penrose_python::window_triangles, "density"_a, "region"_a = py::none(),
        "n"_a = py::none(), "window"_a = py::none(), "scale"_a = py::none(), "correction"_a = true,
        "integral"_a = py::none(), "border"_a = py::none(), "margin"_a = 0., "foreign"_a = false,
        R"doc(window_triangles(density, region=None, n=None, window=None, scale=None, correction=True, integral=None,
                 border=None, margin=0, foreign=False)
    -> (points (N, 2) float64, keys (N,) uint64, triangles (M, 3) uint64)

The part of `triangulate()`'s triangulation that the rectangle `window` =
(x0, y0, x1, y1) owns, computed alone, without the rest of the region: its
samples (those of `sample(..., window=window)`, by increasing key), their
keys, and the triangles whose circumcentres lie in the window, each as the
keys of its vertices, counter-clockwise. A key names a sample the same way
in every window and process: the union over the windows of any partition
of the region is `triangulate()`'s triangulation, exactly.

The triangles whose circumcentres lie outside the region, along its border,
come with the window that holds the region's lower left corner (`border`:
True or False to decide otherwise; `window=None`: the border's alone).

integral: the integral of the density over the region, as
   `density_integral()` gives it: with it, the window's sampler does not
   integrate the density over the whole region, and its points are the
   same. Workers that share one get the same points.
margin: the first margin around the window, in the region's units (0: from
   the density); it grows where the triangles cannot be certified.
n may exceed the 10^8 of sample() and triangulate(): a window holds its part
   only (MemoryError if that outgrows the memory).
foreign: also return, after those three, the other vertices of the
   triangles (points (K, 2), keys (K,)), the keys of the convex hull,
   counter-clockwise, where the border was computed, and the triangles as
   indices (M, 3) uint32 into the window's points followed by those K
   vertices: what a driver needs to number the vertices.
The other arguments are those of `sample()`.)doc");

  m.def("density_integral", &penrose_python::density_integral, "density"_a, "region"_a = py::none(),
        R"doc(density_integral(density, region=None) -> float

The integral of the density over the region, as the sampler estimates it
(midpoint rule on a 512 x 512 grid): computed once by a driver and passed
as `integral` to the windows of `window_triangles()`.)doc");

  m.def("triangulate", &penrose_python::triangulate, "density"_a, "region"_a = py::none(), "n"_a = py::none(),
        "scale"_a = py::none(), "correction"_a = true, "boundary"_a = false, "neighbors"_a = false, "threads"_a = 1,
        R"doc(triangulate(density, region=None, n=None, scale=None, correction=True, boundary=False, neighbors=False,
            threads=1)
    -> (points (N, 2) float64, simplices (M, 3) int32[, neighbors (M, 3) int32])

The samples of `sample()` with the same arguments, and their Delaunay
triangulation. The points are those of `sample()`, in the order in which the
construction makes them (the tile tree's, breadth first); `simplices` lists
the vertices of each triangle, counter-clockwise.

boundary: also add points along the border of the region, spaced at the
   local density, so that the triangles cover the whole rectangle; they
   come after the samples in `points`, and the samples closer to the border
   than half the local spacing are left out. Then, so that no triangle with
   a vertex on the border has an angle under 15 degrees, the circumcentres
   of those that have one (or midpoints of the border's edges) are added,
   last (Ruppert's refinement, restricted to the border).
neighbors: also return, as scipy.spatial.Delaunay does, the triangle
   opposite each vertex of each triangle, -1 on the convex hull.
threads: the construction on this many threads (TBB's; 0: as many as TBB
   allows), for a number or a raster; a function density is always
   evaluated on the calling thread. The result is the same, bit for bit.
The other arguments are those of `sample()`.)doc");
}
