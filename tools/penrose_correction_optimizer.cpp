// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Offline optimiser of the correction vectors. For each importance index it
// samples the unit square at constant importance without correction, relaxes
// the points with Lloyd's algorithm (CGAL's Delaunay triangulation and its
// Voronoi dual), and averages the displacement from each raw point to its
// relaxed position per (importance index, structural index), in the frame of
// the sample's leaf tile divided by the leaf scale. Points near the border,
// whose cells the border distorts, are left out of the averages.
//
// It writes a C++ header; the command line that made it is recorded there.

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Depth_first_sampling.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace P = CGAL::internal::Penrose;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
typedef CGAL::Delaunay_triangulation_2<K, Tds> Delaunay;

struct Options
{
  unsigned bins = 21;
  int structural_bits = 6;
  double points = 20000;
  int iterations = 30;
  int runs_per_bin = 2;
  int rounds = 1;
  double separation = 0.;  // push apart Delaunay neighbours closer than this many d_max
  int polish_rounds = 0;   // rounds of separation alone, after the Lloyd rounds
  double push_weight = 1.; // weight, in a class average, of a point that was pushed
  std::string out;
};

static void usage()
{
  std::cerr << "usage: penrose_correction_optimizer --out FILE [--bins 21] [--structural-bits 6]\n"
               "         [--points 20000] [--iterations 30] [--runs-per-bin 2] [--rounds 1]\n"
               "         [--separation 0] [--polish-rounds 0] [--push-weight 1]\n";
  std::exit(2);
}

// The Delaunay triangulation of p, each vertex knowing its index in p.
static Delaunay delaunay_of(const std::vector<K::Point_2>& p)
{
  std::vector<std::pair<K::Point_2, std::size_t>> indexed;
  indexed.reserve(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) indexed.emplace_back(p[i], i);
  return Delaunay(indexed.begin(), indexed.end());
}

// Moves every point not marked fixed to the centroid of its Voronoi cell. The
// fixed points, a band along the border, keep the other cells bounded.
static void lloyd_step(std::vector<K::Point_2>& p, const std::vector<bool>& fixed)
{
  const Delaunay dt = delaunay_of(p);
  std::vector<K::Point_2> next = p;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    if(fixed[v->info()]) continue;
    auto f = dt.incident_faces(v), done = f;
    std::vector<K::Point_2> cell;
    bool bounded = true;
    do {
      if(dt.is_infinite(f)) { bounded = false; break; }
      cell.push_back(dt.circumcenter(f));
    } while(++f != done);
    if(!bounded) continue;
    double a = 0., cx = 0., cy = 0.;
    for(std::size_t i = 0; i < cell.size(); ++i) {
      const K::Point_2& q = cell[i];
      const K::Point_2& r = cell[(i + 1) % cell.size()];
      const double w = q.x() * r.y() - r.x() * q.y();
      a += w; cx += (q.x() + r.x()) * w; cy += (q.y() + r.y()) * w;
    }
    const double x = cx / (3. * a), y = cy / (3. * a);
    if(a > 0. && std::isfinite(x) && std::isfinite(y)) next[v->info()] = K::Point_2(x, y);
  }
  p.swap(next);
}

// Moves the two ends of every Delaunay edge shorter than `target` apart until
// it has that length: close pairs are what the averages of Lloyd's moves
// leave, and a per-class average then carries the separation into the table.
static std::vector<bool> separate(std::vector<K::Point_2>& p, const std::vector<bool>& fixed, double target)
{
  const Delaunay dt = delaunay_of(p);
  std::vector<K::Vector_2> push(p.size(), K::Vector_2(0, 0));
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(Delaunay::cw(e->second)), b = e->first->vertex(Delaunay::ccw(e->second));
    const K::Vector_2 d = b->point() - a->point();
    const double len = std::sqrt(d.squared_length());
    if(len >= target || len == 0.) continue;
    const K::Vector_2 u = d * (0.5 * (target - len) / len);
    push[a->info()] = push[a->info()] - u;
    push[b->info()] = push[b->info()] + u;
  }
  std::vector<bool> pushed(p.size(), false);
  for(std::size_t i = 0; i < p.size(); ++i)
    if(!fixed[i] && push[i] != K::Vector_2(0, 0)) { p[i] = p[i] + push[i]; pushed[i] = true; }
  return pushed;
}

