// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fresh TDS whose vertex storage is reserved, and whose faces are created
// empty, on a helper thread while the construction finishes its flat mesh.
// Most of the cost of writing a TDS is the first touch of its storage: page
// faults, and the free list that Compact_container threads through every
// new block: creating the vertices and faces of a fresh TDS takes several
// times as long as once their storage is reserved. On a second core,
// that cost overlaps with the Lawson flips, which touch nothing of the TDS.
// The faces can be made there, not only reserved, since the flips change
// their number no more than their storage: one for each slot of the flat
// mesh's faces, in order, recorded in a Creation_order_handles, so that the
// calling thread finds the TDS face of any flat face and gives them their
// vertices and neighbours in two halves on two threads, where creating them
// would have to be done by one.
//
// Before it reserves, the helper runs a job that frees memory the
// construction no longer needs (unmapping the base mesh builder's arrays
// takes milliseconds): freed there, that memory is gone
// before the reservation touches any, and the peak is the same as if the
// calling thread had freed it.
//
// Nothing is prepared (the TDS is empty, and prepared() false) below
// `least_vertices`, where starting a thread costs more than it saves (with
// it, constructions of 3 x 10^4 points or fewer were slower, those of 10^5
// faster); without threads (CGAL_HAS_NO_THREADS), or where
// the user asks for none (CGAL_PENROSE_NO_HELPER_THREAD); on a machine with
// one core; where no thread can be started; for a TDS whose vertex container
// has no reserve(); and if the helper runs out of memory, or a face's
// default constructor throws. The caller then creates what it needs itself,
// and fails there if it must.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Creation_order_handles.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Helper_threads.h>

#include <cstddef>
#include <type_traits>
#include <utility>
#if defined(CGAL_PENROSE_HELPER_THREADS)
#  include <atomic>
#  include <thread>
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

template <class Tds, class = void>
struct Has_reservable_vertices : std::false_type {};

template <class Tds>
struct Has_reservable_vertices<Tds, std::void_t<decltype(std::declval<Tds&>().vertices().reserve(std::size_t()))>>
  : std::true_type {};

template <class Tds>
class Tds_reservation
{
public:
  typedef Creation_order_handles<typename Tds::Face_range> Faces;

  static constexpr std::size_t least_vertices = std::size_t(1) << 16;

  // Starts, on a helper, `release()`, which must not throw, then the
  // reservation of room for `vertices` vertices and the creation of `faces`
  // faces, default-constructed. Without a helper, only `release()` runs,
  // here.
  template <class Release>
  Tds_reservation(std::size_t vertices, std::size_t faces, Release release)
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if constexpr(Has_reservable_vertices<Tds>::value)
      if(vertices >= least_vertices && more_than_one_core()) {
        helper_ = try_to_start_thread([this, vertices, faces, release]() mutable {
          release();
          prepare(vertices, faces);
        });
        if(helper_.joinable()) return;  // otherwise nothing prepared
      }
#else
    (void)vertices; (void)faces;
#endif
    release();
  }

  Tds_reservation(const Tds_reservation&) = delete;
  Tds_reservation& operator=(const Tds_reservation&) = delete;

  ~Tds_reservation() { wait(); }

  // Whether the helper made the faces; waits for it.
  bool prepared()
  {
    wait();
    return prepared_;
  }

  // Where prepared(), the TDS with its faces, otherwise empty; waits for the
  // helper. To be taken once.
  Tds& tds()
  {
    wait();
    return tds_;
  }

  // The TDS, whose vertices the caller may create while the helper may
  // still make its faces: the vertices and the faces of a
  // Triangulation_data_structure_2 are two containers, and the helper
  // touches the vertices' only first, to reserve them. Waits until then.
  Tds& tds_for_vertices()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    while(helper_.joinable() && !vertices_reserved_.load(std::memory_order_acquire)) std::this_thread::yield();
#endif
    return tds_;
  }

  // Where prepared(), the faces of tds() in the order they were made,
  // indexed; otherwise none. To be taken once.
  Faces& faces()
  {
    wait();
    return faces_;
  }

private:
  void prepare(std::size_t vertices, std::size_t faces)
  {
    try {
      tds_.vertices().reserve(vertices);
    } catch(...) {  // out of memory: the caller will allocate them, or fail
    }
#if defined(CGAL_PENROSE_HELPER_THREADS)
    vertices_reserved_.store(true, std::memory_order_release);
#endif
    try {
      for(std::size_t f = 0; f < faces; ++f) faces_.record(tds_.create_face());
      faces_.index();
      prepared_ = true;
    } catch(...) {  // out of memory, or a face's constructor threw: the caller will create them, or fail
      tds_.faces().clear();
      faces_ = Faces();
    }
  }

  void wait()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(helper_.joinable()) helper_.join();
#endif
  }

  Tds tds_;
  Faces faces_;
  bool prepared_ = false;
#if defined(CGAL_PENROSE_HELPER_THREADS)
  std::atomic<bool> vertices_reserved_{false};
  std::thread helper_;
#endif
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
