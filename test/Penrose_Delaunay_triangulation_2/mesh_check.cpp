// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks the OFF meshes that penrose_mesh writes, for the command-line tests:
//
//   mesh_check border-angle MESH [X0 Y0 X1 Y1]
//     prints the smallest angle, in degrees, of the triangles with a vertex on
//     the border of the mesh's bounding box, or on that of the rectangle
//     X0 Y0 X1 Y1 (the region of which the mesh is a tile);
//   mesh_check tiles K PREFIX
//     checks the tiles PREFIX_I_J.off of `--tiles K`: each covers its
//     rectangle (the triangles' area is that of its bounding box), the
//     rectangles meet exactly, and every vertex on a tile edge shared with
//     a neighbour is a vertex of the neighbour, with the same coordinates
//     bit for bit. Prints what fails and exits with status 1.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;

struct Mesh
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  double x0 = 0., y0 = 0., x1 = 0., y1 = 0.;  // the bounding box
};

Mesh read(const std::string& file)
{
  Mesh m;
  if(!CGAL::IO::read_OFF(file, m.points, m.faces) || m.points.empty())
    throw std::runtime_error(file + ": cannot read");
  m.x0 = m.x1 = m.points[0].x();
  m.y0 = m.y1 = m.points[0].y();
  for(const Point& p : m.points) {
    m.x0 = std::min(m.x0, p.x()); m.x1 = std::max(m.x1, p.x());
    m.y0 = std::min(m.y0, p.y()); m.y1 = std::max(m.y1, p.y());
  }
  return m;
}

bool on_border(const std::array<double, 4>& r, const Point& p)
{
  return p.x() == r[0] || p.y() == r[1] || p.x() == r[2] || p.y() == r[3];
}

double smallest_angle(const Point& a, const Point& b, const Point& c)
{
  const Point* p[3] = {&a, &b, &c};
  double smallest = 180.;
  for(int i = 0; i < 3; ++i) {
    const Point &o = *p[i], &u = *p[(i + 1) % 3], &v = *p[(i + 2) % 3];
    const double ux = u.x() - o.x(), uy = u.y() - o.y(), vx = v.x() - o.x(), vy = v.y() - o.y();
    const double angle = std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180. / M_PI;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

double smallest_border_angle(const Mesh& m, const std::array<double, 4>& r)
{
  double smallest = 180.;
  for(const auto& f : m.faces) {
    const Point &a = m.points[f[0]], &b = m.points[f[1]], &c = m.points[f[2]];
    if(on_border(r, a) || on_border(r, b) || on_border(r, c)) smallest = std::min(smallest, smallest_angle(a, b, c));
  }
  return smallest;
}

double area(const Mesh& m)
{
  double twice = 0.;
  for(const auto& f : m.faces) {
    const Point &a = m.points[f[0]], &b = m.points[f[1]], &c = m.points[f[2]];
    twice += (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
  }
  return 0.5 * twice;
}

// The vertices on the line x = `at` (vertical) or y = `at`.
std::set<std::array<double, 3>> on_line(const Mesh& m, bool vertical, double at)
{
  std::set<std::array<double, 3>> s;
  for(const Point& p : m.points)
    if((vertical ? p.x() : p.y()) == at) s.insert({p.x(), p.y(), p.z()});
  return s;
}

int check_tiles(int k, const std::string& prefix)
{
  std::vector<std::vector<Mesh>> tile(static_cast<std::size_t>(k));
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      tile[std::size_t(i)].push_back(read(prefix + "_" + std::to_string(i) + "_" + std::to_string(j) + ".off"));
  int failures = 0;
  auto fail = [&failures](const std::string& what) { std::cout << what << "\n"; ++failures; };
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j) {
      const Mesh& m = tile[std::size_t(i)][std::size_t(j)];
      const std::string name = "tile " + std::to_string(i) + " " + std::to_string(j);
      const double box = (m.x1 - m.x0) * (m.y1 - m.y0), a = area(m);
      if(!(std::abs(a - box) <= 1e-9 * box)) fail(name + ": the triangles' area " + std::to_string(a)
                                                  + " is not that of the rectangle, " + std::to_string(box));
      for(int side = 0; side < 2; ++side) {  // the east and the north neighbour
        const bool east = side == 0;
        if((east ? i : j) + 1 == k) continue;
        const Mesh& n = east ? tile[std::size_t(i + 1)][std::size_t(j)] : tile[std::size_t(i)][std::size_t(j + 1)];
        const double at = east ? m.x1 : m.y1;
        if(at != (east ? n.x0 : n.y0)) {
          fail(name + ": does not meet its " + (east ? "east" : "north") + " neighbour");
          continue;
        }
        const auto mine = on_line(m, east, at), theirs = on_line(n, east, at);
        std::size_t unmatched = 0;
        for(const auto& p : mine) unmatched += theirs.count(p) == 0;
        for(const auto& p : theirs) unmatched += mine.count(p) == 0;
        if(unmatched || mine.size() < 2)
          fail(name + ": " + std::to_string(unmatched) + " unmatched vertices of " + std::to_string(mine.size())
               + " on its edge shared with the " + (east ? "east" : "north") + " neighbour");
      }
    }
  std::cout << k * k << " tiles, " << failures << " failures\n";
  return failures ? 1 : 0;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const std::string command = argc > 1 ? argv[1] : "";
    if(command == "border-angle" && (argc == 3 || argc == 7)) {
      const Mesh m = read(argv[2]);
      std::array<double, 4> r{m.x0, m.y0, m.x1, m.y1};
      if(argc == 7)
        for(int k = 0; k < 4; ++k) r[std::size_t(k)] = std::atof(argv[3 + k]);
      std::cout << smallest_border_angle(m, r) << "\n";
      return 0;
    }
    if(command == "tiles" && argc == 4) return check_tiles(std::atoi(argv[2]), argv[3]);
    std::cerr << "usage: mesh_check border-angle MESH [X0 Y0 X1 Y1] | tiles K PREFIX\n";
  } catch(const std::exception& e) {
    std::cerr << "mesh_check: " << e.what() << "\n";
  }
  return 2;
}