// One pass over all importance indices: the mean displacement, per class, from
// the raw points to the relaxed positions of the points `start` corrects.
static std::vector<float> relax_and_average(const Options& o, const P::Correction_table* start,
                                            int iterations, double push_weight)
{
  const unsigned columns = P::number_of_structural_indices(o.structural_bits);
  const P::Importance_bins importance_bins(o.bins);
  std::vector<double> sum(2 * o.bins * columns, 0.);
  std::vector<double> count(o.bins * columns, 0.);
  const double phi2 = P::golden_ratio * P::golden_ratio;
  // On the unit square about 0.1 I points come out: the level holding the target.
  const int level = int(std::floor(std::log1p(std::sqrt(5.) * 10. * o.points) / std::log(phi2)));

  for(unsigned bin = 0; bin < o.bins; ++bin)
    for(int run = 0; run < o.runs_per_bin; ++run) {
      const double f = (bin + (run + 0.5) / o.runs_per_bin) / o.bins;
      const double importance = (std::pow(phi2, level + f) - 1.) / std::sqrt(5.);
      P::Sampling_context unit(0, 0, 1, 1, [](double, double) { return 1.; }, nullptr, 1., nullptr);
      const double density = importance / unit.importance_per_density();
      P::Sampling_context c(0, 0, 1, 1, [density](double, double) { return density; }, nullptr, 1., start);

      std::vector<P::Placed_sample> raw;
      P::Placed_sample s;
      P::for_each_sample_depth_first(c, [&](double x, double y, double i, const P::Sample_birth& b) {
        if(c.activate(x, y, i, b, s) && c.contains(x, y)) raw.push_back(s);
      });
      const double d_max = std::sqrt(2. / (std::sqrt(3.) * raw.size()));
      std::vector<K::Point_2> p;
      std::vector<bool> fixed;
      for(const auto& r : raw) {
        p.emplace_back(r.x, r.y);
        fixed.push_back(std::min({r.x, r.y, 1. - r.x, 1. - r.y}) < 3. * d_max);
      }
      for(int it = 0; it < iterations; ++it) lloyd_step(p, fixed);
      std::vector<bool> pushed(p.size(), false);
      if(o.separation > 0.) pushed = separate(p, fixed, o.separation * d_max);

      const double band = 10. * d_max;
      const P::Direction_table& u = P::directions();
      for(std::size_t i = 0; i < raw.size(); ++i) {
        const P::Placed_sample& r = raw[i];
        const double rx = r.reference_x, ry = r.reference_y;
        if(rx < band || rx > 1 - band || ry < band || ry > 1 - band) continue;
        const double dx = p[i].x() - rx, dy = p[i].y() - ry;
        const double sl = c.scale(r.leaf_level);
        const int d = r.leaf_direction, e = (d + 5) % 20;
        const unsigned is = unsigned(P::fibonacci_value(r.leaf_code & ((1u << o.structural_bits) - 1), o.structural_bits));
        const unsigned iv = importance_bins(r.importance);
        const std::size_t k = iv * columns + is;
        const double w = pushed[i] ? push_weight : 1.;
        sum[2 * k] += w * (dx * u.x[d] + dy * u.y[d]) / sl;
        sum[2 * k + 1] += w * (dx * u.x[e] + dy * u.y[e]) / sl;
        count[k] += w;
      }
      std::cerr << "bin " << bin << " run " << run << ": " << raw.size() << " points\n";
    }
  std::vector<float> table(2 * o.bins * columns, 0.f);
  for(std::size_t k = 0; k < count.size(); ++k)
    if(count[k] > 0.) {
      table[2 * k] = float(sum[2 * k] / count[k]);
      table[2 * k + 1] = float(sum[2 * k + 1] / count[k]);
    }
  return table;
}

