// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rasters for penrose_mesh: bilinear lookup over a rectangle, and the maps
// that turn an image or a height field into a sampling density.

#ifndef PENROSE_TOOLS_RASTER_MAPS_H
#define PENROSE_TOOLS_RASTER_MAPS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace penrose_tools {

// Index i clamped to [0, n).
inline std::size_t clamp_index(long i, std::size_t n) { return std::size_t(std::min(std::max(i, 0L), long(n) - 1)); }

// Pixel (i, j) of a w x h raster, the border repeated outside.
inline double clamped_at(const std::vector<double>& v, std::size_t w, std::size_t h, long i, long j)
{
  return v[clamp_index(j, h) * w + clamp_index(i, w)];
}

// A raster of `channels` values a pixel stretched over the rectangle
// [x0, x1] x [y0, y1], row 0 at the top; pixel (i, j) has its centre at
// u = i + 1/2, v = j + 1/2 in pixel coordinates.
template <class T>
struct Raster
{
  std::size_t width = 0, height = 0, channels = 1;
  std::vector<T> values;
  double x0 = 0., y0 = 0., x1 = 1., y1 = 1.;

  double u(double x) const { return (x - x0) / (x1 - x0) * double(width); }
  double v(double y) const { return (y1 - y) / (y1 - y0) * double(height); }
  double x(double u) const { return x0 + u / double(width) * (x1 - x0); }
  double y(double v) const { return y1 - v / double(height) * (y1 - y0); }
  const T* at(long i, long j) const { return &values[channels * (clamp_index(j, height) * width + clamp_index(i, width))]; }

  // The bilinear interpolation of channel c at (x, y), clamped at the border.
  double operator()(double x, double y, std::size_t c = 0) const
  {
    const double su = u(x) - 0.5, sv = v(y) - 0.5, fu = std::floor(su), fv = std::floor(sv);
    const double a = su - fu, b = sv - fv;
    const long i = long(fu), j = long(fv);
    return (1 - a) * (1 - b) * at(i, j)[c] + a * (1 - b) * at(i + 1, j)[c]
         + (1 - a) * b * at(i, j + 1)[c] + a * b * at(i + 1, j + 1)[c];
  }
};

// One pass of a box filter of the given radius over n lines of `length`
// values, value k of line l at v[l * line_step + k * step], with the border
// value repeated; `in` and `sum` are scratch space. The running sum runs over
// whole lines at once when the lines are the rows (step = width), so that
// columns are filtered in memory order.
inline void box_pass(double* v, std::size_t length, std::size_t step, std::size_t lines, std::size_t line_step,
                     int radius, std::vector<double>& in, std::vector<double>& sum)
{
  in.assign(v, v + (length - 1) * step + (lines - 1) * line_step + 1);
  sum.assign(lines, 0.);
  auto add = [&](long k, double sign) {
    const std::size_t c = clamp_index(k, length) * step;
    for(std::size_t l = 0; l < lines; ++l) sum[l] += sign * in[c + l * line_step];
  };
  for(long k = -radius; k <= radius; ++k) add(k, 1.);
  const double scale = 1. / double(2 * radius + 1);
  for(long k = 0; k < long(length); ++k) {
    for(std::size_t l = 0; l < lines; ++l) v[std::size_t(k) * step + l * line_step] = sum[l] * scale;
    add(k + radius + 1, 1.);
    add(k - radius, -1.);
  }
}

// Two passes of a box filter of the given radius, across then down: close to
// a Gaussian of standard deviation 1.15 r. The scratch space is allocated once:
// fresh pages for each pass cost as much as the filtering.
inline void smooth(std::vector<double>& v, std::size_t w, std::size_t h, int radius)
{
  if(radius < 1) return;
  std::vector<double> in, sum;
  in.reserve(v.size());
  sum.reserve(std::max(w, h));
  for(int pass = 0; pass < 2; ++pass) {
    for(std::size_t j = 0; j < h; ++j) box_pass(v.data() + j * w, w, 1, 1, 0, radius, in, sum);  // in cache
    box_pass(v.data(), h, w, w, 1, radius, in, sum);
  }
}

inline double mean(const std::vector<double>& v)
{
  return v.empty() ? 0. : std::accumulate(v.begin(), v.end(), 0.) / double(v.size());
}

// log(1 + L / mean L): the density of an HDR image then follows the contrast
// that the eye sees, and the result does not depend on the radiance's unit.
inline void log_transform(std::vector<double>& v)
{
  const double m = mean(v);
  if(m > 0.)
    for(double& x : v) x = std::log1p(std::max(x, 0.) / m);
}

// The Sobel gradient magnitude, smoothed over one pixel so that the samples
// gather on both sides of an edge, plus a floor of a tenth of its mean so that
// flat regions keep a few samples.
inline void gradient_magnitude(std::vector<double>& v, std::size_t w, std::size_t h)
{
  std::vector<double> g(v.size());
  auto at = [&](long i, long j) { return clamped_at(v, w, h, i, j); };
  for(long j = 0; j < long(h); ++j)
    for(long i = 0; i < long(w); ++i) {
      const double gx = at(i + 1, j - 1) + 2 * at(i + 1, j) + at(i + 1, j + 1) - at(i - 1, j - 1) - 2 * at(i - 1, j) - at(i - 1, j + 1);
      const double gy = at(i - 1, j + 1) + 2 * at(i, j + 1) + at(i + 1, j + 1) - at(i - 1, j - 1) - 2 * at(i, j - 1) - at(i + 1, j - 1);
      g[std::size_t(j) * w + std::size_t(i)] = std::sqrt(gx * gx + gy * gy);
    }
  smooth(g, w, h, 1);
  const double floor = 0.1 * mean(g);
  for(double& x : g) x += floor;
  v.swap(g);
}

