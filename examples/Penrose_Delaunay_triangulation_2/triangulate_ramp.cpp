// The gradient ramp of the paper's Figure 7: samples of a density that grows
// linearly from the left edge, and their Delaunay triangulation, written as a
// mesh file. With TBB, the construction runs as TBB tasks on every core.
// Usage: triangulate_ramp [number_of_points] [out.off|out.ply|out.obj]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/write_triangulation.h>

#include <cstdlib>
#include <exception>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
// Parallel_tag calls the density from several threads: a pure function is thread-safe.
#if defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Parallel_tag Concurrency_tag;
#else
typedef CGAL::Sequential_tag Concurrency_tag;
#endif
typedef CGAL::Penrose_Delaunay_triangulation_2<K, CGAL::Default, Concurrency_tag> Triangulation;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 5000;
  const CGAL::Penrose_importance_sampler<K> ramp(K::Iso_rectangle_2(0, 0, 1, 1),
                                                 [](const K::Point_2& p) { return p.x(); },
                                                 CGAL::parameters::number_of_output_points(n));
  const Triangulation dt(ramp);
  std::cout << dt.number_of_vertices() << " vertices, " << dt.number_of_faces() << " triangles, "
            << dt.number_of_flips() << " flips, " << dt.number_of_fallbacks() << " fallbacks\n";

  try {
    CGAL::IO::write_triangulation(argc > 2 ? argv[2] : "ramp.off", dt);  // OFF, PLY or OBJ, by the extension
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return dt.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