int main(int argc, char** argv)
{
  Options o;
  std::ostringstream command;
  command << "penrose_correction_optimizer";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a != "--out") command << ' ' << a << (i + 1 < argc ? std::string(" ") + argv[i + 1] : "");
    if(i + 1 >= argc) usage();
    const char* v = argv[++i];
    if(a == "--bins") o.bins = unsigned(std::atoi(v));
    else if(a == "--structural-bits") o.structural_bits = std::atoi(v);
    else if(a == "--points") o.points = std::atof(v);
    else if(a == "--iterations") o.iterations = std::atoi(v);
    else if(a == "--runs-per-bin") o.runs_per_bin = std::atoi(v);
    else if(a == "--rounds") o.rounds = std::atoi(v);
    else if(a == "--separation") o.separation = std::atof(v);
    else if(a == "--polish-rounds") o.polish_rounds = std::atoi(v);
    else if(a == "--push-weight") o.push_weight = std::atof(v);
    else if(a == "--out") o.out = v;
    else usage();
  }
  if(o.out.empty() || o.bins < 1 || o.structural_bits < 2 || o.structural_bits % 2 || o.points < 100 || o.rounds < 1)
    usage();

  const unsigned columns = P::number_of_structural_indices(o.structural_bits);
  // Round 0 relaxes the raw points; each later round relaxes the points that
  // the previous round's table corrects, and measures from the raw points again.
  std::vector<float> table;
  for(int round = 0; round < o.rounds + o.polish_rounds; ++round) {
    const P::Correction_table current = {o.bins, o.structural_bits, table.data()};
    const bool polish = round >= o.rounds;
    table = relax_and_average(o, round == 0 ? nullptr : &current, polish ? 0 : o.iterations,
                              polish ? o.push_weight : 1.);
  }
  // written whole, or not at all: a run cut short leaves the header that the build includes as it was
  std::ostringstream out;
  out << "// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.\n"
         "// SPDX-License-Identifier: GPL-3.0-or-later\n//\n"
         "// GENERATED FILE, do not edit. Made by tools/penrose_correction_optimizer:\n//   "
      << command.str() << " --out <this file>\n"
         "// (README.md, \"Correction vectors\"). Rows: importance index; columns:\n"
         "// structural index; entries (a, b) in leaf scales, along u(d_leaf) and u(d_leaf + 5).\n\n"
         "#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_VECTORS_H\n"
         "#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_VECTORS_H\n\n"
         "#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Correction_table.h>\n\n"
         "namespace CGAL {\nnamespace internal {\nnamespace Penrose {\n\n"
         "inline const Correction_table& default_correction_table()\n{\n"
         "  static const float vectors[] = {\n";
  char buf[64];
  for(unsigned bin = 0; bin < o.bins; ++bin) {
    out << "    // importance index " << bin << "\n   ";
    for(unsigned col = 0; col < columns; ++col) {
      const std::size_t k = bin * columns + col;
      std::snprintf(buf, sizeof buf, " %.6ff, %.6ff,", double(table[2 * k]), double(table[2 * k + 1]));
      out << buf;
      if(col % 4 == 3 && col + 1 < columns) out << "\n   ";
    }
    out << "\n";
  }
  out << "  };\n  static const Correction_table table = { " << o.bins << "u, " << o.structural_bits
      << ", vectors };\n  return table;\n}\n\n"
         "} // namespace Penrose\n} // namespace internal\n} // namespace CGAL\n\n"
         "#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_VECTORS_H\n";
  try {
    CGAL::IO::internal::write_bytes(o.out, out.str());
  } catch(const std::exception& e) {
    std::cerr << "penrose_correction_optimizer: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
