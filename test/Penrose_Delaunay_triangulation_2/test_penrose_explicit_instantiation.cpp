// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every member of each public class template compiles, not only those that
// the other tests call: each is instantiated explicitly with the traits
// classes of the tests.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <gtest/gtest.h>

#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> Gmpq_kernel;
typedef CGAL::Projection_traits_xy_3<Epick> Terrain;
typedef CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<int, Epick>,
                                             CGAL::Triangulation_face_base_2<Epick>> Info_tds;

template class CGAL::Penrose_importance_sampler<Epick>;
template class CGAL::Penrose_importance_sampler<Epeck>;
template class CGAL::Penrose_importance_sampler<Gmpq_kernel>;

template class CGAL::Raster_density_2<Epick>;
template class CGAL::Raster_density_2<Epeck>;
template class CGAL::Raster_density_2<Gmpq_kernel>;

template class CGAL::Penrose_Delaunay_triangulation_2<Epick>;
template class CGAL::Penrose_Delaunay_triangulation_2<Epeck>;
template class CGAL::Penrose_Delaunay_triangulation_2<Gmpq_kernel>;
template class CGAL::Penrose_Delaunay_triangulation_2<Terrain>;
template class CGAL::Penrose_Delaunay_triangulation_2<Epick, Info_tds>;
#if defined(CGAL_LINKED_WITH_TBB)
template class CGAL::Penrose_Delaunay_triangulation_2<Epick, CGAL::Default, CGAL::Parallel_tag>;
template class CGAL::Penrose_Delaunay_triangulation_2<Epick, Info_tds, CGAL::Parallel_tag>;
#endif

// The members instantiated above, on the smallest inputs: an empty
// triangulation, a raster of one pixel, a sampler of a density that is zero.
TEST(Instantiation, MembersWorkOnTheSmallestInputs)
{
  CGAL::Penrose_Delaunay_triangulation_2<Terrain> empty, other;
  EXPECT_EQ(empty.number_of_vertices(), 0u);
  EXPECT_EQ(empty.number_of_flips(), 0u);
  EXPECT_EQ(empty.number_of_fallbacks(), 0u);
  empty.swap(other);
  EXPECT_TRUE(empty.is_valid());

  const Epeck::Iso_rectangle_2 square(Epeck::Point_2(0, 0), Epeck::Point_2(1, 1));
  const CGAL::Raster_density_2<Epeck> pixel(1, 1, std::vector<double>{3.}, square);
  EXPECT_EQ(pixel.width(), 1u);
  EXPECT_EQ(pixel.pixel(0, 0), 3.);
  EXPECT_EQ(pixel(Epeck::Point_2(0.2, 0.9)), 3.);
  EXPECT_EQ(pixel.integral(), 3.);
  EXPECT_GE(pixel.upper_bound_function()(square), 3.);

  const CGAL::Penrose_importance_sampler<Gmpq_kernel> zero(
    Gmpq_kernel::Iso_rectangle_2(Gmpq_kernel::Point_2(0, 0), Gmpq_kernel::Point_2(2, 1)),
    [](const Gmpq_kernel::Point_2&) { return 0.; });
  EXPECT_EQ(zero.expected_number_of_points(), 0.);
  std::vector<Gmpq_kernel::Point_2> none;
  zero(std::back_inserter(none));
  EXPECT_TRUE(none.empty());
  const CGAL::Penrose_Delaunay_triangulation_2<Gmpq_kernel> from_zero(zero);
  EXPECT_EQ(from_zero.dimension(), -1);
}
