// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PENROSE_DELAUNAY_WINDOW_2_H
#define CGAL_PENROSE_DELAUNAY_WINDOW_2_H

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/named_parameters.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampler_access.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Density_probes.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Window_certificate.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Window_mesh.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

The part of the Delaunay triangulation of a sampler's points that one
window of its region owns, computed alone: from the samples of the window
grown by a margin, without the rest of the region and without a message to
the other windows.

A window owns a triangle of the region's triangulation when the
triangle's circumcentre lies in it (windows are half-open as in
`Penrose_importance_sampler::operator()(window, out)`: closed on the sides
that lie on the region's border), so that the windows of any partition of
the region own each triangle whose circumcentre is in the region exactly
once. The triangles whose circumcentres lie outside the region, along its
border, are `Penrose_Delaunay_border_2`'s. Together they are the
triangulation of `Delaunay_triangulation_2`, edge for edge.

The window is grown by a margin (at first twice the spacing of the samples
where the density is lowest around it, or the named parameter
`window_margin`), its samples are triangulated as
`Penrose_Delaunay_triangulation_2` does, and the result is certified: no
point of the window is farther from its nearest sample than from the
grown window's sides inside the region, so that no sample outside can
change a triangle whose circumcentre is in the window. Where the
certificate fails (the density is lower, or zero, in the margin), the
margin is doubled and the window made again; the sampler being
deterministic, the retry is exact.

Vertices are named by their samples' `key`, the same in every window and
process: a triangle is three keys, and a driver numbers the samples as it
likes (for instance window after window, by key within each window).

The density is read in the grown window, in a band about a tile wide around
it (where tiles that straddle its sides are subdivided) and at the corners
of the ancestors of its tiles: outside the grown window, about as many calls
as in the margin, growing with the window's perimeter (11,136 against
369,981 in the window for a window of 78,183 of 10<sup>6</sup> ramp points;
see the user manual).

\tparam Traits the traits of the sampler.
*/
template <class Traits = Exact_predicates_inexact_constructions_kernel>
class Penrose_Delaunay_window_2
{
public:
  /// \name Types
  /// @{
  typedef typename Traits::Point_2 Point_2;                  ///< the point type
  typedef typename Traits::Iso_rectangle_2 Iso_rectangle_2;  ///< the window's type
  typedef std::uint64_t Key;                                 ///< the name of a sample
  typedef std::array<Key, 3> Triangle;                       ///< three keys, counter-clockwise
  /// @}

  /// \name Creation
  /// @{

