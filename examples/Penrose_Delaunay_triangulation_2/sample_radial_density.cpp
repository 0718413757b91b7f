// Samples a radial density into a vector, then reads the tile data of a few
// samples. Usage: sample_radial_density [number_of_points]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Penrose_importance_sampler.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 50000;
  const K::Iso_rectangle_2 region(0, 0, 2, 1);

  // points per unit area, up to a factor: only the shape matters with number_of_output_points
  auto density = [](const Point_2& p) {
    const double r2 = CGAL::squared_distance(p, Point_2(1, 0.5));
    return 0.05 + std::exp(-r2 / 0.08);
  };

  CGAL::Penrose_importance_sampler<K> sampler(region, density,
                                               CGAL::parameters::number_of_output_points(n));
  std::vector<Point_2> points;
  sampler(std::back_inserter(points));
  std::cout << points.size() << " points (" << n << " asked for)\n";

  std::vector<CGAL::Penrose_importance_sampler<K>::Sample> samples;
  sampler.samples(std::back_inserter(samples));
  for(std::size_t i = 0; i < 3 && i < samples.size(); ++i)
    std::cout << samples[i].point << ": leaf level " << samples[i].level << ", F-code "
              << samples[i].f_code << ", structural index " << samples[i].structural_index << "\n";
  return points.size() == samples.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