inline void invert(std::vector<double>& v)
{
  const double top = v.empty() ? 0. : *std::max_element(v.begin(), v.end());
  for(double& x : v) x = top - x;
}

inline void apply_gamma(std::vector<double>& v, double gamma)
{
  if(gamma != 1.)
    for(double& x : v) x = std::pow(std::max(x, 0.), gamma);
}

/*
The density for meshing a height field: the largest absolute eigenvalue of
its Hessian, |hxx + hyy| / 2 + sqrt(((hxx - hyy) / 2)^2 + hxy^2), averaged
over blocks of `block` pixels and smoothed over a block more (the density
need not vary faster than the vertices are spaced, and a coarser raster is
sampled faster), raised to the power 2/3. Linear interpolation over a
triangle of diameter d errs by about kappa d^2 where the curvature is kappa;
with n = integral of rho vertices, the integral of (kappa / rho)^2, the squared
RMS error, is smallest for rho proportional to kappa^(2/3). A floor of a tenth
of the mean keeps flat regions meshed.
`dx`, `dy`: the size of a pixel in the plane; `heights` already scaled; `w`
and `h` become the dimensions of the result.
The curvature is computed a row at a time and added to its blocks at once:
the full-resolution map, as large as the heights, is never stored.
*/
inline std::vector<double> curvature_density(const std::vector<double>& heights, std::size_t& w, std::size_t& h,
                                             double dx, double dy, std::size_t block)
{
  const std::size_t bw = (w + block - 1) / block, bh = (h + block - 1) / block;
  std::vector<double> k(bw * bh, 0.), row(w);
  for(std::size_t j = 0; j < h; ++j) {
    // rows j - 1, j and j + 1, and columns i - 1 and i + 1, the border repeated
    const double* n = &heights[clamp_index(long(j) - 1, h) * w];
    const double* c = &heights[j * w];
    const double* s = &heights[clamp_index(long(j) + 1, h) * w];
    auto curvature = [&](std::size_t l, std::size_t i, std::size_t r) {
      const double hxx = (c[r] - 2 * c[i] + c[l]) / (dx * dx);
      const double hyy = (s[i] - 2 * c[i] + n[i]) / (dy * dy);
      const double hxy = (s[r] - n[r] - s[l] + n[l]) / (4 * dx * dy);
      const double d = 0.5 * (hxx - hyy);
      return 0.5 * std::abs(hxx + hyy) + std::sqrt(d * d + hxy * hxy);
    };
    row[0] = curvature(0, 0, std::min<std::size_t>(1, w - 1));
    for(std::size_t i = 1; i + 1 < w; ++i) row[i] = curvature(i - 1, i, i + 1);
    if(w > 1) row[w - 1] = curvature(w - 2, w - 1, w - 1);
    double* sum = &k[(j / block) * bw];
    for(std::size_t b = 0, i = 0; b < bw; ++b)
      for(const std::size_t end = std::min(w, i + block); i < end; ++i) sum[b] += row[i];
  }
  if(block > 1)  // the means, of fewer pixels at the right and bottom borders
    for(std::size_t bj = 0; bj < bh; ++bj)
      for(std::size_t bi = 0; bi < bw; ++bi)
        k[bj * bw + bi] /= double((std::min(w, (bi + 1) * block) - bi * block) * (std::min(h, (bj + 1) * block) - bj * block));
  w = bw;
  h = bh;
  smooth(k, w, h, 1);
  for(double& x : k) x = std::cbrt(x * x);
  const double floor = 0.1 * mean(k);
  for(double& x : k) x += floor;
  return k;
}

// Multiplies the density by 1 / (1 + d / d0), d the distance from the viewer
// at (vx, vy) and d0 a fiftieth of the raster's diagonal: a vertex then errs
// by about the same angle seen from the viewer, as in a view-dependent mesh.
// The weights are scaled so that the cell nearest the viewer keeps its
// density: a viewer far away gives a nearly uniform weighting, where the
// density underflowed to zero. Returns false if the distances overflow.
inline bool weight_by_viewer(Raster<double>& r, double vx, double vy)
{
  const double d0 = 0.02 * std::hypot(r.x1 - r.x0, r.y1 - r.y0);
  auto distance = [&](std::size_t i, std::size_t j) { return std::hypot(r.x(i + 0.5) - vx, r.y(j + 0.5) - vy); };
  double nearest = std::numeric_limits<double>::infinity();
  for(std::size_t j = 0; j < r.height; ++j)
    for(std::size_t i = 0; i < r.width; ++i) nearest = std::min(nearest, distance(i, j));
  if(!std::isfinite(nearest)) return false;
  for(std::size_t j = 0; j < r.height; ++j)
    for(std::size_t i = 0; i < r.width; ++i) r.values[j * r.width + i] *= (d0 + nearest) / (d0 + distance(i, j));
  return true;
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_RASTER_MAPS_H
