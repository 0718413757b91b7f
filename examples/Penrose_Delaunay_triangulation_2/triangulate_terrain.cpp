// A terrain: samples denser where the surface bends, triangulated by their x
// and y with Projection_traits_xy_3, each vertex lifted to its height and
// told, through a vertex base with info, the level of the tile it comes from.
// The construction reports its advancement through the `callback` named
// parameter. The mesh is written with its heights (OFF, PLY or OBJ).
// Usage: triangulate_terrain [number_of_points] [out.off|out.ply|out.obj]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/write_triangulation.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Projection_traits_xy_3<K> Gt;
typedef CGAL::Triangulation_vertex_base_with_info_2<int, Gt> Vb;  // info: the tile level
typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
typedef CGAL::Penrose_Delaunay_triangulation_2<Gt, Tds> Terrain;
typedef CGAL::Penrose_importance_sampler<K> Sampler;

// two hills and a ridge
static double height(double x, double y)
{
  return std::exp(-20 * ((x - 0.3) * (x - 0.3) + (y - 0.4) * (y - 0.4))) +
         0.6 * std::exp(-40 * ((x - 0.7) * (x - 0.7) + (y - 0.7) * (y - 0.7))) + 0.2 * std::sin(6 * x + 4 * y);
}

// how much the surface bends: the magnitude of its Laplacian, by central differences
static double bending(const K::Point_2& p)
{
  const double h = 1e-3, x = p.x(), y = p.y();
  return std::abs(height(x + h, y) + height(x - h, y) + height(x, y + h) + height(x, y - h) - 4 * height(x, y)) / (h * h);
}

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
  // a floor of density, so that the flat parts are sampled too
  const Sampler sampler(K::Iso_rectangle_2(0, 0, 1, 1), [](const K::Point_2& p) { return 2 + bending(p); },
                        CGAL::parameters::number_of_output_points(n));

  Terrain terrain;
  int reported = 0;
  const bool built = terrain.build(
    sampler, [](double x, double y) { return K::Point_3(x, y, height(x, y)); },
    [](Terrain::Vertex_handle v, const Sampler::Sample& sample) { v->info() = sample.level; },
    CGAL::parameters::callback([&reported](double advancement) {
      for(; reported < int(10 * advancement); ++reported) std::cout << '.' << std::flush;
      return true;  // false would stop the construction, leaving the terrain empty
    }));
  std::cout << "\n";
  if(!built) return EXIT_FAILURE;

  std::map<int, std::size_t> vertices_per_level;
  for(auto v : terrain.finite_vertex_handles()) ++vertices_per_level[v->info()];
  std::cout << terrain.number_of_vertices() << " vertices, " << terrain.number_of_faces() << " triangles; "
            << "vertices per tile level:";
  for(const auto& [level, count] : vertices_per_level) std::cout << ' ' << level << ':' << count;
  std::cout << "\n";

  try {
    CGAL::IO::write_triangulation(argc > 2 ? argv[2] : "terrain.off", terrain);  // with the heights
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return terrain.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
