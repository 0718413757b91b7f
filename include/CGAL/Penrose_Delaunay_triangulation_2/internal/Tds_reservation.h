// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fresh TDS whose storage is reserved on a helper thread while the
// construction finishes its flat mesh. Most of the cost of writing a TDS is
// the first touch of its storage: page faults, and the free list that
// Compact_container threads through every new block. Creating 10^6 vertices
// and 2 x 10^6 faces in a fresh TDS takes about 53 ms here, 15 ms once their
// storage is reserved. Reserved on a second core, that cost overlaps with
// the Lawson flips, which touch nothing of the TDS. (Where the process
// reuses memory that an earlier TDS freed, there are no page faults and
// little to gain.)
//
// Before it reserves, the helper runs a job that frees memory the
// construction no longer needs (unmapping 10^6 points' worth of the base
// mesh builder's arrays takes about 9 ms): freed there, that memory is gone
// before the reservation touches any, and the peak is the same as if the
// calling thread had freed it.
//
// The reservation is skipped (the TDS is simply empty) below
// `least_vertices`, where starting a thread costs more than it saves (at
// 10^3 points a construction took 12% longer with it, at 3 x 10^4 2% longer,
// at 10^5 6 to 35% shorter); without threads (CGAL_HAS_NO_THREADS), or where
// the user asks for none (CGAL_PENROSE_NO_HELPER_THREAD); on a
// machine with one core; where no thread can be started; for a TDS whose
// containers have no reserve(); and if the reservation runs out of memory.
// Writing the TDS then allocates as it goes, and fails there if it must.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Helper_threads.h>

#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace internal {
namespace Penrose {

template <class Tds, class = void>
struct Has_reservable_containers : std::false_type {};

template <class Tds>
struct Has_reservable_containers<Tds, std::void_t<decltype(std::declval<Tds&>().vertices().reserve(std::size_t())),
                                                  decltype(std::declval<Tds&>().faces().reserve(std::size_t()))>>
  : std::true_type {};

template <class Tds>
class Tds_reservation
{
public:
  static constexpr std::size_t least_vertices = std::size_t(1) << 16;

  // Starts reserving room for `vertices` vertices and `faces` faces, after
  // `release()`, which must not throw. Without a helper, `release()` runs
  // here.
  template <class Release>
  Tds_reservation(std::size_t vertices, std::size_t faces, Release release)
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if constexpr(Has_reservable_containers<Tds>::value)
      if(vertices >= least_vertices && std::thread::hardware_concurrency() > 1) {
        helper_ = try_to_start_thread([this, vertices, faces, release]() mutable {
          release();
          reserve(vertices, faces);
        });
        if(helper_.joinable()) return;  // otherwise no reservation
      }
#else
    (void)vertices; (void)faces;
#endif
    release();
  }

  Tds_reservation(std::size_t vertices, std::size_t faces) : Tds_reservation(vertices, faces, [] {}) {}

  Tds_reservation(const Tds_reservation&) = delete;
  Tds_reservation& operator=(const Tds_reservation&) = delete;

  ~Tds_reservation() { wait(); }

  // The TDS, empty, with its storage reserved if it could be; waits for the
  // helper. To be taken once.
  Tds& tds()
  {
    wait();
    return tds_;
  }

private:
  void reserve(std::size_t vertices, std::size_t faces)
  {
    try {
      tds_.vertices().reserve(vertices);
      tds_.faces().reserve(faces);
    } catch(const std::bad_alloc&) {
      tds_.clear();
    }
  }

  void wait()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(helper_.joinable()) helper_.join();
#endif
  }

  Tds tds_;
#if defined(CGAL_PENROSE_HELPER_THREADS)
  std::thread helper_;
#endif
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_RESERVATION_H
