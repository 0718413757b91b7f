// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fresh TDS whose vertex storage is reserved, and whose faces are created
// empty, one for each face of the flat mesh, in order, recorded in a
// Creation_order_handles: the TDS face of any flat face is then found by
// its index, and the faces can be given their vertices and neighbours in
// two halves. Most of the cost of writing a TDS is the first touch of its
// storage (page faults, and the free list that Compact_container threads
// through every new block); the Lawson flips change the number of faces no
// more than they touch the TDS, so with Parallel_tag the reservation is a
// task beside them.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tds/Creation_order_handles.h>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace internal {
namespace Penrose {

template <class Tds, class = void>
struct Has_reservable_vertices : std::false_type {};

template <class Tds>
struct Has_reservable_vertices<Tds, std::void_t<decltype(std::declval<Tds&>().vertices().reserve(std::size_t()))>>
  : std::true_type {};

template <class Tds>
struct Tds_reservation
{
  typedef Creation_order_handles<typename Tds::Face_range> Faces;

  // Room for `vertices` vertices, where the TDS's vertex container has
  // reserve(), and `faces` faces, default-constructed.
  Tds_reservation(std::size_t vertices, std::size_t faces)
  {
    if constexpr(Has_reservable_vertices<Tds>::value) tds.vertices().reserve(vertices);
    for(std::size_t f = 0; f < faces; ++f) made.record(tds.create_face());
    made.index();
  }

  Tds tds;
  Faces made;  // the faces of tds in the order they were made, indexed
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
