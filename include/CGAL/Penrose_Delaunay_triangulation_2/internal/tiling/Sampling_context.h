// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every traversal of the tile tree shares: the region, the importance
// field, the root tile, when a tile is refined and where a sample lands.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLING_CONTEXT_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLING_CONTEXT_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Correction_table.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Fibonacci_code.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Penrose_rules.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_subdivision.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Size_limits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

// For the few functions that every tile's refinement calls: Clang 14 leaves
// them out of line, which makes the sampler about a tenth slower than with
// them inlined (the construction, whose surveys call them apart from the
// mesh, much less). G++ 12 inlines them on its own.
#if defined(__clang__)
#  define CGAL_PENROSE_HOT_INLINE __attribute__((always_inline)) inline
#else
#  define CGAL_PENROSE_HOT_INLINE inline
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

// A sample that passed its threshold, with the data of its leaf tile.
struct Placed_sample
{
  double x, y;             // corrected position
  double reference_x, reference_y;
  double importance;
  std::uint64_t threshold;
  std::uint64_t leaf_code;
  std::uint64_t key;       // sample_key() of its birth
  int leaf_level;
  std::uint8_t leaf_direction;
  unsigned structural_index;
  unsigned importance_index;
};

// A part of the region where samples are wanted: closed on the sides that
// lie on the region's border, open on the others, so that the windows of a
// partition of the region share no sample and miss none.
struct Sample_window
{
  double x0, y0, x1, y1;
  bool closed_x1, closed_y1;

  bool contains(double x, double y) const
  {
    return x >= x0 && y >= y0 && (x < x1 || (closed_x1 && x == x1)) && (y < y1 || (closed_y1 && y == y1));
  }
  bool is_empty() const { return !(x0 < x1 || (closed_x1 && x0 == x1)) || !(y0 < y1 || (closed_y1 && y0 == y1)); }
};

// Number of subdivision levels applied everywhere before adaptivity (C.6).
constexpr int uniform_levels = 6;
// Structural bits reported with each sample when no table is in use.
constexpr int default_structural_bits = 6;

class Sampling_context
{
public:
  typedef std::function<double(double, double)> Density;
  // upper bound of the density over the box [x0, x1] x [y0, y1]
  typedef std::function<double(double, double, double, double)> Density_bound;

  // `expected_points` sets the most tiles that a traversal may subdivide
  // (see refinement_budget()); infinite: no limit.
  Sampling_context(double xmin, double ymin, double xmax, double ymax,
                   Density density, Density_bound bound,
                   double points_per_density_unit, const Correction_table* table,
                   double expected_points = std::numeric_limits<double>::infinity())
    : xmin_(xmin), ymin_(ymin), xmax_(xmax), ymax_(ymax),
      density_(std::move(density)), bound_(std::move(bound)), table_(table),
      expected_points_(expected_points), most_refined_tiles_(refinement_budget(expected_points)),
      importance_bins_(table ? table->importance_bins : 21u)
  {
    check_region(xmin, ymin, xmax, ymax);
    root_scale_ = 2. * (std::max)(xmax - xmin, ymax - ymin);
    const double phi = golden_ratio;
    for(int l = 0; l < max_level + 2; ++l) scale_[l] = root_scale_ / std::pow(phi, l);
    // C.8: samples per unit area = importance / root_scale^2 * sqrt 5 / (phi^4 sin36 + phi sin72)
    const double deg = 3.14159265358979323846 / 180.;
    const double k = std::sqrt(5.) / (std::pow(phi, 4) * std::sin(36 * deg) + phi * std::sin(72 * deg));
    importance_per_point_density_ = root_scale_ * root_scale_ / k;
    importance_per_density_ = points_per_density_unit * importance_per_point_density_;
    const Direction_table& u = directions();
    root_x_[0] = xmin - root_scale_ * (phi * phi / 2. - 0.25);
    root_y_[0] = ymin - root_scale_ / 8.;
    root_x_[1] = root_x_[0] + phi * phi * root_scale_ * u.x[15];
    root_y_[1] = root_y_[0] + phi * phi * root_scale_ * u.y[15];
    root_x_[2] = root_x_[0] + phi * root_scale_ * u.x[17];
    root_y_[2] = root_y_[0] + phi * root_scale_ * u.y[17];
    // A sample moves at most max_length() scales of its leaf level, which is
    // at least its birth level; the factor covers the rounding of the moves.
    margin_factor_ = table_ == nullptr ? 0. : table_->max_length() * (1. + 1e-6);
    set_finest_level();
    region_window_ = region_window();
    max_importance_ = fibonacci().level_importance[max_level + 1];
    structural_bits_ = table_ ? table_->structural_bits : default_structural_bits;
    structural_index_.resize(std::size_t(1) << structural_bits_);
    for(std::size_t c = 0; c < structural_index_.size(); ++c)
      structural_index_[c] = unsigned(fibonacci_value(c, structural_bits_));
  }

