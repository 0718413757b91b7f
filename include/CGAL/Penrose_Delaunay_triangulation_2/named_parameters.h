// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of this package that CGAL 5.5 does not define. Being
// outside CGAL's list, they start a chain (for example
// `parameters::use_correction_vectors(false).number_of_output_points(n)`)
// and cannot be appended to one; to combine them, pass the rest of the chain
// as a second argument: `use_correction_vectors(false, density_upper_bound(b))`.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_NAMED_PARAMETERS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
// The tags live in a namespace of this package: a tag that a later CGAL adds
// to `internal_np` cannot collide with them.
namespace Penrose_np {
enum use_correction_vectors_t { use_correction_vectors };
enum density_upper_bound_t { density_upper_bound };
enum max_error_t { max_error };
enum number_of_points_t { number_of_points };
enum base_fraction_t { base_fraction };
enum density_integral_t { density_integral };
enum window_margin_t { window_margin };
} // namespace Penrose_np

namespace parameters {

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// Whether the sampler moves each sample by its correction vector (default `true`).
inline Named_function_parameters<bool, Penrose_np::use_correction_vectors_t>
use_correction_vectors(bool b)
{
  return Named_function_parameters<bool, Penrose_np::use_correction_vectors_t>(b);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// A callable `double(const Iso_rectangle_2&)` that bounds the density from
/// above over a box: with it, no feature of the density is missed.
template <class Bound>
Named_function_parameters<Bound, Penrose_np::density_upper_bound_t>
density_upper_bound(const Bound& b)
{
  return Named_function_parameters<Bound, Penrose_np::density_upper_bound_t>(b);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// The largest vertical error that `refine_terrain_by_greedy_insertion()` and
/// `triangulate_height_grid()` leave.
inline Named_function_parameters<double, Penrose_np::max_error_t>
max_error(double e)
{
  return Named_function_parameters<double, Penrose_np::max_error_t>(e);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// The most vertices that `refine_terrain_by_greedy_insertion()` and
/// `triangulate_height_grid()` let the triangulation have.
inline Named_function_parameters<std::size_t, Penrose_np::number_of_points_t>
number_of_points(std::size_t n)
{
  return Named_function_parameters<std::size_t, Penrose_np::number_of_points_t>(n);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// The fraction of `number_of_points` that `triangulate_height_grid()` samples
/// before greedy insertion.
inline Named_function_parameters<double, Penrose_np::base_fraction_t>
base_fraction(double f)
{
  return Named_function_parameters<double, Penrose_np::base_fraction_t>(f);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// The integral of the unscaled density over the region, as
/// `Penrose_importance_sampler::density_integral()` gave it: the sampler
/// then does not integrate the density, and makes the same points as the
/// sampler that measured it, which lets a worker build the sampler of a
/// window without reading the density far from it.
inline Named_function_parameters<double, Penrose_np::density_integral_t>
density_integral(double i)
{
  return Named_function_parameters<double, Penrose_np::density_integral_t>(i);
}

/// \ingroup PkgPenroseDelaunayTriangulation2NamedParameters
/// The first margin that `Penrose_Delaunay_window_2` grows its window by,
/// in units of the region's coordinates; it is doubled until the window's
/// triangles are certified.
inline Named_function_parameters<double, Penrose_np::window_margin_t>
window_margin(double m)
{
  return Named_function_parameters<double, Penrose_np::window_margin_t>(m);
}

/// `density_integral(i)` followed by the parameters of `np`.
template <class T, class Tag, class Base>
Named_function_parameters<double, Penrose_np::density_integral_t, Named_function_parameters<T, Tag, Base>>
density_integral(double i, const Named_function_parameters<T, Tag, Base>& np)
{
  return {i, np};
}

/// `max_error(e)` followed by the parameters of `np`.
template <class T, class Tag, class Base>
Named_function_parameters<double, Penrose_np::max_error_t, Named_function_parameters<T, Tag, Base>>
max_error(double e, const Named_function_parameters<T, Tag, Base>& np)
{
  return {e, np};
}

/// `number_of_points(n)` followed by the parameters of `np`.
template <class T, class Tag, class Base>
Named_function_parameters<std::size_t, Penrose_np::number_of_points_t, Named_function_parameters<T, Tag, Base>>
number_of_points(std::size_t n, const Named_function_parameters<T, Tag, Base>& np)
{
  return {n, np};
}

/// `base_fraction(f)` followed by the parameters of `np`.
template <class T, class Tag, class Base>
Named_function_parameters<double, Penrose_np::base_fraction_t, Named_function_parameters<T, Tag, Base>>
base_fraction(double f, const Named_function_parameters<T, Tag, Base>& np)
{
  return {f, np};
}

/// `use_correction_vectors(b)` followed by the parameters of `np`.
template <class T, class Tag, class Base>
Named_function_parameters<bool, Penrose_np::use_correction_vectors_t, Named_function_parameters<T, Tag, Base>>
use_correction_vectors(bool b, const Named_function_parameters<T, Tag, Base>& np)
{
  return {b, np};
}

/// `density_upper_bound(b)` followed by the parameters of `np`.
template <class Bound, class T, class Tag, class Base>
Named_function_parameters<Bound, Penrose_np::density_upper_bound_t, Named_function_parameters<T, Tag, Base>>
density_upper_bound(const Bound& b, const Named_function_parameters<T, Tag, Base>& np)
{
  return {b, np};
}

} // namespace parameters
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_NAMED_PARAMETERS_H