  /*!
  Computes the samples and the triangles that `window` owns.

  \param sampler the sampler whose triangulation is computed.
  \param window the window; it may extend beyond the region, or miss it.
  \param np an optional sequence of named parameters among:
    - `window_margin`: the first margin, in the region's units (default:
      twice the spacing of the samples where the density is lowest in and
      around the window, from a grid of probes). Any positive value gives
      the same result; a small one costs retries, a large one samples.

  \throws std::invalid_argument if the window is not finite, or its corners
          are not in order, or the margin is not positive.
  \throws what sampling throws (see `Penrose_importance_sampler`), and
          what the density throws.
  */
  template <class NamedParameters = parameters::Default_named_parameters>
  Penrose_Delaunay_window_2(const Penrose_importance_sampler<Traits>& sampler, const Iso_rectangle_2& window,
                            const NamedParameters& np = parameters::default_values())
    : traits_(sampler.geom_traits())
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const internal::Penrose::Sampling_context& c = internal::Penrose::Sampler_access::context(sampler);
    const internal::Penrose::Sample_window own = internal::Penrose::Sampler_access::window(sampler, window);
    if(own.is_empty()) return;
    const double margin = choose_parameter(get_parameter(np, Penrose_np::window_margin), 0.);
    if(!(margin >= 0. && margin < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument("Penrose_Delaunay_window_2: window_margin must be positive and finite");
    margin_ = margin > 0. ? margin : first_margin(c, sampler.density_scale(), own);
    build(c, sampler.density_scale(), own);
  }
  /// @}

  /// \name Access
  /// None of these throws.
  /// @{

  /// The samples that lie in the window, by increasing key.
  const std::vector<Point_2>& points() const { return points_; }
  /// Their keys, increasing.
  const std::vector<Key>& keys() const { return keys_; }
  /// The triangles that the window owns, each counter-clockwise.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// The vertices of those triangles that lie outside the window, with
  /// their keys, by increasing key: the windows that own them give their
  /// numbers.
  const std::vector<std::pair<Key, Point_2>>& foreign_vertices() const { return foreign_; }
  /// The triangles of `triangles()`, in the same order, as indices: `i` is
  /// `points()[i]` below `points().size()`, and `foreign_vertices()[i -
  /// points().size()]` beyond; for drivers that number the vertices.
  const std::vector<std::array<std::uint32_t, 3>>& triangle_indices() const { return indices_; }
  /// The margin that the certificate accepted.
  double margin() const { return margin_; }
  /// How many times the window was triangulated (1, unless the margin grew).
  int attempts() const { return attempts_; }
  /// Whether local repair left vertices to `insert()`, so that the last
  /// attempt was triangulated by `Delaunay_triangulation_2` instead (rare).
  bool repaired_by_insertion() const { return repaired_by_insertion_; }
  /// @}

private:
  typedef internal::Penrose::Flat_mesh::Index Index;

  static double first_margin(const internal::Penrose::Sampling_context& c, double scale,
                             const internal::Penrose::Sample_window& w)
  {
    const double whole = region_size(c);
    const double inside = internal::Penrose::probe_density(c, scale, w.x0, w.y0, w.x1, w.y1).spacing(2., whole);
    const double around = internal::Penrose::probe_density(c, scale, w.x0 - inside, w.y0 - inside,
                                                           w.x1 + inside, w.y1 + inside).spacing(2., whole);
    return (std::min)((std::max)(inside, around), whole);
  }

  static double region_size(const internal::Penrose::Sampling_context& c)
  {
    return (std::max)(c.xmax() - c.xmin(), c.ymax() - c.ymin());
  }

  void build(const internal::Penrose::Sampling_context& c, double scale, const internal::Penrose::Sample_window& own)
  {
    using namespace internal::Penrose;
    const double size = region_size(c);
    const double magnitude = (std::max)({std::abs(c.xmin()), std::abs(c.xmax()), std::abs(c.ymin()), std::abs(c.ymax())});
    const double tolerance = 1e-12 * (size + magnitude);
    const double eps = 1e-9 * size;
    const Box domain{own.x0 - eps, own.y0 - eps, own.x1 + eps, own.y1 + eps};
    for(;;) {
      ++attempts_;
      const double m = margin_;
      const Sample_window grown = c.window(own.x0 - m, own.y0 - m, own.x1 + m, own.y1 + m);
      const Bounding_window bounds{{own.x0 - m, own.y0 - m, own.x1 + m, own.y1 + m},
                                   own.x0 - m > c.xmin(), own.y0 - m > c.ymin(),
                                   own.x1 + m < c.xmax(), own.y1 + m < c.ymax(), tolerance};
      const Density_probes probes = probe_density(c, scale, grown.x0, grown.y0, grown.x1, grown.y1);
      const double expected = 1.05 * probes.mean * (grown.x1 - grown.x0) * (grown.y1 - grown.y0) + 64.;
      const Window_mesh w = make_window_mesh(c, grown, expected);
      Window_certificate certificate(w, domain, bounds);
      if(bounds.bounds_nothing() || certificate.holds()) {
        repaired_by_insertion_ = w.repaired_by_insertion;
        collect(w, own, certificate.circles());
        return;
      }
      margin_ *= 2.;
    }
  }

  void collect(const internal::Penrose::Window_mesh& w, const internal::Penrose::Sample_window& own,
               const std::vector<internal::Penrose::Circumcircle>& circles)
  {
    const internal::Penrose::Flat_mesh& m = w.mesh;
    auto inside = [&](Index v) { return own.contains(m.points[v].x(), m.points[v].y()); };
    std::vector<std::pair<Key, Index>> mine;
    for(Index v = 0; v < m.points.size(); ++v)
      if(w.is_sample[v] && m.vertex_face[v] != internal::Penrose::Flat_mesh::null && inside(v)) mine.emplace_back(w.key[v], v);
    std::sort(mine.begin(), mine.end());
    for(const auto& [k, v] : mine) {
      keys_.push_back(k);
      points_.push_back(point(m.points[v]));
    }
    // each mesh vertex's index among the window's (mine, then foreign), once known
    constexpr std::uint32_t unknown = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> local(m.points.size(), unknown);
    for(std::size_t i = 0; i < mine.size(); ++i) local[mine[i].second] = std::uint32_t(i);
    std::vector<std::pair<Key, Index>> foreign;
    for(Index f = 0; f < m.faces.size(); ++f) {
      if(!m.face_alive[f]) continue;
      const auto& v = m.faces[f].v;
      if(!(w.is_sample[v[0]] && w.is_sample[v[1]] && w.is_sample[v[2]])) continue;
      const internal::Penrose::Circumcircle& cc = circles[f];
      if(!cc.is_finite() || !own.contains(cc.x, cc.y)) continue;
      triangles_.push_back({{w.key[v[0]], w.key[v[1]], w.key[v[2]]}});
      indices_.push_back({{v[0], v[1], v[2]}});  // mesh vertices for now
      for(Index u : v)
        if(local[u] == unknown) {
          local[u] = unknown - 1;  // noted once
          foreign.emplace_back(w.key[u], u);
        }
    }
    std::sort(foreign.begin(), foreign.end());
    for(std::size_t i = 0; i < foreign.size(); ++i) {
      foreign_.emplace_back(foreign[i].first, point(m.points[foreign[i].second]));
      local[foreign[i].second] = std::uint32_t(mine.size() + i);
    }
    for(auto& t : indices_)
      for(auto& v : t) v = local[v];
  }

  Point_2 point(const internal::Penrose::Flat_mesh::Point& p) const
  {
    return traits_.construct_point_2_object()(typename Traits::FT(p.x()), typename Traits::FT(p.y()));
  }

  Traits traits_;
  std::vector<Point_2> points_;
  std::vector<Key> keys_;
  std::vector<Triangle> triangles_;
  std::vector<std::pair<Key, Point_2>> foreign_;
  std::vector<std::array<std::uint32_t, 3>> indices_;
  double margin_ = 0.;
  int attempts_ = 0;
  bool repaired_by_insertion_ = false;
};

} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_WINDOW_2_H
