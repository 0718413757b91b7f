// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// penrose_mesh: samples a density over a rectangle with the Penrose
// importance sampler, triangulates the samples with
// Penrose_Delaunay_triangulation_2 and writes the points, the mesh, drawings
// and statistics. The density comes from a formula, an image or the
// curvature of a height field; meshes of images and terrains are compared
// with the regular grid of as many vertices.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>
#include <CGAL/fit_terrain_heights.h>
#include <CGAL/refine_terrain_by_greedy_insertion.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_rgb_image.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/write_triangulation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <stb/stb_image_write.h>

#include "border_points.h"
#include "border_refinement.h"
#include "mesh_options.h"
#include "mesh_raster.h"
#include "progress_bar.h"
#include "raster_maps.h"
#include "streamed_ply.h"
#include "svg_writer.h"
#include "tiles.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#endif

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Penrose_importance_sampler<K> Sampler;
// Every mesh is a terrain: the triangulation is of the points' x and y, and
// z is the height (zero without a height field).
typedef CGAL::Projection_traits_xy_3<K> Gt;
typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Gt> Vb;  // index of the point
typedef CGAL::Triangulation_data_structure_2<Vb, CGAL::Triangulation_face_base_2<Gt>> Tds;
typedef CGAL::Penrose_Delaunay_triangulation_2<Gt, Tds> Triangulation;
typedef Triangulation::Vertex_handle Vertex_handle;
using penrose_tools::Raster;

using penrose_tools::Options;
using penrose_tools::usage_error;

// Whether every value is finite: an option that overflows them is refused by name.
bool all_finite(const std::vector<double>& v)
{
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

bool all_zero(const std::vector<double>& v)
{
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.; });
}

std::string text(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What the run reads: an image (its colours for display and reconstruction),
// or a height field; and the density as a raster when it comes from either.
struct Input
{
  std::string file;
  Raster<float> colours;    // 3 channels, display values in [0, 1]; empty unless an image
  Raster<double> heights;   // scaled; empty unless a terrain
  Raster<double> intensity; // the luminance of the colours; empty unless an image refined greedily
  Raster<double> density;   // empty for the built-in densities
};

// The image as display values: linear radiance is clamped to [0, 1] and
// gamma-encoded, which is also what --reconstruct writes and PSNR compares.
Input read_image(const Options& o)
{
  Input in;
  in.file = o.density.substr(6);
  CGAL::IO::Rgb_image img = CGAL::IO::read_rgb_image(in.file, std::size_t(o.max_pixels));
  in.density.width = in.colours.width = img.width;
  in.density.height = in.colours.height = img.height;
  in.colours.channels = 3;
  in.density.values = CGAL::IO::luminance(img);
  if(img.high_dynamic_range)
    for(float& v : img.values) v = std::pow(std::min(std::max(v, 0.f), 1.f), 1.f / 2.2f);
  if(o.max_error > 0. || o.reconstruction_mesh) {  // of the display values, which --reconstruct draws
    in.intensity.width = img.width;
    in.intensity.height = img.height;
    in.intensity.values = CGAL::IO::luminance(img);
  }
  in.colours.values = std::move(img.values);
  std::vector<double>& d = in.density.values;
  if(o.log) penrose_tools::log_transform(d);
  if(o.gradient) penrose_tools::gradient_magnitude(d, img.width, img.height);
  if(o.invert) penrose_tools::invert(d);
  const bool zero = all_zero(d);
  penrose_tools::apply_gamma(d, o.gamma);
  if(!all_finite(d)) usage_error("--gamma " + text(o.gamma) + ": the density of " + in.file + " raised to it overflows");
  if(!zero && all_zero(d)) usage_error("--gamma " + text(o.gamma) + ": the density of " + in.file + " raised to it is zero");
  return in;
}

// The density raster of a terrain has a pixel for about every half vertex
// spacing: finer would only cost time (see curvature_density).
Input read_terrain(const Options& o)
{
  Input in;
  in.file = o.terrain;
  CGAL::IO::Height_field hf = CGAL::IO::read_height_field(in.file, std::size_t(o.max_pixels));
  Raster<double>& h = in.heights;
  h.width = hf.width;
  h.height = hf.height;
  h.values = std::move(hf.values);
  const std::string scaled = "--height-scale " + text(o.height_scale) + ": ";
  if(o.height_scale != 1.) {  // the reader's heights are finite
    for(double& v : h.values) v *= o.height_scale;
    if(!all_finite(h.values)) usage_error(scaled + "the heights of " + in.file + " times it overflow");
  }
  h.x0 = hf.x0; h.y0 = hf.y0; h.x1 = hf.x1; h.y1 = hf.y1;
  const double spacing = o.points > 0. ? std::sqrt(double(h.width * h.height) / o.points) : 4.;
  const std::size_t block = std::size_t(std::min(16., std::max(1., std::floor(0.5 * spacing))));
  in.density.width = h.width;
  in.density.height = h.height;
  in.density.values = penrose_tools::curvature_density(h.values, in.density.width, in.density.height,
                                                       (h.x1 - h.x0) / double(h.width),
                                                       (h.y1 - h.y0) / double(h.height), block);
  if(!all_finite(in.density.values)) {
    if(o.height_scale != 1.) usage_error(scaled + "the curvature of the heights of " + in.file + " overflows");
    throw std::runtime_error(in.file + ": the curvature of its heights overflows (cells too small for their heights)");
  }
  const bool zero = all_zero(in.density.values);
  penrose_tools::apply_gamma(in.density.values, o.gamma);
  if(!all_finite(in.density.values))
    usage_error("--gamma " + text(o.gamma) + ": the density of " + in.file + " raised to it overflows");
  if(!zero && all_zero(in.density.values))
    usage_error("--gamma " + text(o.gamma) + ": the density of " + in.file + " raised to it is zero");
  return in;
}

// Stretches the rasters over the region; the viewer is in region coordinates.
void place(Input& in, const Options& o)
{
  const double* r = o.region;
  for(auto* d : {&in.heights, &in.intensity, &in.density}) { d->x0 = r[0]; d->y0 = r[1]; d->x1 = r[2]; d->y1 = r[3]; }
  in.colours.x0 = r[0]; in.colours.y0 = r[1]; in.colours.x1 = r[2]; in.colours.y1 = r[3];
  if(o.viewer_given && !penrose_tools::weight_by_viewer(in.density, o.viewer[0], o.viewer[1]))
    usage_error("--viewer " + text(o.viewer[0]) + " " + text(o.viewer[1]) + ": its distances to the region overflow");
}

struct Density
{
  std::function<double(const Point&)> value;
  std::function<double(const K::Iso_rectangle_2&)> upper_bound;  // empty: probes
};

// Takes the density raster of `in`, if any.
Density make_density(const Options& o, Input& in, const K::Iso_rectangle_2& region)
{
  const double x0 = o.region[0], y0 = o.region[1], x1 = o.region[2], y1 = o.region[3];
  Density d;
  if(!in.density.values.empty()) {
    auto raster = std::make_shared<CGAL::Raster_density_2<K>>(in.density.width, in.density.height,
                                                              std::move(in.density.values), region);
    d.value = [raster](const Point& p) { return (*raster)(p); };
    d.upper_bound = [raster](const K::Iso_rectangle_2& b) { return raster->upper_bound(b); };
  } else if(o.density == "constant") d.value = [](const Point&) { return 1.; };
  else if(o.density == "ramp") d.value = [=](const Point& p) { return (p.x() - x0) / (x1 - x0); };
  else {  // radial, at most 1.05
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), s = 0.2 * (x1 - x0);
    d.value = [=](const Point& p) {
      const double r2 = (p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy);
      return std::exp(-r2 / (2 * s * s)) + 0.05;
    };
    if(!std::isfinite(std::pow(1.05, o.gamma)))
      usage_error("--gamma " + text(o.gamma) + ": the radial density raised to it overflows");
  }
  if(in.density.values.empty() && o.gamma != 1.)  // a raster has it already
    d.value = [value = d.value, gamma = o.gamma](const Point& p) { return std::pow(value(p), gamma); };
  return d;
}

