// The gradient ramp of the paper's Figure 7: samples of a density that grows
// linearly from the left edge, and their Delaunay triangulation, written as OFF.
// Usage: triangulate_ramp [number_of_points] [out.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Penrose_Delaunay_triangulation_2<K> Triangulation;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 5000;
  const CGAL::Penrose_importance_sampler<K> ramp(K::Iso_rectangle_2(0, 0, 1, 1),
                                                 [](const K::Point_2& p) { return p.x(); },
                                                 CGAL::parameters::number_of_output_points(n));
  const Triangulation dt(ramp);
  std::cout << dt.number_of_vertices() << " vertices, " << dt.number_of_faces() << " triangles, "
            << dt.number_of_flips() << " flips, " << dt.number_of_fallbacks() << " fallbacks\n";

  // it is a Delaunay_triangulation_2: use it as one
  std::ofstream off(argc > 2 ? argv[2] : "ramp.off");
  off << "OFF\n" << dt.number_of_vertices() << ' ' << dt.number_of_faces() << " 0\n";
  std::map<Triangulation::Vertex_handle, std::size_t> index;
  for(auto v : dt.finite_vertex_handles()) {
    off << v->point() << " 0\n";
    index.emplace(v, index.size());
  }
  for(auto f : dt.finite_face_handles())
    off << "3 " << index[f->vertex(0)] << ' ' << index[f->vertex(1)] << ' ' << index[f->vertex(2)] << '\n';
  return dt.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
