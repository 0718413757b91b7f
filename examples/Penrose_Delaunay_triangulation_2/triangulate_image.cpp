// An image-driven triangulation (the paper's Figure 9): the luminance of an
// image is the density, bounded exactly over each tile by the raster's max
// pyramid so that no bright detail is missed.
// Usage: triangulate_image image.png [number_of_points]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Raster_density_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: triangulate_image image.png [number_of_points]\n";
    return EXIT_FAILURE;
  }
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 20000;
  try {
    CGAL::IO::Luminance_image image = CGAL::IO::read_luminance_image(argv[1]);
    for(double& v : image.values) v += 0.02;  // a few points in the dark too
    const K::Iso_rectangle_2 region(0, 0, double(image.width), double(image.height));
    const CGAL::Raster_density_2<K> density(image.width, image.height, std::move(image.values), region);
    const CGAL::Penrose_importance_sampler<K> sampler(region, density,
      CGAL::parameters::density_upper_bound(density.upper_bound_function(),
                                            CGAL::parameters::number_of_output_points(n)));
    const CGAL::Penrose_Delaunay_triangulation_2<K> dt(sampler);
    std::cout << dt.number_of_vertices() << " vertices, " << dt.number_of_faces() << " triangles\n";
    return dt.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
