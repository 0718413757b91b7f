// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_RASTER_DENSITY_2_H
#define CGAL_RASTER_DENSITY_2_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

A density given by a raster of non-negative values stretched over a
rectangle, interpolated bilinearly between pixel centres. Row 0 is the top row
(largest y), as in an image.

Besides evaluating the density, it bounds it from above over any box with a
max pyramid, in constant time, which makes it a conservative
`density_upper_bound` for `Penrose_importance_sampler`:

\code
CGAL::Raster_density_2<K> d(width, height, values, region);
CGAL::Penrose_importance_sampler<K> sampler(region, d,
  CGAL::parameters::density_upper_bound(d.upper_bound_function()));
\endcode

Copies share the raster and its pyramid, which never change after the
construction. Only the constructor throws.
*/
template <class Traits = Exact_predicates_inexact_constructions_kernel>
class Raster_density_2
{
public:
  /// The number type of the traits.
  typedef typename Traits::FT FT;
  /// The point type of the traits, the density's argument.
  typedef typename Traits::Point_2 Point_2;
  /// The type of the region and of the boxes bounded.
  typedef typename Traits::Iso_rectangle_2 Iso_rectangle_2;

  /// `values` holds `width * height` values, row after row from the top.
  /// \throws std::invalid_argument on an empty raster, a size mismatch, a
  /// negative, NaN or infinite value, or a region that is empty, degenerate
  /// or not finite.
  Raster_density_2(std::size_t width, std::size_t height, std::vector<double> values,
                   const Iso_rectangle_2& region, const Traits& traits = Traits())
    : w_(width), h_(height), traits_(traits)
  {
    if(width == 0 || height == 0 || height > values.size() / width || values.size() != width * height)
      throw std::invalid_argument("Raster_density_2: the raster is empty or its size does not match");
    for(std::size_t k = 0; k < values.size(); ++k)
      if(!(values[k] >= 0. && values[k] < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("Raster_density_2: pixel (" + std::to_string(k % width) + ", "
                                    + std::to_string(k / width) + ") is " + std::to_string(values[k])
                                    + "; values must be finite and non-negative");
    x0_ = to_double(traits_.compute_x_2_object()((region.min)()));
    y0_ = to_double(traits_.compute_y_2_object()((region.min)()));
    x1_ = to_double(traits_.compute_x_2_object()((region.max)()));
    y1_ = to_double(traits_.compute_y_2_object()((region.max)()));
    const double inf = std::numeric_limits<double>::infinity();
    if(!(x1_ > x0_ && y1_ > y0_ && x1_ - x0_ < inf && y1_ - y0_ < inf))
      throw std::invalid_argument("Raster_density_2: the region is empty, degenerate or not finite");
    u_per_x_ = double(w_) / (x1_ - x0_);
    v_per_y_ = double(h_) / (y1_ - y0_);
    levels_ = build_pyramid(std::move(values));
    raster_ = levels_->front().data();
  }

  /// The number of columns.
  std::size_t width() const { return w_; }
  /// The number of rows.
  std::size_t height() const { return h_; }
  /// The value of pixel (i, j), column i, row j from the top.
  double pixel(std::size_t i, std::size_t j) const { return raster_[j * w_ + i]; }

  /// The bilinearly interpolated density at `p`.
  double operator()(const Point_2& p) const
  {
    const double u = limited(pixel_u(to_double(traits_.compute_x_2_object()(p))) - 0.5, w_);
    const double v = limited(pixel_v(to_double(traits_.compute_y_2_object()(p))) - 0.5, h_);
    const long i = floor_index(u), j = floor_index(v);
    const double a = u - double(i), b = v - double(j);
    return (1 - a) * (1 - b) * at(i, j) + a * (1 - b) * at(i + 1, j)
         + (1 - a) * b * at(i, j + 1) + a * b * at(i + 1, j + 1);
  }

  /// An upper bound of the density over `box`: the largest pixel whose
  /// interpolation support meets it, read from the max pyramid.
  double upper_bound(const Iso_rectangle_2& box) const
  {
    const double bx0 = to_double(traits_.compute_x_2_object()((box.min)()));
    const double by0 = to_double(traits_.compute_y_2_object()((box.min)()));
    const double bx1 = to_double(traits_.compute_x_2_object()((box.max)()));
    const double by1 = to_double(traits_.compute_y_2_object()((box.max)()));
    // pixels i with centre within one pixel of the box in u, likewise in v
    const long i0 = clamp_index(floor_index(limited(pixel_u(bx0) - 0.5, w_)), w_);
    const long i1 = clamp_index(floor_index(limited(pixel_u(bx1) - 0.5, w_)) + 1, w_);
    const long j0 = clamp_index(floor_index(limited(pixel_v(by1) - 0.5, h_)), h_);
    const long j1 = clamp_index(floor_index(limited(pixel_v(by0) - 0.5, h_)) + 1, h_);
    // the finest level at which the range spans at most two cells each way
    std::size_t k = 0;
    while(k + 1 < levels_->size() && ((i1 >> k) - (i0 >> k) > 1 || (j1 >> k) - (j0 >> k) > 1)) ++k;
    // the two cells each way, the same one twice where the range spans one
    const std::vector<double>& level = (*levels_)[k];
    const std::size_t wk = level_width(k);
    const std::size_t r0 = std::size_t(j0 >> k) * wk, r1 = std::size_t(j1 >> k) * wk;
    const std::size_t c0 = std::size_t(i0 >> k), c1 = std::size_t(i1 >> k);
    const double m = (std::max)((std::max)(level[r0 + c0], level[r0 + c1]), (std::max)(level[r1 + c0], level[r1 + c1]));
    // the rounding of operator() can exceed its pixels by a few units in the last place
    return m * (1. + 1e-14);
  }

  /// `upper_bound` as a callable, for the `density_upper_bound` named
  /// parameter. It holds a copy of this density, which shares the raster and
  /// its pyramid: it stays valid after this density is destroyed.
  std::function<double(const Iso_rectangle_2&)> upper_bound_function() const
  {
    return [copy = *this](const Iso_rectangle_2& b) { return copy.upper_bound(b); };
  }

  /// The exact integral of the interpolated density over the region, up to
  /// the half-pixel border where the interpolation is clamped.
  double integral() const
  {
    double s = 0.;
    for(double v : levels_->front()) s += v;
    return s * (x1_ - x0_) * (y1_ - y0_) / double(w_ * h_);
  }

private:
  // the sampler evaluates the density several times per sample: no division here
  double pixel_u(double x) const { return (x - x0_) * u_per_x_; }
  double pixel_v(double y) const { return (y1_ - y) * v_per_y_; }
  static long clamp_index(long i, std::size_t n) { return (std::min)((std::max)(i, 0L), long(n) - 1); }
  // u limited to [-1, n], beyond which the interpolation is clamped anyway
  // (NaN to -1), so that its floor converts safely to an index
  static double limited(double u, std::size_t n) { return u >= -1. ? (std::min)(u, double(n)) : -1.; }
  // the floor of a limited u, without a call to the C library
  static long floor_index(double u)
  {
    const long i = long(u);
    return double(i) > u ? i - 1 : i;
  }
  double at(long i, long j) const { return raster_[std::size_t(clamp_index(j, h_)) * w_ + std::size_t(clamp_index(i, w_))]; }
  std::size_t level_width(std::size_t k) const { return ((w_ - 1) >> k) + 1; }
  std::size_t level_height(std::size_t k) const { return ((h_ - 1) >> k) + 1; }

  std::shared_ptr<const std::vector<std::vector<double>>> build_pyramid(std::vector<double> raster) const
  {
    auto levels = std::make_shared<std::vector<std::vector<double>>>();
    levels->push_back(std::move(raster));
    for(std::size_t k = 1; level_width(k - 1) > 1 || level_height(k - 1) > 1; ++k) {
      const std::vector<double>& f = (*levels)[k - 1];
      const std::size_t fw = level_width(k - 1), fh = level_height(k - 1);
      const std::size_t cw = level_width(k), ch = level_height(k);
      std::vector<double> c(cw * ch, 0.);
      for(std::size_t j = 0; j < fh; ++j)
        for(std::size_t i = 0; i < fw; ++i) {
          double& m = c[(j / 2) * cw + i / 2];
          m = (std::max)(m, f[j * fw + i]);
        }
      levels->push_back(std::move(c));
    }
    return levels;
  }

  std::size_t w_, h_;
  Traits traits_;
  double x0_, y0_, x1_, y1_;
  double u_per_x_, v_per_y_;  // pixels per unit
  // levels_[0]: the raster; then 2x2 maxima. Never changed, so copies share them.
  std::shared_ptr<const std::vector<std::vector<double>>> levels_;
  const double* raster_;  // levels_[0]'s values
};

} // namespace CGAL

#endif // CGAL_RASTER_DENSITY_2_H
