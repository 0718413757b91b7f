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
//   mesh_check delaunay MESH.ply [X0 Y0 X1 Y1]
//     checks a binary PLY of `--streamed` (x, y as doubles; uint or uint64
//     indices) against CGAL's Delaunay_triangulation_2 of its points: every
//     triangle is CGAL's, once, counter-clockwise, and there are 2N - h - 2
//     of them; with a window, only the triangles whose circumcentres lie in
//     it, against CGAL's triangulation of the points around it (for files
//     too large to triangulate whole). Exits with status 1 if not.

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Canonical_circumcircle.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
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

typedef CGAL::Exact_predicates_inexact_constructions_kernel K2;
typedef std::array<std::uint64_t, 3> Face;

Face rotated(Face f)
{
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

// The circumcentre as the windows compute it, or NaN for a flat triangle.
std::array<double, 2> circumcentre(const K2::Point_2& a, const K2::Point_2& b, const K2::Point_2& c)
{
  using CGAL::internal::Penrose::Xy;
  const auto cc = CGAL::internal::Penrose::canonical_circumcircle(Xy{a.x(), a.y()}, Xy{b.x(), b.y()}, Xy{c.x(), c.y()});
  return {cc.x, cc.y};
}

struct Ply_reader
{
  std::ifstream in;
  std::uint64_t vertices = 0, faces = 0;
  bool wide = false;

  explicit Ply_reader(const std::string& file) : in(file, std::ios::binary)
  {
    std::string line, word;
    if(!std::getline(in, line) || line != "ply") throw std::runtime_error(file + ": not a PLY file");
    while(std::getline(in, line) && line != "end_header") {
      std::istringstream l(line);
      l >> word;
      if(word == "format" && (l >> word, word != "binary_little_endian")) throw std::runtime_error(file + ": not binary little-endian");
      if(word == "element") {
        std::string what;
        std::uint64_t n;
        l >> what >> n;
        (what == "vertex" ? vertices : faces) = n;
      }
      if(word == "property" && line.find("vertex_indices") != std::string::npos) wide = line.find("uint64") != std::string::npos;
    }
    if(!in) throw std::runtime_error(file + ": truncated header");
  }

  std::vector<K2::Point_2> points()
  {
    std::vector<double> xy(2 * vertices);
    in.read(reinterpret_cast<char*>(xy.data()), std::streamsize(xy.size() * sizeof(double)));
    if(!in) throw std::runtime_error("truncated vertices");
    std::vector<K2::Point_2> p;
    p.reserve(vertices);
    for(std::uint64_t i = 0; i < vertices; ++i) p.emplace_back(xy[2 * i], xy[2 * i + 1]);
    return p;
  }

  Face face()
  {
    unsigned char n = 0;
    in.read(reinterpret_cast<char*>(&n), 1);
    if(!in || n != 3) throw std::runtime_error("a face that is not a triangle, or truncated faces");
    Face f;
    for(auto& v : f) {
      if(wide) in.read(reinterpret_cast<char*>(&v), 8);
      else { std::uint32_t u; in.read(reinterpret_cast<char*>(&u), 4); v = u; }
    }
    if(!in) throw std::runtime_error("truncated faces");
    return f;
  }
};

// The points on the boundary of the convex hull, those inside its edges
// included, as Delaunay_triangulation_2 counts them (the degree of its
// infinite vertex): Andrew's monotone chain, turning only at strict turns.
std::size_t points_on_hull(std::vector<K2::Point_2> p)
{
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if(p.size() < 3) return p.size();
  auto chain = [&](auto begin, auto end) {
    std::vector<K2::Point_2> c;
    for(auto it = begin; it != end; ++it) {
      while(c.size() >= 2 && CGAL::orientation(c[c.size() - 2], c.back(), *it) == CGAL::RIGHT_TURN) c.pop_back();
      c.push_back(*it);
    }
    return c.size() - 1;  // the last point starts the other chain
  };
  return chain(p.begin(), p.end()) + chain(p.rbegin(), p.rend());
}

int check_delaunay(const std::string& file, const double* window)
{
  Ply_reader ply(file);
  const std::vector<K2::Point_2> points = ply.points();
  double box[4] = {-1e300, -1e300, 1e300, 1e300};  // the points triangulated: all, or those around the window
  if(window) {
    const double g = 0.1 * std::max(window[2] - window[0], window[3] - window[1]);
    box[0] = window[0] - g; box[1] = window[1] - g; box[2] = window[2] + g; box[3] = window[3] + g;
  }
  auto in_box = [&](const K2::Point_2& p) { return p.x() >= box[0] && p.y() >= box[1] && p.x() <= box[2] && p.y() <= box[3]; };
  auto in_window = [&](const std::array<double, 2>& c) {
    return !window || (c[0] >= window[0] && c[1] >= window[1] && c[0] < window[2] && c[1] < window[3]);
  };
  std::vector<std::pair<K2::Point_2, std::uint64_t>> chosen;
  for(std::uint64_t i = 0; i < points.size(); ++i)
    if(in_box(points[i])) chosen.emplace_back(points[i], i);
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::uint64_t, K2> Vb;
  typedef CGAL::Delaunay_triangulation_2<K2, CGAL::Triangulation_data_structure_2<Vb>> Dt;
  const Dt dt(chosen.begin(), chosen.end());
  std::set<Face> reference;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const auto c = circumcentre(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if(window && !in_window(c)) continue;
    reference.insert(rotated({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  }
  std::set<Face> found;
  std::uint64_t twice = 0, not_ccw = 0;
  for(std::uint64_t k = 0; k < ply.faces; ++k) {
    const Face f = ply.face();
    if(f[0] >= points.size() || f[1] >= points.size() || f[2] >= points.size()) throw std::runtime_error("an index past the vertices");
    if(window) {
      if(!in_box(points[f[0]]) || !in_box(points[f[1]]) || !in_box(points[f[2]])) continue;
      if(!in_window(circumcentre(points[f[0]], points[f[1]], points[f[2]]))) continue;
    }
    if(CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::LEFT_TURN) ++not_ccw;
    if(!found.insert(rotated(f)).second) ++twice;
  }
  const std::size_t hull = window ? points_on_hull(points) : dt.degree(dt.infinite_vertex());
  std::size_t missing = 0;
  for(const Face& f : reference) missing += found.count(f) == 0;
  const std::size_t extra = found.size() + missing - reference.size();
  std::cout << points.size() << " points, " << ply.faces << " triangles in the file, " << found.size()
            << " checked: " << missing << " of CGAL's missing, " << extra << " not CGAL's, " << twice << " twice, "
            << not_ccw << " clockwise";
  const bool count_holds = ply.faces == 2 * points.size() - hull - 2;
  std::cout << "; 2N - h - 2 = " << 2 * points.size() - hull - 2;
  std::cout << "\n";
  return missing || extra || twice || not_ccw || !count_holds ? 1 : 0;
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
    if(command == "delaunay" && (argc == 3 || argc == 7)) {
      double w[4];
      for(int k = 0; k < 4 && argc == 7; ++k) w[k] = std::atof(argv[3 + k]);
      return check_delaunay(argv[2], argc == 7 ? w : nullptr);
    }
    std::cerr << "usage: mesh_check border-angle MESH [X0 Y0 X1 Y1] | tiles K PREFIX | delaunay MESH.ply [X0 Y0 X1 Y1]\n";
  } catch(const std::exception& e) {
    std::cerr << "mesh_check: " << e.what() << "\n";
  }
  return 2;
}
