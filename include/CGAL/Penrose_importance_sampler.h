// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PENROSE_IMPORTANCE_SAMPLER_H
#define CGAL_PENROSE_IMPORTANCE_SAMPLER_H

#include <CGAL/Penrose_Delaunay_triangulation_2/named_parameters.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Depth_first_sampling.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampler_access.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/correction_vectors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

The importance sampler of Ostromoukhov, Donohue and Jodoin (SIGGRAPH 2004):
a Penrose tiling is subdivided where the density demands it, the sample
vertices of its tiles are thresholded with their F-codes read as Fibonacci
numbers, and the survivors are moved by correction vectors that an offline
Lloyd relaxation computed. The result is a blue-noise point set whose local
density follows a density function, in time linear in its size.

The density is a number of points per unit area. Without further parameters
the sampler returns about the integral of the density over the region; the
named parameter `number_of_output_points` rescales the density to a target
count instead.

The sampler is deterministic: the same region, density and parameters give
the same points, bit for bit.

Sampling (`operator()`, `samples()` and the constructions of
`Penrose_Delaunay_triangulation_2`) throws `std::invalid_argument`, naming
the point and the value, where the density is negative, NaN or infinite,
or where, scaled, it exceeds what the 30 levels of the tile tree can
represent: about 4 x 10<sup>11</sup> / <i>L</i><sup>2</sup> points per unit area, <i>L</i>
being the longer side of the region (about 4 x 10<sup>11</sup> points in
a square region, <i>k</i> times fewer in a region <i>k</i> times longer than
wide). A `density_upper_bound` far above the density refines tiles that
hold no point: to keep such a bound from running for minutes, sampling and
the constructions of `Penrose_Delaunay_triangulation_2` subdivide at most
256 tiles per expected point, plus 10<sup>5</sup>, and throw
`std::length_error` beyond, as the tree grows: a tight bound, or none,
subdivides 1.3 to 1.6 tiles per point, a bound 64 times the density about
80, and one 10<sup>6</sup> times the density is refused within a second.

\tparam Traits a model of `PenroseImportanceSamplerTraits_2`; the default is
`Exact_predicates_inexact_constructions_kernel`, and every CGAL kernel is a model.

\sa `Penrose_Delaunay_triangulation_2`
*/
template <class Traits = Exact_predicates_inexact_constructions_kernel>
class Penrose_importance_sampler
{
public:
  /// \name Types
  /// @{

  /// The traits, a model of `PenroseImportanceSamplerTraits_2`.
  typedef Traits Geom_traits;
  /// The number type of the traits.
  typedef typename Traits::FT FT;
  /// The point type of the traits, the type of the samples and of the density's argument.
  typedef typename Traits::Point_2 Point_2;
  /// The type of the region.
  typedef typename Traits::Iso_rectangle_2 Iso_rectangle_2;

  /// A sample with the data of its leaf tile.
  struct Sample
  {
    Point_2 point;              ///< the position, correction applied
    Point_2 reference_point;    ///< the tile vertex, before correction
    double importance;          ///< importance at the reference point
    int level;                  ///< level of the A/B leaf tile
    std::uint64_t f_code;       ///< F-code of the leaf tile
    std::uint64_t threshold;    ///< Fibonacci value of the F-code
    unsigned structural_index;  ///< column of the correction table
    unsigned importance_index;  ///< row of the correction table
    /// A 64-bit name of the sample, unique among the samples of the
    /// sampler and the same in every traversal, window or process: its
    /// birth tile's level and F-code. `Penrose_Delaunay_window_2` names
    /// vertices with it.
    std::uint64_t key;
  };
  /// @}

  /// \name Creation
  /// @{

