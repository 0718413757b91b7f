// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PENROSE_DELAUNAY_BORDER_2_H
#define CGAL_PENROSE_DELAUNAY_BORDER_2_H

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampler_access.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Canonical_circumcircle.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Density_probes.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Window_certificate.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

The part of the Delaunay triangulation of a sampler's points that lies
along the region's border and that no window owns: the triangles whose
circumcentres lie outside the region (nearly collinear samples along the
border make circles up to 10<sup>19</sup> spacings wide, which reach only
about a spacing into the region), and the convex hull, which
`Delaunay_triangulation_2` holds as its infinite faces. With the
triangles of the windows of a partition of the region
(`Penrose_Delaunay_window_2`), these make the whole triangulation.

The samples of a strip along the border are triangulated with
`Delaunay_triangulation_2`: a few spacings wide, it holds about
4 sqrt(<i>N</i>) <i>k</i> of <i>N</i> points for <i>k</i> spacings. The
result is certified with exact predicates: the circumcircle of every
triangle that a point outside the region may see (those whose circles
leave the region, and all those around their vertices) misses the inner
rectangle that the strip leaves out, and every corner of that rectangle
lies strictly inside every hull edge, so that the samples left out change
neither the Voronoi diagram outside the region nor the hull. Where it
fails, the strip is made twice as wide along the side nearest to what
failed, up to the whole region. Each side's first width is three spacings
of the samples where the density is lowest near it.

\tparam Traits the traits of the sampler.
*/
template <class Traits = Exact_predicates_inexact_constructions_kernel>
class Penrose_Delaunay_border_2
{
public:
  /// \name Types
  /// @{
  typedef std::uint64_t Key;              ///< the name of a sample (`Penrose_importance_sampler::Sample::key`)
  typedef std::array<Key, 3> Triangle;    ///< three keys, counter-clockwise
  typedef typename Traits::Point_2 Point_2;  ///< the point type
  /// @}

  /// \name Creation
  /// @{

  /// Computes the border's triangles and the hull of the points of `sampler`.
  /// \throws what sampling throws (see `Penrose_importance_sampler`), and
  /// what the density throws.
  explicit Penrose_Delaunay_border_2(const Penrose_importance_sampler<Traits>& sampler)
    : traits_(sampler.geom_traits())
  {
    const internal::Penrose::Sampling_context& c = internal::Penrose::Sampler_access::context(sampler);
    region_ = {c.xmin(), c.ymin(), c.xmax(), c.ymax()};
    const double size = (std::max)(region_.x1 - region_.x0, region_.y1 - region_.y0);
    const double magnitude = (std::max)({std::abs(region_.x0), std::abs(region_.x1), std::abs(region_.y0), std::abs(region_.y1)});
    tolerance_ = 1e-12 * (size + magnitude);
    for(int side = 0; side < 4; ++side) width_[side] = first_width(c, sampler.density_scale(), side, size);
    while(attempt(sampler))
      for(int side = 0; side < 4; ++side) width_[side] = (std::max)(width_[side], needed_[side]);
  }
  /// @}

  /// \name Access
  /// None of these throws.
  /// @{

  /// The triangles whose circumcentres lie outside the region, or that
  /// doubles see flat, each counter-clockwise.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// The vertices of the convex hull of the points, counter-clockwise.
  const std::vector<Key>& hull() const { return hull_; }
  /// The vertices of those triangles and of the hull, with their keys, by
  /// increasing key: the windows that own them give their numbers.
  const std::vector<std::pair<Key, Point_2>>& vertices() const { return vertices_; }
  /// The width of the strip that the certificate accepted along each side
  /// of the region: left, bottom, right, top.
  const std::array<double, 4>& widths() const { return width_; }
  /// How many times the strip was triangulated.
  int attempts() const { return attempts_; }
  /// @}

private:
  typedef Exact_predicates_inexact_constructions_kernel K;
  struct Vertex_data
  {
    Key key = 0;
    bool seen_from_outside = false;
  };
  typedef Triangulation_vertex_base_with_info_2<Vertex_data, K> Vb;
  typedef Triangulation_face_base_with_info_2<char, K> Fb;  // 1: its circle is checked
  typedef Delaunay_triangulation_2<K, Triangulation_data_structure_2<Vb, Fb>> Dt;
  typedef typename Dt::Face_handle Face_handle;
  typedef internal::Penrose::Box Box;