  static void check_region(double xmin, double ymin, double xmax, double ymax)
  {
    if(!(std::isfinite(xmin) && std::isfinite(ymin) && std::isfinite(xmax) && std::isfinite(ymax)))
      throw std::invalid_argument("Penrose_importance_sampler: the region has a non-finite bound");
    if(!(xmax > xmin && ymax > ymin))
      throw std::invalid_argument("Penrose_importance_sampler: the region is empty or degenerate");
    const double size = (std::max)(xmax - xmin, ymax - ymin);
    if(!(size * size < 1e300 && size > 1e-150))
      throw std::invalid_argument("Penrose_importance_sampler: the region's size is out of the range of doubles this sampler supports");
  }

  double xmin() const { return xmin_; }
  double ymin() const { return ymin_; }
  double xmax() const { return xmax_; }
  double ymax() const { return ymax_; }
  // The whole region, as a window.
  Sample_window region_window() const { return Sample_window{xmin_, ymin_, xmax_, ymax_, true, true}; }
  // The part of [x0, x1] x [y0, y1] in the region, closed only on the region's border.
  Sample_window window(double x0, double y0, double x1, double y1) const
  {
    return Sample_window{(std::max)(x0, xmin_), (std::max)(y0, ymin_), (std::min)(x1, xmax_), (std::min)(y1, ymax_),
                         x1 >= xmax_, y1 >= ymax_};
  }
  double root_scale() const { return root_scale_; }
  double scale(int level) const { return scale_[level]; }
  double root_x(int i) const { return root_x_[i]; }
  double root_y(int i) const { return root_y_[i]; }
  double importance_per_density() const { return importance_per_density_; }
  const Correction_table* correction_table() const { return table_; }
  // The most tiles that a traversal of the tree may subdivide, checked as it grows.
  std::size_t most_refined_tiles() const { return most_refined_tiles_; }

  // Throws std::length_error once a traversal has subdivided more than
  // most_refined_tiles() tiles.
  void check_refinement(std::size_t refined_tiles) const
  {
    if(refined_tiles > most_refined_tiles_) throw_overrefined();
  }

  // Importance at (x, y), read at the nearest point of the region: the density
  // is never evaluated outside the region, and tiles that straddle its border
  // see the density inside it.
  CGAL_PENROSE_HOT_INLINE double importance(double x, double y) const
  {
    const double i = density(x, y) * importance_per_density_;
    if(!(i < max_importance_)) throw_too_dense(clamp_x(x), clamp_y(y), i);
    return i;
  }

  // The unscaled density, checked, at the nearest point of the region.
  double density(double x, double y) const
  {
    const double cx = clamp_x(x), cy = clamp_y(y);
    return checked(density_(cx, cy), cx, cy);
  }

  // Whether a tile of level `level` whose F-code has Fibonacci value
  // `threshold` is subdivided: only if a sample of its subtree can land in
  // the region (the uniform levels of C.6 are subdivided only there), and
  // be active.
  // Every sample born below it has a threshold of at least `threshold` +
  // F(2 level + 2) (C.7), which is also above the least importance that
  // needs the level (C.5): a tile whose thresholds are all out of reach is a
  // leaf, which spares the idle last level just past a level boundary.
  CGAL_PENROSE_HOT_INLINE bool should_refine(int level, std::uint64_t threshold,
                     const double* x, const double* y, const double* importance) const
  {
    return should_refine(level, threshold, x, y, importance, region_window_);
  }