  /*!
  Prepares sampling `density` over `region`.

  \tparam Density a callable `double(const Point_2&)` (any return type
          convertible with `CGAL::to_double()`); it is evaluated inside the
          closed region only.
  \param region the rectangle sampled; it must have a positive area.
  \param density the density, in points per unit area up to the scaling
         of `number_of_output_points` and `density_control_factor`: finite
         and non-negative.
  \param np an optional sequence of named parameters among the ones below.

  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_output_points}
      \cgalParamDescription{the number of points wanted: the density is scaled so that its integral over the region is this number. The integral is estimated by the midpoint rule on a 512 x 512 grid over the region, the same whatever `density_upper_bound`, so that the bound changes which tiles are visited and never the points: a feature narrower than a grid cell may be missed by the estimate, and the count then differs from the number asked for (scale with `density_control_factor` instead)}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{the integral of the density}
    \cgalParamNEnd
    \cgalParamNBegin{density_control_factor}
      \cgalParamDescription{a factor applied to the density (after `number_of_output_points`)}
      \cgalParamType{`double`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{density_integral}
      \cgalParamDescription{the integral of the unscaled density over the region, as `density_integral()` of a sampler of the same region and density returned it: the density is then not integrated, and the points are those of that sampler, bit for bit. A worker that samples or triangulates one window of a large region builds its sampler so, reading the density only near its window and the tile tree's ancestors}
      \cgalParamType{`double`, finite and non-negative}
      \cgalParamDefault{the integral measured on the density}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_number}
      \cgalParamDescription{the largest expected number of points accepted; a larger request throws `std::length_error` before anything is allocated}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{10<sup>8</sup>}
    \cgalParamNEnd
    \cgalParamNBegin{use_correction_vectors}
      \cgalParamDescription{whether samples are moved by their correction vectors}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{density_upper_bound}
      \cgalParamDescription{a callable `double(const Iso_rectangle_2&)` that bounds the density from above over a box. Tiles are then refined as the bound demands, so that no feature of the density is missed. Without it, the density is probed at the corners and the centroid of each tile, as in the 2004 system: a feature narrower than a tile that falls between the probes is sampled at the density around it.}
      \cgalParamType{a callable}
      \cgalParamDefault{none: probes}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of the traits class}
      \cgalParamType{`Traits`}
      \cgalParamDefault{`Traits()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws std::invalid_argument if the region is empty, degenerate or not
          finite, or if the density is negative, NaN or infinite where it is
          evaluated (the message names the point and the value).
  \throws std::length_error if more than `maximum_number` points are expected.
  \throws std::range_error if the region lies so far from the origin, for its
          size, that doubles cannot place even the first tiles. Sampling, the
          tile tree and the triangulation throw it too when the density needs
          tiles finer than doubles resolve at the region's coordinates,
          where the samples would be closer than about 100 to 150 units in
          the last place: 5000 points in a unit square are refused at
          (10^12, 10^12), where doubles are 1.2 x 10^-4 apart, and sampled
          at (10^11, 10^11). Moving the region nearer to the origin mends
          that.
  */
  template <class Density, class NamedParameters = parameters::Default_named_parameters>
  Penrose_importance_sampler(const Iso_rectangle_2& region, const Density& density,
                             const NamedParameters& np = parameters::default_values())
    : traits_(parameters::choose_parameter(parameters::get_parameter(np, internal_np::geom_traits), Traits())),
      region_(region)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;

    const double x0 = coordinate_x(region_min()), y0 = coordinate_y(region_min());
    const double x1 = coordinate_x(region_max()), y1 = coordinate_y(region_max());
    internal::Penrose::Sampling_context::check_region(x0, y0, x1, y1);

    auto construct_point = traits_.construct_point_2_object();
    std::function<double(double, double)> density_xy =
      [density, construct_point](double x, double y) {
        return CGAL::to_double(density(construct_point(FT(x), FT(y))));
      };

    std::function<double(double, double, double, double)> bound_xy;
    assign_bound(bound_xy, get_parameter(np, Penrose_np::density_upper_bound));