// `n` points, or the density scaled by o.scale if n is 0.
// The sampler takes any count: what a construction can hold is checked by
// the construction, and a streamed one holds windows only.
std::unique_ptr<Sampler> make_sampler(const Options& o, const K::Iso_rectangle_2& region, const Density& d, std::size_t n)
{
  using CGAL::parameters::use_correction_vectors;
  using CGAL::parameters::density_upper_bound;
  const std::size_t most = std::numeric_limits<std::size_t>::max();
  const auto np = use_correction_vectors(o.correction).maximum_number(most);
  if(d.upper_bound) {
    if(n) return std::make_unique<Sampler>(region, d.value, density_upper_bound(d.upper_bound, np.number_of_output_points(n)));
    return std::make_unique<Sampler>(region, d.value, density_upper_bound(d.upper_bound, np.density_control_factor(o.scale)));
  }
  if(n) return std::make_unique<Sampler>(region, d.value, np.number_of_output_points(n));
  return std::make_unique<Sampler>(region, d.value, np.density_control_factor(o.scale));
}

// The triangulation of the sampler's points, each vertex's info its index in
// `points`, and `vertex[k]` the vertex at points[k]. The points are in the
// order in which the triangulation reports its vertices (the tile tree's,
// breadth first), and --out-points and --out-mesh share it.
struct Mesh
{
  Triangulation t;
  std::vector<Point> points;
  std::vector<Vertex_handle> vertex;

  // Appends `v`, numbered next.
  void add(Vertex_handle v)
  {
    v->info() = points.size();
    points.emplace_back(v->point().x(), v->point().y());
    vertex.push_back(v);
  }
};

template <class Lift>
void triangulate(Mesh& m, const Sampler& sampler, const Lift& lift, penrose_tools::Progress_bar& bar)
{
  m.points.reserve(std::size_t(sampler.expected_number_of_points() * 1.05) + 16);
  m.vertex.reserve(m.points.capacity());
  const std::function<bool(double)> progress = [&bar](double advancement) {
    bar.set(advancement);
    return true;
  };
  m.t.build(sampler, lift, [&](Vertex_handle v, const Sampler::Sample& s) {
    v->info() = m.points.size();
    m.points.push_back(s.point);
    m.vertex.push_back(v);
  }, CGAL::parameters::callback(progress));
}

// How a mesh is refined: by greedy insertion or not, up to how many vertices
// (the region's, for --tiles), and at which scale of the density its border
// points lie: with a budget, that of the finished mesh rather than of the
// sample, so that the vertices that greedy insertion puts near the border
// make fewer slivers with them (a fifth as many vertices to mend them on the
// bundled terrain at 20,000 vertices, and a lower RMS error).
struct Plan
{
  bool greedy = false;
  std::size_t budget = std::numeric_limits<std::size_t>::max();
  double border_scale = 1.;

  bool bounded() const { return budget != std::numeric_limits<std::size_t>::max(); }
};

// What a mesh covers: the region, or a tile of it, and which of its sides
// the border's refinement may split (not those shared with another tile,
// which would not know).
struct Piece
{
  std::array<double, 4> rect;
  std::array<bool, 4> splittable;
};

// Removes the samples too close to the border, then inserts the points
// along it (see border_points.h) with insert(); with --max-error, as many
// more as the heights along the border need to be within it (without, the
// border points of a tile's side are as sparse as the sample, and greedy
// insertion's vertices beside it make slivers with them that its tiles may
// not mend).
template <class Lift>
std::size_t add_boundary(Mesh& m, const Options& o, const Piece& piece, const Density& d, double scale,
                         const Raster<double>& heights, const Lift& lift)
{
  penrose_tools::Border border(piece.rect, [&](double x, double y) { return scale * d.value(Point(x, y)); });
  if(o.max_error > 0. && !heights.values.empty()) {
    std::array<std::vector<double>, 2> centres;
    for(std::size_t i = 0; i < heights.width; ++i) centres[0].push_back(heights.x(double(i) + 0.5));
    for(std::size_t j = heights.height; j-- > 0;) centres[1].push_back(heights.y(double(j) + 0.5));
    border.fit([&](double x, double y) { return lift(x, y).z(); }, o.max_error, centres);
  }
  penrose_tools::remove_samples_near_border(m.t, m.vertex, border);
  std::vector<Vertex_handle> kept;
  kept.swap(m.vertex);
  m.points.clear();
  for(const Vertex_handle v : kept) m.add(v);
  const std::size_t before = m.points.size();
  Triangulation::Face_handle hint;
  border.for_each_point([&](double x, double y) {
    const std::size_t n = m.t.number_of_vertices();
    const Vertex_handle v = m.t.insert(lift(x, y), hint);
    if(m.t.number_of_vertices() > n) v->info() = m.points.size();
    m.points.emplace_back(x, y);
    m.vertex.push_back(v);
    hint = v->face();
  });
  return m.points.size() - before;
}