  // Three spacings of the samples where they are sparsest along a side
  // (0 left, 1 bottom, 2 right, 3 top), from probes within an eighth of the
  // region of it: a side where the density vanishes gets a wider strip at
  // once.
  static double first_width(const internal::Penrose::Sampling_context& c, double scale, int side, double size)
  {
    const double d = size / 8.;
    const double x0 = c.xmin(), y0 = c.ymin(), x1 = c.xmax(), y1 = c.ymax();
    const internal::Penrose::Density_probes p =
      side == 0 ? internal::Penrose::probe_density(c, scale, x0, y0, (std::min)(x0 + d, x1), y1)
      : side == 1 ? internal::Penrose::probe_density(c, scale, x0, y0, x1, (std::min)(y0 + d, y1))
      : side == 2 ? internal::Penrose::probe_density(c, scale, (std::max)(x1 - d, x0), y0, x1, y1)
                  : internal::Penrose::probe_density(c, scale, x0, (std::max)(y1 - d, y0), x1, y1);
    return p.spacing(3., size);
  }

  bool covers_region() const
  {
    return width_[0] + width_[2] >= region_.x1 - region_.x0 || width_[1] + width_[3] >= region_.y1 - region_.y0;
  }

  // The rectangle that the strip leaves out, closed: the samples outside
  // the strip lie in it.
  Box inner() const
  {
    return {region_.x0 + width_[0], region_.y0 + width_[1], region_.x1 - width_[2], region_.y1 - width_[3]};
  }

  // Notes that the strip must be twice as wide along the side nearest to
  // (x, y). (Growing it to the depth that a failing disk reaches makes it
  // wider than needed near a corner, where the disks are widest.)
  void grow_near(double x, double y)
  {
    const double d[4] = {x - region_.x0, y - region_.y0, region_.x1 - x, region_.y1 - y};
    const int side = int(std::min_element(d, d + 4) - d);
    needed_[side] = 2. * width_[side];
  }

  // Triangulates the strip and certifies it; returns false, with the
  // widths needed_ set, where it must grow.
  bool attempt(const Penrose_importance_sampler<Traits>& sampler)
  {
    ++attempts_;
    std::vector<typename Penrose_importance_sampler<Traits>::Sample> samples;
    const auto& t = sampler.geom_traits();
    auto rectangle = [&](double x0, double y0, double x1, double y1) {
      return t.construct_iso_rectangle_2_object()(t.construct_point_2_object()(x0, y0),
                                                  t.construct_point_2_object()(x1, y1));
    };
    const Box& r = region_;
    const Box in = inner();
    if(covers_region()) {
      sampler.samples(std::back_inserter(samples));
    } else {
      for(const auto& b : {Box{r.x0, r.y0, r.x1, in.y0}, Box{r.x0, in.y1, r.x1, r.y1},
                           Box{r.x0, in.y0, in.x0, in.y1}, Box{in.x1, in.y0, r.x1, in.y1}})
        sampler.samples(rectangle(b.x0, b.y0, b.x1, b.y1), std::back_inserter(samples));
    }
    std::vector<std::pair<K::Point_2, Vertex_data>> points;
    points.reserve(samples.size());
    for(const auto& s : samples)
      points.emplace_back(K::Point_2(CGAL::to_double(t.compute_x_2_object()(s.point)),
                                     CGAL::to_double(t.compute_y_2_object()(s.point))),
                          Vertex_data{s.key, false});
    Dt dt(points.begin(), points.end());
    if(!covers_region() && !certified(dt)) return true;
    collect(dt);
    return false;
  }

  internal::Penrose::Circumcircle circle(Face_handle f) const
  {
    auto p = [&](int i) { return internal::Penrose::Xy{f->vertex(i)->point().x(), f->vertex(i)->point().y()}; };
    return internal::Penrose::canonical_circumcircle(p(0), p(1), p(2));
  }