  // The same, for a traversal that wants only the samples of `window`, a
  // part of the region: a tile is subdivided only if a sample of its subtree
  // can land in the window. Where it is, the decision is the one of the whole
  // region, so that the samples of the window are those of the region.
  CGAL_PENROSE_HOT_INLINE bool should_refine(int level, std::uint64_t threshold, const double* x, const double* y,
                                             const double* importance, const Sample_window& window) const
  {
    const double bx0 = (std::min)({x[0], x[1], x[2]}), bx1 = (std::max)({x[0], x[1], x[2]});
    const double by0 = (std::min)({y[0], y[1], y[2]}), by1 = (std::max)({y[0], y[1], y[2]});
    // the samples born below the tile, at level + 1 or deeper, land within m of it
    const double m = margin_factor_ * scale_[level + 1];
    if(bx1 < window.x0 - m || bx0 > window.x1 + m || by1 < window.y0 - m || by0 > window.y1 + m) return false;
    if(level < uniform_levels) return true;
    const double least = static_cast<double>(threshold + fibonacci().fib[2 * level + 2]);
    // the corners decide when they already reach a threshold: the bound over
    // the tile, or the centroid, is asked only when they do not
    double imax = (std::max)({importance[0], importance[1], importance[2]});
    if(!(imax >= least)) {
      if(bound_) {
        const double cx0 = clamp_x(bx0), cx1 = clamp_x(bx1), cy0 = clamp_y(by0), cy1 = clamp_y(by1);
        imax = checked_bound(bound_(cx0, cy0, cx1, cy1), cx0, cy0, cx1, cy1) * importance_per_density_;
      } else {
        imax = this->importance((x[0] + x[1] + x[2]) / 3., (y[0] + y[1] + y[2]) / 3.);
      }
    }
    if(!(imax >= least)) return false;
    if(level >= finest_level_) throw_too_fine(level + 1);
    return true;
  }

  // Threshold test (C.7), then correction (C.9). Returns false for a sample
  // that is not active; `s` is filled in either way for an active one.
  CGAL_PENROSE_HOT_INLINE bool activate(double x, double y, double importance, const Sample_birth& b, Placed_sample& s) const
  {
    if(!(importance >= static_cast<double>(b.threshold))) return false;
    const auto& li = fibonacci().level_importance;
    int leaf = (std::max)(1, int(b.level));
    while(leaf < max_level && importance >= li[leaf + 1]) ++leaf;
    const int shift = leaf - b.level;
    s.reference_x = x; s.reference_y = y;
    s.importance = importance;
    s.threshold = b.threshold;
    s.leaf_level = leaf;
    s.leaf_code = b.code << (2 * shift);
    s.key = sample_key(b);
    s.leaf_direction = static_cast<std::uint8_t>((b.direction + 10 * shift) % 20);
    s.structural_index = structural_index_[s.leaf_code & (structural_index_.size() - 1)];
    s.importance_index = importance_bins_(importance);
    s.x = x; s.y = y;
    if(table_ != nullptr && table_->vectors != nullptr) {
      const float* ab = table_->at(s.importance_index, s.structural_index);
      const Direction_table& u = directions();
      const int d = s.leaf_direction, e = (d + 5) % 20;
      const double sl = scale_[leaf];
      s.x = x + sl * (ab[0] * u.x[d] + ab[1] * u.x[e]);
      s.y = y + sl * (ab[0] * u.y[d] + ab[1] * u.y[e]);
    }
    return true;
  }

  bool contains(double x, double y) const
  {
    return x >= xmin_ && x <= xmax_ && y >= ymin_ && y <= ymax_;
  }

  double checked(double v, double x, double y) const
  {
    if(v >= 0. && v < std::numeric_limits<double>::infinity()) return v;
    throw_bad_density(x, y, v);
  }