// Inserts the centres of the cells of largest vertical error into the mesh
// of a terrain until it has `budget` vertices or every cell is within
// o.max_error.
CGAL::Terrain_refinement_result refine(Mesh& m, const Options& o, const Raster<double>& heights, std::size_t budget)
{
  using namespace CGAL::parameters;
  return CGAL::refine_terrain_by_greedy_insertion(m.t, heights.width, heights.height, heights.values,
                                                  CGAL::Bbox_2(heights.x0, heights.y0, heights.x1, heights.y1),
                                                  max_error(o.max_error, number_of_points(budget,
                                                    visitor([&m](Vertex_handle v) { m.add(v); }))));
}

// Removes the vertices m.vertex[first..] that greedy insertion added last,
// the least needed, until the mesh has `budget` vertices. Those next to the
// border stay, so that its triangles stay as they are.
void trim(Mesh& m, const std::array<double, 4>& rect, std::size_t first, std::size_t budget)
{
  std::vector<char> removed(m.vertex.size(), 0);
  for(std::size_t k = m.vertex.size(); k-- > first && m.t.number_of_vertices() > budget;) {
    const Vertex_handle v = m.vertex[k];
    if(penrose_tools::is_on_border(rect, v->point().x(), v->point().y())) continue;
    bool near = false;
    auto w = m.t.incident_vertices(v), done = w;
    do near = near || m.t.is_infinite(w) || penrose_tools::is_on_border(rect, w->point().x(), w->point().y());
    while(++w != done);
    if(near) continue;
    m.t.remove(v);
    removed[k] = 1;
  }
  std::size_t kept = first;
  for(std::size_t k = first; k < m.vertex.size(); ++k)
    if(!removed[k]) {
      m.vertex[kept] = m.vertex[k];
      m.points[kept] = m.points[k];
      m.vertex[kept]->info() = kept;
      ++kept;
    }
  m.vertex.resize(kept);
  m.points.resize(kept);
}

// Refines the triangles at the border until none has an angle under 15
// degrees (see border_refinement.h), in turn with greedy insertion, if
// `greedy`, until neither inserts: a triangle mended at the border may
// cover cells above --max-error, and greedy insertion make a sliver there.
// At the --points budget, the vertices that greedy insertion added last
// make room for those of the border. Returns the number of vertices that the
// border's refinement inserted; `refined` counts greedy insertion's.
template <class Lift>
std::size_t refine_border(Mesh& m, const Options& o, const Piece& piece, const Raster<double>& heights, bool greedy,
                          std::size_t budget, std::size_t first_inserted, CGAL::Terrain_refinement_result& refined,
                          const Lift& lift)
{
  std::size_t mended = 0, trims = 0;
  for(;;) {
    const std::size_t more = penrose_tools::refine_border_triangles(m.t, piece.rect, piece.splittable, lift,
                                                                    [&m](Vertex_handle v) { m.add(v); });
    mended += more;
    if(!greedy || !more) break;
    if(m.t.number_of_vertices() > budget) {
      const std::size_t before = m.t.number_of_vertices();
      const bool last = ++trims == 3;
      trim(m, piece.rect, first_inserted, last ? budget : budget - (std::min)(budget, more));
      refined.number_of_inserted_points -= before - m.t.number_of_vertices();
      if(last) break;
    }
    const CGAL::Terrain_refinement_result again = refine(m, o, heights, budget);
    if(!again.number_of_inserted_points) break;
    refined.number_of_inserted_points += again.number_of_inserted_points;
    refined.max_error = again.max_error;
    refined.max_error_reached = again.max_error_reached;
  }
  return mended;
}

// Tile (i, j) of --tiles, computed alone: the samples of the region that lie
// in it, inserted one at a time in the sampler's depth-first order (each
// near the one before), then the border, greedy insertion on the cells
// strictly inside (up to the tile's share of --points: that of its samples)
// and the border's refinement, as run() does for the whole region.
template <class Lift>
Mesh tile_mesh(const Options& o, const Sampler& sampler, const Density& d, const Raster<double>& heights,
               const std::array<std::size_t, 2>& cells_xy, const Plan& plan, int i, int j, const Lift& lift)
{
  const std::array<double, 4> region{o.region[0], o.region[1], o.region[2], o.region[3]};
  const Piece piece{penrose_tools::tile_rectangle(region, i, j, o.tiles, cells_xy),
                    penrose_tools::sides_on_region_border(i, j, o.tiles)};
  std::vector<Point> samples;
  sampler(K::Iso_rectangle_2(piece.rect[0], piece.rect[1], piece.rect[2], piece.rect[3]), std::back_inserter(samples));
  Mesh m;
  Triangulation::Face_handle hint;
  for(const Point& p : samples) {
    const Vertex_handle v = m.t.insert(lift(p.x(), p.y()), hint);
    m.add(v);
    hint = v->face();
  }
  add_boundary(m, o, piece, d, plan.border_scale, heights, lift);
  const Raster<double> cells = plan.greedy ? penrose_tools::cells_inside(heights, piece.rect) : Raster<double>();
  std::size_t budget = plan.budget;
  if(plan.bounded())
    budget = (std::max)(m.t.number_of_vertices(), std::size_t(std::llround(double(plan.budget) * double(samples.size())
                                                                           / sampler.expected_number_of_points())));
  CGAL::Terrain_refinement_result refined;
  const std::size_t first_inserted = m.vertex.size();
  if(!cells.values.empty()) refined = refine(m, o, cells, budget);
  refine_border(m, o, piece, cells, !cells.values.empty(), budget, first_inserted, refined, lift);
  return m;
}

