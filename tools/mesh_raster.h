// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangle meshes against rasters, for penrose_mesh: visiting the pixels a
// mesh covers (to measure its error or render it back to an image), the
// regular grid mesh it is compared with, and line drawings.

#ifndef PENROSE_TOOLS_MESH_RASTER_H
#define PENROSE_TOOLS_MESH_RASTER_H

#include "raster_maps.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace penrose_tools {

// A triangle mesh in the plane; faces index the vertices, counter-clockwise.
struct Plane_mesh
{
  std::vector<double> x, y;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

// The regular grid with about n vertices over the raster's rectangle, with
// as many vertices per unit length across as down, each cell cut in two.
template <class T>
Plane_mesh grid_mesh(const Raster<T>& r, std::size_t n)
{
  const double w = r.x1 - r.x0, h = r.y1 - r.y0;
  const std::size_t nx = std::max<std::size_t>(2, std::size_t(std::lround(std::sqrt(double(n) * w / h))));
  const std::size_t ny = std::max<std::size_t>(2, std::size_t(std::lround(double(n) / double(nx))));
  Plane_mesh m;
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      m.x.push_back(r.x0 + w * double(i) / double(nx - 1));
      m.y.push_back(r.y0 + h * double(j) / double(ny - 1));
    }
  for(std::uint32_t j = 0; j + 1 < ny; ++j)
    for(std::uint32_t i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = j * std::uint32_t(nx) + i, b = a + 1, c = a + std::uint32_t(nx), d = c + 1;
      m.faces.push_back({a, b, d});
      m.faces.push_back({a, d, c});
    }
  return m;
}

/*
Calls f(k, face, w) once for each pixel k = j * width + i of the raster whose
centre lies in a face of the mesh, w holding the barycentric coordinates of
the centre in that face. A pixel on an edge goes to the first face visited.
`done` becomes the mask of the pixels covered; returns their number.
*/
template <class T, class F>
std::size_t for_each_covered_pixel(const Plane_mesh& m, const Raster<T>& r, std::vector<char>& done, F&& f)
{
  done.assign(r.width * r.height, 0);
  std::size_t covered = 0;
  for(std::size_t face = 0; face < m.faces.size(); ++face) {
    double u[3], v[3];
    for(int i = 0; i < 3; ++i) {
      u[i] = r.u(m.x[m.faces[face][i]]);
      v[i] = r.v(m.y[m.faces[face][i]]);
    }
    const double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if(area == 0.) continue;
    // w[e] = A[e] u + B[e] v + C[e]: the area of (p, a, b) over that of the face, (e, a, b) in turn
    double A[3], B[3], C[3];
    for(int e = 0; e < 3; ++e) {
      const int a = (e + 1) % 3, b = (e + 2) % 3;
      A[e] = (v[a] - v[b]) / area;
      B[e] = (u[b] - u[a]) / area;
      C[e] = (u[a] * v[b] - u[b] * v[a]) / area;
    }
    const long j0 = std::max(0L, long(std::ceil(std::min({v[0], v[1], v[2]}) - 0.5)));
    const long j1 = std::min(long(r.height) - 1, long(std::floor(std::max({v[0], v[1], v[2]}) - 0.5)));
    for(long j = j0; j <= j1; ++j) {
      const double pv = j + 0.5;
      double lo = std::min({u[0], u[1], u[2]}), hi = std::max({u[0], u[1], u[2]});
      for(int e = 0; e < 3; ++e)  // the span of the row where w[e] >= 0
        if(A[e] > 0.) lo = std::max(lo, -(B[e] * pv + C[e]) / A[e] - 1e-9);
        else if(A[e] < 0.) hi = std::min(hi, -(B[e] * pv + C[e]) / A[e] + 1e-9);
      const long i0 = std::max(0L, long(std::ceil(lo - 0.5))), i1 = std::min(long(r.width) - 1, long(std::floor(hi - 0.5)));
      for(long i = i0; i <= i1; ++i) {
        const double pu = i + 0.5;
        std::array<double, 3> w;
        for(int e = 0; e < 3; ++e) w[e] = A[e] * pu + B[e] * pv + C[e];
        if(w[0] < -1e-9 || w[1] < -1e-9 || w[2] < -1e-9) continue;
        const std::size_t k = std::size_t(j) * r.width + std::size_t(i);
        if(done[k]) continue;
        done[k] = 1;
        ++covered;
        f(k, face, w);
      }
    }
  }
  return covered;
}

// An 8-bit RGB picture, row 0 at the top.
struct Picture
{
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;

  void blend(long i, long j, const unsigned char colour[3], double alpha)
  {
    if(i < 0 || j < 0 || i >= width || j >= height) return;
    unsigned char* p = &rgb[3 * (std::size_t(j) * std::size_t(width) + std::size_t(i))];
    for(int c = 0; c < 3; ++c) p[c] = (unsigned char)std::lround((1 - alpha) * p[c] + alpha * colour[c]);
  }

  // A line between two points in pixel coordinates, one pixel wide.
  void line(double u0, double v0, double u1, double v1, const unsigned char colour[3], double alpha)
  {
    const int steps = int(std::ceil(std::max(std::abs(u1 - u0), std::abs(v1 - v0)))) + 1;
    for(int s = 0; s <= steps; ++s) {
      const double t = double(s) / steps;
      blend(long(std::floor(u0 + t * (u1 - u0))), long(std::floor(v0 + t * (v1 - v0))), colour, alpha);
    }
  }
};

} // namespace penrose_tools

#endif // PENROSE_TOOLS_MESH_RASTER_H