  double checked_bound(double v, double x0, double y0, double x1, double y1) const
  {
    if(v >= 0. && v < std::numeric_limits<double>::infinity()) return v;
    throw_bad_bound(x0, y0, x1, y1, v);
  }

private:
  // the messages are built out of line, to keep the checks of the hot path small
  [[noreturn]] static void throw_bad_density(double x, double y, double v)
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << "Penrose_importance_sampler: the density at (" << x << ", " << y << ") is " << v
        << "; it must be finite and non-negative";
    throw std::invalid_argument(msg.str());
  }

  // the bound, not the density, is wrong: the message names it
  [[noreturn]] static void throw_bad_bound(double x0, double y0, double x1, double y1, double v)
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << "Penrose_importance_sampler: density_upper_bound over [" << x0 << ", " << x1 << "] x [" << y0 << ", "
        << y1 << "] is " << v << "; it must be finite and non-negative";
    throw std::invalid_argument(msg.str());
  }

  [[noreturn]] void throw_overrefined() const
  {
    std::ostringstream msg;
    msg.precision(3);
    msg << "Penrose_importance_sampler: more than " << double(most_refined_tiles_) << " tiles refined for about "
        << expected_points_ << " points expected (at most " << most_refined_tiles_per_point << " a point, plus "
        << least_refinement_budget << ")" << overrefinement_hint;
    throw std::length_error(msg.str());
  }

  // (x, y): where the density was evaluated
  [[noreturn]] void throw_too_dense(double x, double y, double importance) const
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << "Penrose_importance_sampler: the density at (" << x << ", " << y << ") is "
        << importance / importance_per_density_;
    msg.precision(3);
    msg << ", scaled to " << importance / importance_per_point_density_ << " points per unit area: more than the "
        << max_importance_ / importance_per_point_density_ << " that the " << max_level
        << " levels of the tile tree can represent in this region";
    throw std::invalid_argument(msg.str());
  }

  // The finest level that doubles resolve at the coordinates of the tile
  // tree. A vertex of level l is interpolated from coarser ones, one
  // rounding per level, so it lies within l + 2 ulps of the largest
  // coordinate from its exact place, while the triangles of the base
  // triangulation down to level l are at least sin 36 scale(l) high (0.588
  // scale(l), measured on constant, ramp, spike and step densities). Their
  // orientations are certain while two such errors stay below that height,
  // that is while scale(l) >= 3.4 (l + 2) ulps: 4 are asked.
  void set_finest_level()
  {
    largest_coordinate_ = (std::max)({std::abs(xmin_), std::abs(xmax_), std::abs(ymin_), std::abs(ymax_)});
    for(int i = 0; i < 3; ++i)
      largest_coordinate_ = (std::max)({largest_coordinate_, std::abs(root_x_[i]), std::abs(root_y_[i])});
    const double ulp = std::nextafter(largest_coordinate_, std::numeric_limits<double>::infinity()) - largest_coordinate_;
    auto resolved = [&](int level) { return scale_[level] >= 4. * (level + 2) * ulp; };
    finest_level_ = 0;
    while(finest_level_ < max_level && resolved(finest_level_ + 1)) ++finest_level_;
    if(finest_level_ < uniform_levels) throw_too_fine(finest_level_ + 1);
  }

  [[noreturn]] void throw_too_fine(int level) const
  {
    if(level > max_level)
      throw std::length_error("Penrose_importance_sampler: the density needs more than "
                              + std::to_string(max_level) + " subdivision levels");
    std::ostringstream msg;
    msg.precision(3);
    msg << "Penrose_importance_sampler: the tiles of level " << level << " (" << scale_[level]
        << " across) are too fine for doubles to place at coordinates as large as " << largest_coordinate_
        << "; move the region nearer to the origin, or ask for fewer points";
    throw std::range_error(msg.str());
  }

  double clamp_x(double x) const { return (std::min)((std::max)(x, xmin_), xmax_); }
  double clamp_y(double y) const { return (std::min)((std::max)(y, ymin_), ymax_); }

  double xmin_, ymin_, xmax_, ymax_;
  Sample_window region_window_;
  Density density_;
  Density_bound bound_;
  const Correction_table* table_;
  double expected_points_;
  std::size_t most_refined_tiles_;
  double root_scale_;
  double importance_per_point_density_;  // of a density of one point per unit area
  double importance_per_density_;
  double margin_factor_;
  double largest_coordinate_;  // of the region and the root tile
  int finest_level_;            // see set_finest_level()
  double max_importance_;  // beyond it the importance needs more than max_level levels
  int structural_bits_;
  Importance_bins importance_bins_;
  std::vector<unsigned> structural_index_;  // Fibonacci value of every low code
  std::array<double, max_level + 2> scale_;
  std::array<double, 3> root_x_, root_y_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLING_CONTEXT_H