  // Whether the strip's triangulation holds; where not, needed_ says how
  // wide the strip must grow, from all that fails.
  bool certified(Dt& dt)
  {
    needed_ = width_;
    if(dt.dimension() < 2) {
      for(double& w : needed_) w *= 2.;
      return false;
    }
    // the vertices whose Voronoi cells may reach out of the region
    const double eps = 1e-9 * (region_.x1 - region_.x0 + region_.y1 - region_.y0);
    for(auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
      f->info() = 0;
      bool outside = dt.is_infinite(f);
      if(!outside) {
        const internal::Penrose::Circumcircle cc = circle(f);
        outside = !(cc.is_finite() && cc.x - cc.radius > region_.x0 + eps && cc.x + cc.radius < region_.x1 - eps &&
                    cc.y - cc.radius > region_.y0 + eps && cc.y + cc.radius < region_.y1 - eps);
      }
      if(outside)
        for(int i = 0; i < 3; ++i)
          if(!dt.is_infinite(f->vertex(i))) f->vertex(i)->info().seen_from_outside = true;
    }
    bool holds = true;
    const Box in = inner();
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      if(!v->info().seen_from_outside) continue;
      auto f = dt.incident_faces(v), done = f;
      do {
        if(!dt.is_infinite(f) && !f->info()) {
          f->info() = 1;
          if(disk_meets(f, in)) {
            holds = false;
            const K::Point_2 g = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
            grow_near(g.x(), g.y());
          }
        }
      } while(++f != done);
    }
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const Face_handle f = e->first, g = f->neighbor(e->second);
      if(!dt.is_infinite(f) && !dt.is_infinite(g)) continue;
      const Face_handle inside = dt.is_infinite(f) ? g : f;
      const int i = dt.is_infinite(f) ? g->index(f) : e->second;
      const K::Point_2 &a = inside->vertex(Dt::ccw(i))->point(), &b = inside->vertex(Dt::cw(i))->point();
      for(double x : {in.x0, in.x1})
        for(double y : {in.y0, in.y1})
          if(K::Orientation_2()(a, b, K::Point_2(x, y)) != LEFT_TURN) {
            holds = false;
            grow_near(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()));
          }
    }
    return holds;
  }

  // Whether the closed disk of f's circumcircle meets the closed box `b`:
  // decided on doubles where they leave no doubt, exactly otherwise.
  bool disk_meets(Face_handle f, const Box& b) const
  {
    const internal::Penrose::Circumcircle cc = circle(f);
    if(cc.is_finite()) {
      const double dx = (std::max)({b.x0 - cc.x, 0., cc.x - b.x1}), dy = (std::max)({b.y0 - cc.y, 0., cc.y - b.y1});
      const double d = std::hypot(dx, dy), slack = 1e-9 * cc.radius + tolerance_;
      if(d > cc.radius + slack) return false;
      if(d < cc.radius - slack) return true;
    }
    typedef Exact_predicates_exact_constructions_kernel E;
    auto exact = [&](int i) { return E::Point_2(f->vertex(i)->point().x(), f->vertex(i)->point().y()); };
    const E::Point_2 o = E::Construct_circumcenter_2()(exact(0), exact(1), exact(2));
    const E::FT r2 = E::Compute_squared_distance_2()(o, exact(0));
    E::FT dx(0), dy(0);
    if(o.x() < b.x0) dx = E::FT(b.x0) - o.x();
    else if(o.x() > b.x1) dx = o.x() - E::FT(b.x1);
    if(o.y() < b.y0) dy = E::FT(b.y0) - o.y();
    else if(o.y() > b.y1) dy = o.y() - E::FT(b.y1);
    return dx * dx + dy * dy <= r2;
  }

  void collect(const Dt& dt)
  {
    auto in_region = [&](double x, double y) { return region_.contains(x, y); };
    std::map<Key, K::Point_2> used;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const internal::Penrose::Circumcircle cc = circle(f);
      if(cc.is_finite() && in_region(cc.x, cc.y)) continue;
      triangles_.push_back({{f->vertex(0)->info().key, f->vertex(1)->info().key, f->vertex(2)->info().key}});
      for(int i = 0; i < 3; ++i) used.emplace(f->vertex(i)->info().key, f->vertex(i)->point());
    }
    if(dt.dimension() == 2) {
      // the hull edges, each from the vertex before to the vertex after it counter-clockwise
      std::map<Key, Key> next;
      auto f = dt.incident_faces(dt.infinite_vertex()), done = f;
      do {
        const int i = f->index(dt.infinite_vertex());
        next[f->vertex(Dt::cw(i))->info().key] = f->vertex(Dt::ccw(i))->info().key;
        used.emplace(f->vertex(Dt::cw(i))->info().key, f->vertex(Dt::cw(i))->point());
      } while(++f != done);
      Key k = next.begin()->first;
      do {
        hull_.push_back(k);
        k = next[k];
      } while(k != hull_.front() && hull_.size() <= next.size());
    }
    for(const auto& [k, p] : used)
      vertices_.emplace_back(k, traits_.construct_point_2_object()(typename Traits::FT(p.x()), typename Traits::FT(p.y())));
  }

  Traits traits_;
  Box region_;
  double tolerance_ = 0.;
  std::array<double, 4> width_, needed_;
  int attempts_ = 0;
  std::vector<Triangle> triangles_;
  std::vector<Key> hull_;
  std::vector<std::pair<Key, Point_2>> vertices_;
};

} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_BORDER_2_H
