// A height grid, the heights of a DEM or the luminance of an image, meshed
// with few vertices for its error by triangulate_height_grid(): a uniform
// sample of 5% of the vertices, then greedy insertion of the rest; with
// --fit-heights, the vertices' heights then fitted by least squares for a
// lower RMS error (the mesh no longer interpolates the grid). The mesh is
// written with its heights, over the grid's extent (an image's: 0 0 WIDTH
// HEIGHT, one unit a pixel).
// Usage: mesh_height_grid dem|image FILE number_of_points [out.off|out.ply|out.obj] [--fit-heights]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/fit_terrain_heights.h>
#include <CGAL/triangulate_height_grid.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/write_triangulation.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Penrose_Delaunay_triangulation_2<CGAL::Projection_traits_xy_3<K>> Terrain;

int main(int argc, char** argv)
{
  const bool fit = argc > 1 && std::strcmp(argv[argc - 1], "--fit-heights") == 0;
  const int args = fit ? argc - 1 : argc;
  if(args < 4 || (std::strcmp(argv[1], "dem") != 0 && std::strcmp(argv[1], "image") != 0)) {
    std::cerr << "usage: mesh_height_grid dem|image FILE number_of_points [out.off|out.ply|out.obj] [--fit-heights]\n";
    return EXIT_FAILURE;
  }
  try {
    std::size_t width, height;
    std::vector<double> heights;
    CGAL::Bbox_2 region;
    if(std::strcmp(argv[1], "dem") == 0) {
      CGAL::IO::Height_field dem = CGAL::IO::read_height_field(argv[2]);
      width = dem.width;
      height = dem.height;
      heights = std::move(dem.values);
      region = CGAL::Bbox_2(dem.x0, dem.y0, dem.x1, dem.y1);
    } else {
      CGAL::IO::Luminance_image image = CGAL::IO::read_luminance_image(argv[2]);
      width = image.width;
      height = image.height;
      heights = std::move(image.values);
      region = CGAL::Bbox_2(0, 0, double(width), double(height));
    }
    Terrain terrain;
    const CGAL::Terrain_refinement_result refined = CGAL::triangulate_height_grid(
      terrain, width, height, heights, region, CGAL::parameters::number_of_points(std::strtoul(argv[3], nullptr, 10)));
    std::cout << terrain.number_of_vertices() << " vertices (" << refined.number_of_inserted_points
              << " inserted), max error " << refined.max_error << "\n";
    if(fit) {
      const CGAL::Terrain_fit_result fitted = CGAL::fit_terrain_heights(terrain, width, height, heights, region);
      std::cout << "heights fitted: RMS error " << fitted.rms_error_before << " -> " << fitted.rms_error_after << "\n";
    }
    CGAL::IO::write_triangulation(args > 4 ? argv[4] : "height_grid.off", terrain);
    return terrain.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