// Writes the meshes of --tiles, or of --tile alone, each computed alone (by
// tile_mesh()), in parallel where TBB is linked; returns the number of
// vertices and of triangles of all. `cells_xy` is the size of the input
// raster ({0, 0} for a built-in density).
template <class Lift>
std::pair<std::size_t, std::size_t> write_tiles(const Options& o, const Sampler& sampler, const Density& d,
                                                const Raster<double>& heights, const std::array<std::size_t, 2>& cells_xy,
                                                const Plan& plan, const Lift& lift)
{
  std::vector<std::array<int, 2>> tiles;
  for(int j = 0; j < o.tiles; ++j)
    for(int i = 0; i < o.tiles; ++i)
      if(o.tile[0] < 0 || (i == o.tile[0] && j == o.tile[1])) tiles.push_back({i, j});
  std::vector<std::pair<std::size_t, std::size_t>> sizes(tiles.size());
  auto one = [&](std::size_t k) {
    const auto [i, j] = tiles[k];
    const Mesh m = tile_mesh(o, sampler, d, heights, cells_xy, plan, i, j, lift);
    CGAL::IO::write_triangulation(penrose_tools::tile_file_name(o.out_mesh, i, j), m.t, m.vertex);
    sizes[k] = {m.t.number_of_vertices(), m.t.number_of_faces()};
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(std::size_t(0), tiles.size(), one);
#else
  for(std::size_t k = 0; k < tiles.size(); ++k) one(k);
#endif
  std::pair<std::size_t, std::size_t> total{0, 0};
  for(const auto& [v, f] : sizes) {
    total.first += v;
    total.second += f;
  }
  return total;
}

// The mesh's finite faces, over the points' x and y, for the rasters.
penrose_tools::Plane_mesh plane_mesh(const Mesh& m)
{
  penrose_tools::Plane_mesh p;
  for(const Point& q : m.points) { p.x.push_back(q.x()); p.y.push_back(q.y()); }
  for(auto f : m.t.finite_face_handles())
    p.faces.push_back({std::uint32_t(f->vertex(0)->info()), std::uint32_t(f->vertex(1)->info()),
                       std::uint32_t(f->vertex(2)->info())});
  return p;
}

// The raster `image` at the vertices of `m`, image.channels values a vertex.
template <class T>
std::vector<double> sample(const penrose_tools::Plane_mesh& m, const Raster<T>& image)
{
  const std::size_t c = image.channels;
  std::vector<double> at_vertex(c * m.x.size());
  for(std::size_t v = 0; v < m.x.size(); ++v)
    for(std::size_t k = 0; k < c; ++k) at_vertex[c * v + k] = image(m.x[v], m.y[v], k);
  return at_vertex;
}

unsigned char byte(double v) { return (unsigned char)std::lround(255. * std::min(std::max(v, 0.), 1.)); }

// The mesh against the raster `image` at the centres of the pixels that it
// covers (marked in `covered`) and that `mask`, if given, holds: the largest
// and the RMS difference between the image and the linear interpolation over
// each face of the values `at_vertex` (image.channels a vertex). That
// interpolation is drawn into `rendering`, if given, as 8-bit values (those
// of the PNG: doubles took 1.6 GB for 8192 x 8192 pixels).
template <class T>
std::pair<double, double> compare(const penrose_tools::Plane_mesh& m, const std::vector<double>& at_vertex,
                                  const Raster<T>& image, std::vector<char>& covered, const std::vector<char>* mask,
                                  Raster<unsigned char>* rendering)
{
  const std::size_t c = image.channels;
  if(rendering)
    *rendering = {image.width, image.height, c, std::vector<unsigned char>(c * image.width * image.height, 0),
                  image.x0, image.y0, image.x1, image.y1};
  double largest = 0., squares = 0.;
  std::size_t n = 0;
  penrose_tools::for_each_covered_pixel(m, image, covered, [&](std::size_t p, std::size_t f, const std::array<double, 3>& w) {
    if(mask && !(*mask)[p]) return;
    for(std::size_t k = 0; k < c; ++k, ++n) {
      double value = 0.;
      for(int i = 0; i < 3; ++i) value += w[i] * at_vertex[c * m.faces[f][i] + k];
      const double e = value - double(image.values[c * p + k]);
      largest = std::max(largest, std::abs(e));
      squares += e * e;
      if(rendering) rendering->values[c * p + k] = byte(value);
    }
  });
  return {largest, n ? std::sqrt(squares / double(n)) : 0.};
}

double psnr(double rms) { return rms > 0. ? -20. * std::log10(rms) : std::numeric_limits<double>::infinity(); }

// The quality of the mesh and of the regular grid of as many vertices,
// both measured over the pixels that the mesh covers.
struct Quality
{
  double coverage = 0., max_error = 0., rms_error = 0., grid_max_error = 0., grid_rms_error = 0.;
  std::size_t grid_vertices = 0;
  Raster<unsigned char> rendering;  // of the mesh, if asked for
};

// The heights of the vertices at m.points, fitted by --fit-heights or not.
std::vector<double> heights_of(const Mesh& m)
{
  std::vector<double> z;
  for(Vertex_handle v : m.vertex) z.push_back(v->point().z());
  return z;
}

// --fit-heights on an image: the colours that --reconstruct interpolates
// fitted by least squares, channel by channel, each lifted as the heights of
// the vertices from the image under them; the heights are then the
// luminance's again, for the fit of the luminance that follows. Returns the
// colours, 3 a point of m.points.
std::vector<double> fit_colours(Mesh& m, const Input& in)
{
  const Raster<float>& c = in.colours;
  std::vector<double> fitted(3 * m.points.size()), channel(c.width * c.height);
  auto lift = [&m](const std::function<double(double, double)>& z) {
    for(Vertex_handle v : m.vertex) v->set_point(K::Point_3(v->point().x(), v->point().y(), z(v->point().x(), v->point().y())));
  };
  for(std::size_t k = 0; k < 3; ++k) {
    for(std::size_t p = 0; p < channel.size(); ++p) channel[p] = double(c.values[3 * p + k]);
    lift([&](double x, double y) { return c(x, y, k); });
    CGAL::fit_terrain_heights(m.t, c.width, c.height, channel, CGAL::Bbox_2(c.x0, c.y0, c.x1, c.y1));
    for(std::size_t i = 0; i < m.points.size(); ++i) fitted[3 * i + k] = m.vertex[i]->point().z();
  }
  lift([&](double x, double y) { return in.intensity(x, y); });
  return fitted;
}

// The mesh against `image`, interpolating `at_vertex` (image.channels values
// a point of m.points); empty: the image under the vertices.
template <class T>
Quality measure(const Mesh& m, const Raster<T>& image, std::vector<double> at_vertex, bool render)
{
  Quality q;
  std::vector<char> covered, grid_covered;
  const penrose_tools::Plane_mesh mesh = plane_mesh(m);
  if(at_vertex.empty()) at_vertex = sample(mesh, image);
  std::tie(q.max_error, q.rms_error) = compare(mesh, at_vertex, image, covered, nullptr, render ? &q.rendering : nullptr);
  const penrose_tools::Plane_mesh grid = penrose_tools::grid_mesh(image, m.t.number_of_vertices());
  q.grid_vertices = grid.x.size();
  std::tie(q.grid_max_error, q.grid_rms_error) = compare(grid, sample(grid, image), image, grid_covered, &covered, nullptr);
  q.coverage = double(std::count(covered.begin(), covered.end(), 1)) / double(covered.size());
  return q;
}

void write_points(const std::string& file, const Mesh& m, bool with_heights)
{
  CGAL::IO::internal::Output_file out(file);
  for(std::size_t k = 0; k < m.points.size(); ++k)
    if(with_heights)
      std::fprintf(out.stream(), "%.17g %.17g %.17g\n", m.points[k].x(), m.points[k].y(), m.vertex[k]->point().z());
    else std::fprintf(out.stream(), "%.17g %.17g\n", m.points[k].x(), m.points[k].y());
  out.commit();
}

void write_svg(const Options& o, const Input& in, const Mesh& m)
{
  penrose_tools::Svg_writer svg(o.svg, o.region[0], o.region[1], o.region[2], o.region[3]);
  if(!in.colours.values.empty()) svg.background_image(penrose_tools::link_to(in.file, o.svg));
  const double r = std::max(0.6, std::min(3., 0.25 * 1024. / std::sqrt(double(m.points.size()) + 1.)));
  svg.begin_group("stroke=\"#1f4e9c\" stroke-width=\"" + std::to_string(0.4 * r) + "\" stroke-opacity=\"0.8\"");
  for(auto e : m.t.finite_edges()) {
    const auto& a = e.first->vertex(Triangulation::cw(e.second))->point();
    const auto& b = e.first->vertex(Triangulation::ccw(e.second))->point();
    svg.segment(a.x(), a.y(), b.x(), b.y());
  }
  svg.end_group();
  svg.begin_group("fill=\"black\"");
  for(const Point& q : m.points) svg.dot(q.x(), q.y(), r);
  svg.end_group();
  svg.close();
}

// Encoded in memory and written by write_bytes(), which checks the write and
// the close: stbi_write_png() does not.
void write_png(const std::string& file, int width, int height, int channels, const unsigned char* data)
{
  std::string png;
  auto append = [](void* to, void* bytes, int n) { static_cast<std::string*>(to)->append(static_cast<char*>(bytes), std::size_t(n)); };
  if(!stbi_write_png_to_func(append, &png, width, height, channels, data, width * channels))
    throw std::runtime_error(file + ": cannot encode the PNG");
  CGAL::IO::internal::write_bytes(file, png);
}

// The mesh's edges, 1024 pixels on the region's longer side, over the image, or over the height
// field shaded (lit from the north-west, its relief exaggerated to a fifth of
// the region's width), lightened so that the edges stand out.
void draw_png(const Options& o, const Input& in, const Mesh& m)
{
  const double w = o.region[2] - o.region[0], h = o.region[3] - o.region[1];
  penrose_tools::Picture pic;
  pic.width = w >= h ? 1024 : std::max(1, int(std::lround(1024. * w / h)));
  pic.height = w >= h ? std::max(1, int(std::lround(1024. * h / w))) : 1024;
  pic.rgb.assign(3 * std::size_t(pic.width) * std::size_t(pic.height), 255);
  Raster<double> frame;
  frame.width = std::size_t(pic.width);
  frame.height = std::size_t(pic.height);
  frame.x0 = o.region[0]; frame.y0 = o.region[1]; frame.x1 = o.region[2]; frame.y1 = o.region[3];
  const Raster<double>& z = in.heights;
  double relief = 0.;
  if(!z.values.empty()) {
    const auto [lo, hi] = std::minmax_element(z.values.begin(), z.values.end());
    relief = *hi > *lo ? 0.2 * w / (*hi - *lo) : 0.;
  }
  const double d = w / pic.width, lx = -0.5, ly = 0.5, lz = std::sqrt(0.5);  // light from the north-west, 45 degrees up
  for(int j = 0; j < pic.height; ++j)
    for(int i = 0; i < pic.width; ++i) {
      const double x = frame.x(i + 0.5), y = frame.y(j + 0.5);
      unsigned char* p = &pic.rgb[3 * (std::size_t(j) * std::size_t(pic.width) + std::size_t(i))];
      if(!in.colours.values.empty())
        for(int c = 0; c < 3; ++c) p[c] = byte(0.5 + 0.5 * in.colours(x, y, std::size_t(c)));
      else if(!z.values.empty()) {
        const double gx = relief * (z(x + d, y) - z(x - d, y)) / (2 * d), gy = relief * (z(x, y + d) - z(x, y - d)) / (2 * d);
        const double shade = std::max(0., (-gx * lx - gy * ly + lz) / std::sqrt(gx * gx + gy * gy + 1.));
        p[0] = p[1] = p[2] = byte(0.45 + 0.55 * shade);
      }
    }
  const unsigned char colour[3] = {200, 30, 30};
  for(auto e : m.t.finite_edges()) {
    const auto& a = e.first->vertex(Triangulation::cw(e.second))->point();
    const auto& b = e.first->vertex(Triangulation::ccw(e.second))->point();
    pic.line(frame.u(a.x()), frame.v(a.y()), frame.u(b.x()), frame.v(b.y()), colour, 0.7);
  }
  write_png(o.png, pic.width, pic.height, 3, pic.rgb.data());
}

void write_reconstruction(const std::string& file, const Raster<unsigned char>& r)
{
  write_png(file, int(r.width), int(r.height), 3, r.values.data());
}

struct Timings
{
  double read = 0., sample = 0., triangulate = 0., refine = 0., fit = 0., measure = 0., write = 0., total = 0.;
};

// The length of the UTF-8 sequence that starts at s[k] (1 for ASCII), or 0
// if it is not one: a stray continuation byte, a sequence cut short, an
// overlong encoding, a surrogate or a code point beyond U+10FFFF.
std::size_t utf8_sequence_length(const std::string& s, std::size_t k)
{
  const unsigned char c = static_cast<unsigned char>(s[k]);
  if(c < 0x80) return 1;
  const std::size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  if(n == 0 || s.size() - k < n) return 0;
  for(std::size_t i = 1; i < n; ++i)
    if((static_cast<unsigned char>(s[k + i]) & 0xc0) != 0x80) return 0;
  const unsigned char d = static_cast<unsigned char>(s[k + 1]);
  if((c == 0xe0 && d < 0xa0) || (c == 0xed && d > 0x9f) || (c == 0xf0 && d < 0x90) || (c == 0xf4 && d > 0x8f)) return 0;
  return n;
}

// A JSON number: null where the value does not exist (the PSNR of a mesh
// without faces is infinite).
std::string json_number(double v, int digits = 6)
{
  if(!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// `s` as a JSON string, valid UTF-8: a byte that does not belong to a UTF-8
// sequence (a file name in Latin-1) becomes U+FFFD, the replacement character.
std::string json_string(const std::string& s)
{
  std::string j = "\"";
  for(std::size_t k = 0; k < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[k]);
    const std::size_t n = utf8_sequence_length(s, k);
    if(n > 1) j.append(s, k, n);
    else if(n == 0) j += "\xef\xbf\xbd";
    else if(c == '"' || c == '\\') { j += '\\'; j += char(c); }
    else if(c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      j += buf;
    } else j += char(c);
    k += n ? n : 1;
  }
  return j + '"';
}

void write_stats(const Options& o, const Input& in, const Sampler& sampler, const Mesh& m, std::size_t sampled,
                 std::size_t boundary, std::size_t mended, const CGAL::Terrain_refinement_result& refined,
                 const CGAL::Terrain_fit_result& fitted, const Quality* q,
                 const Timings& t)
{
  std::string j = "{", separator;
  auto field = [&](const char* name, const std::string& value) {
    j += separator + "\"" + name + "\": " + value;
    separator = ", ";
  };
  auto count = [](std::size_t n) { return std::to_string(n); };
  field("points", count(sampled));
  field("expected_points", json_number(sampler.expected_number_of_points()));
  field("boundary_points", count(boundary));
  field("border_refinement_points", count(mended));
  field("inserted_points", count(refined.number_of_inserted_points));
  if(o.max_error > 0.) field("max_error_reached", refined.max_error_reached ? "true" : "false");
  field("vertices", count(m.t.number_of_vertices()));
  field("faces", count(m.t.number_of_faces()));
  field("flips", count(m.t.number_of_flips()));
  field("fallbacks", count(m.t.number_of_fallbacks()));
  if(o.fit_heights) {
    field("fit_rms_error_before", json_number(fitted.rms_error_before));
    field("fit_rms_error_after", json_number(fitted.rms_error_after));
    field("fit_iterations", count(fitted.number_of_iterations));
  }
  separator = ",\n ";
  field("read_seconds", json_number(t.read));
  field("sample_seconds", json_number(t.sample));
  field("triangulate_seconds", json_number(t.triangulate));
  field("refine_seconds", json_number(t.refine));
  if(o.fit_heights) field("fit_seconds", json_number(t.fit));
  field("measure_seconds", json_number(t.measure));
  field("write_seconds", json_number(t.write));
  field("total_seconds", json_number(t.total));
  separator = ",\n ";
  field("density", json_string(in.file.empty() ? o.density : in.file));
  field("region", "[" + json_number(o.region[0], 17) + ", " + json_number(o.region[1], 17) + ", "
                  + json_number(o.region[2], 17) + ", " + json_number(o.region[3], 17) + "]");
  field("correction", o.correction ? "true" : "false");
  if(q) {
    separator = ",\n ";
    if(!in.heights.values.empty()) {
      field("max_error", json_number(q->max_error));
      field("rms_error", json_number(q->rms_error));
      field("grid_max_error", json_number(q->grid_max_error));
      field("grid_rms_error", json_number(q->grid_rms_error));
    } else {
      field("psnr", json_number(psnr(q->rms_error)));
      field("grid_psnr", json_number(psnr(q->grid_rms_error)));
    }
    field("grid_vertices", count(q->grid_vertices));
    field("coverage", json_number(q->coverage));
  }
  CGAL::IO::internal::write_bytes(o.stats_json, j + "}\n");
}

// Runs `step`, its errors prefixed with the density and the options that
// set it: the sampler's messages name neither.
template <class Step>
auto in_context(const Options& o, const Step& step)
{
  try {
    return step();
  } catch(const std::bad_alloc&) {
    throw;
  } catch(const std::exception& e) {
    std::string s = o.terrain.empty() ? "--density " + o.density : "--terrain " + o.terrain;
    s += o.points > 0. ? " --points " + text(o.points) : " --scale " + text(o.scale);
    if(o.gamma != 1.) s += " --gamma " + text(o.gamma);
    throw std::runtime_error(s + ": " + e.what());
  }
}

// Whether the mesh is written window by window: when asked, or when only a
// PLY of a density's samples is asked for and the mesh would take more than
// half the memory (about 300 bytes a point with penrose_mesh's own arrays).
bool streams(const Options& o, const Sampler& sampler)
{
  if(o.streamed) return true;
  const bool ply = o.out_mesh.size() >= 4 && o.out_mesh.compare(o.out_mesh.size() - 4, 4, ".ply") == 0;
  return ply && o.terrain.empty() && !o.tiles && !o.boundary && penrose_tools::streamable_outputs(o)
         && 300. * sampler.expected_number_of_points() > 0.5 * CGAL::internal::Penrose::physical_memory_bytes();
}

void write_streamed(const Options& o, const Sampler& sampler, penrose_tools::Progress_bar& bar,
                    std::chrono::steady_clock::time_point start)
{
  penrose_tools::Streamed_ply_writer<K> writer(sampler, o.window_points);
  bar.stage("streaming", 0.2, 1.);
  const penrose_tools::Streamed_mesh m =
    in_context(o, [&] { return writer.write(o.out_mesh, [&bar](double f) { bar.set(f); }); });
  bar.finish();
  std::cerr << "penrose_mesh: " << m.vertices << " points, " << m.faces << " triangles in " << seconds_since(start)
            << " s, streamed in " << m.windows << " windows\n";
}

void run(Options o)
{
  const auto start = std::chrono::steady_clock::now();
  penrose_tools::Progress_bar bar;
  Timings time;
  bar.stage("reading", 0., 0.1);
  Input in = o.terrain.empty() ? (o.density.rfind("image:", 0) == 0 ? read_image(o) : Input()) : read_terrain(o);
  if(!o.region_given && !in.heights.values.empty()) {
    const Raster<double>& h = in.heights;
    o.region[0] = h.x0; o.region[1] = h.y0; o.region[2] = h.x1; o.region[3] = h.y1;
  } else if(!o.region_given && !in.colours.values.empty()) {
    o.region[0] = o.region[1] = 0.;
    o.region[2] = double(in.colours.width);
    o.region[3] = double(in.colours.height);
  }
  // A flat terrain, or an image of one colour meshed for its error, has no
  // curvature or luminance to sample by: its sample is uniform, and greedy
  // insertion adds what the heights need (nothing where they are flat).
  if(!in.density.values.empty() && all_zero(in.density.values) && (!in.heights.values.empty() || !in.intensity.values.empty()))
    std::fill(in.density.values.begin(), in.density.values.end(), 1.);
  place(in, o);
  const std::size_t cells_x = (std::max)(in.heights.width, in.colours.width);
  const std::size_t cells_y = (std::max)(in.heights.height, in.colours.height);
  if(o.tiles && cells_x && (cells_x < 8 * std::size_t(o.tiles) || cells_y < 8 * std::size_t(o.tiles)))
    usage_error("--tiles " + std::to_string(o.tiles) + " makes tiles of fewer than 8 x 8 cells of " + in.file + " ("
                + std::to_string(cells_x) + " x " + std::to_string(cells_y) + ")");
  const K::Iso_rectangle_2 region(o.region[0], o.region[1], o.region[2], o.region[3]);
  const Density d = make_density(o, in, region);
  time.read = seconds_since(start);

  // the grid that greedy insertion refines, and the vertices' z
  const Raster<double>& heights = in.heights.values.empty() ? in.intensity : in.heights;
  auto lift = [&heights](double x, double y) { return K::Point_3(x, y, heights.values.empty() ? 0. : heights(x, y)); };
  // A terrain's mesh, and an image's with --max-error or for its
  // reconstruction (see Options::reconstruction_mesh), is sampled for a
  // fraction of its vertices, the rest inserted greedily. With --max-error
  // alone the count is not known: the sample is sparse, a point per 1024
  // cells, and greedy insertion, which needs the fewest vertices for a given
  // error, does the rest.
  const bool greedy = !heights.values.empty() && (o.max_error > 0. || (o.points > 0. && o.base_fraction < 1.));
  const bool bounded = o.points_given || o.max_error == 0.;
  if(greedy && o.points_given && o.points > double(heights.width * heights.height))
    usage_error("--points " + text(o.points) + " is more than the " + std::to_string(heights.width * heights.height)
                + " cells of " + in.file + " (" + std::to_string(heights.width) + " x " + std::to_string(heights.height)
                + "): greedy insertion puts a vertex in a cell at most");
  const std::size_t budget = greedy && bounded ? std::size_t(o.points) : std::numeric_limits<std::size_t>::max();
  std::size_t n = std::size_t(o.points);
  if(greedy && n > 0)
    n = bounded ? std::max<std::size_t>(1, std::size_t(std::lround(o.base_fraction * double(n))))
                : std::max<std::size_t>(16, heights.width * heights.height / 1024);

  bar.stage("sampling", 0.1, 0.2);
  auto t0 = std::chrono::steady_clock::now();
  const std::unique_ptr<Sampler> sampler = in_context(o, [&] { return make_sampler(o, region, d, n); });
  time.sample = seconds_since(t0);
  const Plan plan{greedy, budget, sampler->density_scale() * (greedy && bounded && n ? double(budget) / double(n) : 1.)};
  const double vertices = plan.bounded() ? double(plan.budget) : sampler->expected_number_of_points();
  if(o.tiles && double(o.tiles) * double(o.tiles) > vertices)
    usage_error("--tiles " + std::to_string(o.tiles) + " makes " + std::to_string(o.tiles * o.tiles) + " tiles for about "
                + text(vertices) + " vertices: a tile must have one at least");

  if(streams(o, *sampler)) {
    write_streamed(o, *sampler, bar, start);
    return;
  }

  if(o.tiles) {
    bar.stage("tiles", 0.2, 1.);
    const auto [vertices, faces] = in_context(o, [&] { return write_tiles(o, *sampler, d, heights, {cells_x, cells_y}, plan, lift); });
    bar.finish();
    std::cerr << "penrose_mesh: ";
    if(o.tile[0] < 0) std::cerr << o.tiles << " x " << o.tiles << " tiles";
    else std::cerr << "tile " << o.tile[0] << " " << o.tile[1] << " of " << o.tiles << " x " << o.tiles;
    std::cerr << ", " << vertices << " vertices and " << faces << " triangles in " << seconds_since(start) << " s\n";
    return;
  }

  // the tile tree is sampled while the triangulation is derived from it
  bar.stage("triangulating", 0.2, 0.6);
  t0 = std::chrono::steady_clock::now();
  Mesh m;
  in_context(o, [&] { triangulate(m, *sampler, lift, bar); });
  const Piece whole{{o.region[0], o.region[1], o.region[2], o.region[3]}, {true, true, true, true}};
  const std::size_t boundary = o.boundary ? add_boundary(m, o, whole, d, plan.border_scale, heights, lift) : 0;
  const std::size_t sampled = m.points.size() - boundary;  // those kept
  time.triangulate = seconds_since(t0);

  bar.stage("refining", 0.6, 0.7);
  t0 = std::chrono::steady_clock::now();
  CGAL::Terrain_refinement_result refined;
  const std::size_t first_inserted = m.vertex.size();
  if(greedy) refined = refine(m, o, heights, budget);
  const std::size_t mended = o.boundary ? refine_border(m, o, whole, heights, greedy, budget, first_inserted, refined, lift) : 0;
  time.refine = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  CGAL::Terrain_fit_result fitted;
  std::vector<double> colours;  // fitted, 3 a point; empty: the image's under them
  if(o.fit_heights && !in.colours.values.empty()) colours = fit_colours(m, in);
  if(o.fit_heights)
    fitted = CGAL::fit_terrain_heights(m.t, heights.width, heights.height, heights.values,
                                       CGAL::Bbox_2(heights.x0, heights.y0, heights.x1, heights.y1));
  time.fit = seconds_since(t0);

  bar.stage("measuring", 0.7, 0.85);
  t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Quality> q;
  if(!o.stats_json.empty() || !o.reconstruct.empty()) {
    if(!in.heights.values.empty()) q = std::make_unique<Quality>(measure(m, in.heights, heights_of(m), false));
    else if(!in.colours.values.empty()) q = std::make_unique<Quality>(measure(m, in.colours, colours, !o.reconstruct.empty()));
  }
  time.measure = seconds_since(t0);

  bar.stage("writing", 0.85, 1.);
  t0 = std::chrono::steady_clock::now();
  if(!o.out_points.empty()) write_points(o.out_points, m, !in.heights.values.empty());
  if(!o.out_mesh.empty()) CGAL::IO::write_triangulation(o.out_mesh, m.t, m.vertex);
  if(!o.svg.empty()) write_svg(o, in, m);
  if(!o.png.empty()) draw_png(o, in, m);
  if(!o.reconstruct.empty()) write_reconstruction(o.reconstruct, q->rendering);
  time.write = seconds_since(t0);
  time.total = seconds_since(start);
  if(!o.stats_json.empty()) write_stats(o, in, *sampler, m, sampled, boundary, mended, refined, fitted, q.get(), time);
  bar.finish();

  std::cerr << "penrose_mesh: " << sampled << " points";
  if(boundary) std::cerr << " + " << boundary << " on the border";
  if(mended) std::cerr << " + " << mended << " to shape it";
  if(greedy) std::cerr << " + " << refined.number_of_inserted_points << " inserted";
  std::cerr << ", " << m.t.number_of_faces() << " triangles in " << time.total << " s (read " << time.read
            << ", sample " << time.sample << ", triangulate " << time.triangulate;
  if(greedy) std::cerr << ", refine " << time.refine;
  if(o.fit_heights) std::cerr << ", fit " << time.fit;
  std::cerr << ")\n";
  if(greedy && o.max_error > 0.)
    std::cerr << "penrose_mesh: " << (refined.max_error_reached ? "every cell within --max-error "
                                                                : "stopped at --points vertices with a max error of ")
              << (refined.max_error_reached ? o.max_error : refined.max_error) << "\n";
  if(o.fit_heights)
    std::cerr << "penrose_mesh: heights fitted in " << fitted.number_of_iterations << " iterations, rms error "
              << fitted.rms_error_before << " -> " << fitted.rms_error_after << " over the " << fitted.number_of_cells
              << " cells covered\n";
  if(q && !in.heights.values.empty())
    std::cerr << "penrose_mesh: rms error " << q->rms_error << " (grid " << q->grid_rms_error << "), max error "
              << q->max_error << " (grid " << q->grid_max_error << ")\n";
  if(q && !in.colours.values.empty())
    std::cerr << "penrose_mesh: PSNR " << psnr(q->rms_error) << " dB (grid " << psnr(q->grid_rms_error) << " dB)\n";
}

} // namespace

// The whole tool on the command line `argv`: status 0; 2 for a bad option,
// 1 for a file that cannot be read or written. Messages echo names and
// values: their control bytes are escaped.
int penrose_mesh(int argc, const char* const* argv)
{
  try {
    const Options o = penrose_tools::parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
    std::optional<tbb::global_control> threads;
    if(o.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads));
#endif
    if(o.help) std::cout << penrose_tools::usage_text;
    else {
      penrose_tools::check_files(o);
      run(o);
    }
  } catch(const penrose_tools::Usage_error& e) {
    std::cerr << "penrose_mesh: " << CGAL::IO::internal::printable(e.what()) << " (penrose_mesh --help lists the options)\n";
    return 2;
  } catch(const std::bad_alloc&) {
    std::cerr << "penrose_mesh: out of memory\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "penrose_mesh: " << CGAL::IO::internal::printable(e.what()) << "\n";
    return 1;
  }
  return 0;
}

// fuzz/command_line.cpp includes this file and calls penrose_mesh() itself
#ifndef PENROSE_MESH_NO_MAIN
int main(int argc, char** argv) { return penrose_mesh(argc, argv); }
#endif