    const bool correct = choose_parameter(get_parameter(np, Penrose_np::use_correction_vectors), true);
    const double factor = choose_parameter(get_parameter(np, internal_np::density_control_factor), 1.);
    const std::size_t maximum = choose_parameter(get_parameter(np, internal_np::maximum_number),
                                                 std::size_t(100000000));
    if(!(factor >= 0. && factor < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument("Penrose_importance_sampler: density_control_factor must be finite and non-negative");

    // The integral is measured on the density alone, with the checks of the
    // sampler, before anything large is allocated.
    if constexpr(is_default_parameter<NamedParameters, Penrose_np::density_integral_t>::value) {
      internal::Penrose::Sampling_context probe(x0, y0, x1, y1, density_xy, nullptr, 1., nullptr);
      integral_ = integrate(probe, x0, y0, x1, y1);
    } else {
      integral_ = get_parameter(np, Penrose_np::density_integral);
      if(!(integral_ >= 0.))
        throw std::invalid_argument("Penrose_importance_sampler: density_integral must be finite and non-negative");
    }
    if(!(integral_ < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument("Penrose_importance_sampler: the integral of the density over the region overflows "
                                  "the doubles; scale the density down");

    double scale = factor;
    if(!is_default_parameter<NamedParameters, internal_np::number_of_output_points_t>::value) {
      const double n = static_cast<double>(choose_parameter(get_parameter(np, internal_np::number_of_output_points), std::size_t(0)));
      if(n > 0. && !(integral_ > 0.))
        throw std::invalid_argument("Penrose_importance_sampler: a number of points was asked for, but the density is zero over the region");
      scale *= integral_ > 0. ? n / integral_ : 0.;
      if(!(scale < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("Penrose_importance_sampler: the density is too small over the region to be scaled "
                                    "to the number of points asked for; scale the density up");
    }
    density_scale_ = scale;
    expected_ = scale * integral_;
    if(expected_ > static_cast<double>(maximum)) {
      std::ostringstream msg;
      msg << "Penrose_importance_sampler: about " << std::setprecision(3) << expected_
          << " points expected, more than maximum_number (" << maximum << ")";
      throw std::length_error(msg.str());
    }

    context_ = std::make_shared<internal::Penrose::Sampling_context>(
      x0, y0, x1, y1, density_xy, bound_xy, scale,
      correct ? &internal::Penrose::default_correction_table() : nullptr, expected_);
  }
  /// @}

  /// \name Sampling
  /// @{

  /// Writes the sample points into `out`, in depth-first order of the tile tree.
  /// \throws what sampling throws (see above).
  template <class OutputIterator>
  OutputIterator operator()(OutputIterator out) const
  {
    auto construct_point = traits_.construct_point_2_object();
    for_each_placed([&](const internal::Penrose::Placed_sample& s) {
      *out++ = construct_point(FT(s.x), FT(s.y));
    });
    return out;
  }

  /// Writes the samples, with the data of their leaf tiles, into `out` (value type `Sample`).
  /// \throws what sampling throws (see above).
  template <class OutputIterator>
  OutputIterator samples(OutputIterator out) const
  {
    for_each_placed([&](const internal::Penrose::Placed_sample& s) { *out++ = to_sample(s); });
    return out;
  }

  /*!
  Writes into `out` the sample points of the region that lie in `window`,
  in the depth-first order of the tile tree: the same points, bit for bit,
  as `operator()(out)` writes there, found in time proportional to their
  number plus the depth of the tree, since only the tiles whose samples can
  land in the window are subdivided.

  A window is closed on the sides that lie on or beyond the region's border,
  and open on the others (a point on its upper or right side belongs to the
  window above or to the right): the windows of a partition of the region
  give every sample once, and together all of them. A window may extend
  beyond the region, or miss it (no point).

  \throws std::invalid_argument if the window is not finite or its corners
          are not in order.
  \throws what sampling throws (see above), for the tiles that it visits.
  */
  template <class OutputIterator>
  OutputIterator operator()(const Iso_rectangle_2& window, OutputIterator out) const
  {
    auto construct_point = traits_.construct_point_2_object();
    for_each_placed(sample_window(window), [&](const internal::Penrose::Placed_sample& s) {
      *out++ = construct_point(FT(s.x), FT(s.y));
    });
    return out;
  }

  /// Writes into `out` the samples of the region that lie in `window`, with
  /// the data of their leaf tiles, as `operator()(window, out)` does their
  /// points, and throws what it throws.
  template <class OutputIterator>
  OutputIterator samples(const Iso_rectangle_2& window, OutputIterator out) const
  {
    for_each_placed(sample_window(window), [&](const internal::Penrose::Placed_sample& s) { *out++ = to_sample(s); });
    return out;
  }
  /// @}

  /// \name Access
  /// None of these throws.
  /// @{

  /// The region sampled.
  const Iso_rectangle_2& region() const { return region_; }
  /// The traits.
  const Traits& geom_traits() const { return traits_; }
  /// The factor applied to the density (from `number_of_output_points` and `density_control_factor`).
  double density_scale() const { return density_scale_; }
  /// The integral of the unscaled density over the region, as estimated by the sampler.
  double density_integral() const { return integral_; }
  /// The expected number of points: the integral of the scaled density.
  double expected_number_of_points() const { return expected_; }
  /// Whether the samples are moved by their correction vectors (named parameter `use_correction_vectors`).
  bool uses_correction_vectors() const { return context_->correction_table() != nullptr; }
  /// @}

private:
  friend struct internal::Penrose::Sampler_access;

  Sample to_sample(const internal::Penrose::Placed_sample& s) const
  {
    auto construct_point = traits_.construct_point_2_object();
    return Sample{ construct_point(FT(s.x), FT(s.y)),
                   construct_point(FT(s.reference_x), FT(s.reference_y)),
                   s.importance, s.leaf_level, s.leaf_code, s.threshold,
                   s.structural_index, s.importance_index, s.key };
  }

  template <class F>
  void for_each_placed(F&& f) const
  {
    for_each_placed(context_->region_window(), std::forward<F>(f));
  }

  template <class F>
  void for_each_placed(const internal::Penrose::Sample_window& window, F&& f) const
  {
    const internal::Penrose::Sampling_context& c = *context_;
    internal::Penrose::Placed_sample s;
    internal::Penrose::for_each_sample_depth_first(c, window,
      [&](double x, double y, double importance, const internal::Penrose::Sample_birth& b) {
        if(c.activate(x, y, importance, b, s) && window.contains(s.x, s.y)) f(s);
      });
  }

  internal::Penrose::Sample_window sample_window(const Iso_rectangle_2& window) const
  {
    auto vertex = traits_.construct_vertex_2_object();
    const double x0 = coordinate_x(vertex(window, 0)), y0 = coordinate_y(vertex(window, 0));
    const double x1 = coordinate_x(vertex(window, 2)), y1 = coordinate_y(vertex(window, 2));
    if(!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1) && x0 <= x1 && y0 <= y1))
      throw std::invalid_argument("Penrose_importance_sampler: the window is not finite, or its corners are not in order");
    return context_->window(x0, y0, x1, y1);
  }

  Point_2 region_min() const { return traits_.construct_vertex_2_object()(region_, 0); }
  Point_2 region_max() const { return traits_.construct_vertex_2_object()(region_, 2); }
  double coordinate_x(const Point_2& p) const { return CGAL::to_double(traits_.compute_x_2_object()(p)); }
  double coordinate_y(const Point_2& p) const { return CGAL::to_double(traits_.compute_y_2_object()(p)); }

  void assign_bound(std::function<double(double, double, double, double)>&, internal_np::Param_not_found) const {}

  template <class Bound>
  void assign_bound(std::function<double(double, double, double, double)>& f, const Bound& bound) const
  {
    auto construct_point = traits_.construct_point_2_object();
    auto construct_rectangle = traits_.construct_iso_rectangle_2_object();
    f = [bound, construct_point, construct_rectangle](double x0, double y0, double x1, double y1) {
      return CGAL::to_double(bound(construct_rectangle(construct_point(FT(x0), FT(y0)),
                                                       construct_point(FT(x1), FT(y1)))));
    };
  }

  // Midpoint rule on a 512 x 512 grid: enough for 1% on the densities that
  // the probes themselves can resolve.
  static double integrate(const internal::Penrose::Sampling_context& c,
                          double x0, double y0, double x1, double y1)
  {
    const int n = 512;
    const double dx = (x1 - x0) / n, dy = (y1 - y0) / n;
    double sum = 0.;
    for(int j = 0; j < n; ++j) {
      double row = 0.;
      for(int i = 0; i < n; ++i) row += c.density(x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy);
      sum += row;
    }
    return sum * dx * dy;
  }

  Traits traits_;
  Iso_rectangle_2 region_;
  double integral_ = 0., density_scale_ = 1., expected_ = 0.;
  std::shared_ptr<const internal::Penrose::Sampling_context> context_;
};

} // namespace CGAL

#endif // CGAL_PENROSE_IMPORTANCE_SAMPLER_H
