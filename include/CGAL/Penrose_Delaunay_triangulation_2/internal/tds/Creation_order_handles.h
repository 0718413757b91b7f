// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The handles of the elements made one after the other in a
// Compact_container, found from their rank in that order, in constant time
// and without an array of handles (which, for the faces of a TDS, would add
// 8 bytes per face at the peak of a construction). The container gives a
// fresh block's elements in address order and its blocks one after the
// other, so the elements made in a row lie in a few hundred runs of
// consecutive addresses: those runs are recorded as the elements are made,
// whatever the container does, and indexed by buckets of ranks.
//
// A construction makes the TDS's faces (empty, beside the flips) in the order of
// the flat mesh's faces: the TDS face of a flat face, or of a face across,
// is then known before any of them is written, and the faces get their
// vertices and neighbours in one walk.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CREATION_ORDER_HANDLES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CREATION_ORDER_HANDLES_H

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

template <class Container>
class Creation_order_handles
{
  typedef typename Container::value_type Element;

public:
  typedef typename Container::iterator Handle;

  // Records the element made after those recorded before.
  void record(Handle h)
  {
    Element* const p = std::addressof(*h);
    if(count_ == 0 || p != last_ + 1) runs_.push_back({count_, p});
    last_ = p;
    ++count_;
  }

  // To be called once every element is recorded, before operator[].
  void index()
  {
    bucket_.assign((count_ >> bucket_shift) + 1, 0);
    std::uint32_t run = 0;
    for(std::size_t b = 0; b < bucket_.size(); ++b) {
      while(run + 1 < runs_.size() && runs_[run + 1].first_rank <= (b << bucket_shift)) ++run;
      bucket_[b] = run;
    }
  }

  std::size_t size() const { return count_; }

  // The element recorded `rank`-th (from 0).
  Handle operator[](std::size_t rank) const
  {
    CGAL_precondition(rank < count_ && !bucket_.empty());
    std::size_t run = bucket_[rank >> bucket_shift];
    while(run + 1 < runs_.size() && runs_[run + 1].first_rank <= rank) ++run;
    return Container::s_iterator_to(runs_[run].first[rank - runs_[run].first_rank]);
  }

private:
  // In a fresh container the runs are whole blocks, 14 elements or more
  // (Compact_container's first block): a bucket of 64 ranks spans at most six.
  static constexpr int bucket_shift = 6;

  struct Run
  {
    std::size_t first_rank;
    Element* first;
  };

  std::vector<Run> runs_;
  std::vector<std::uint32_t> bucket_;
  Element* last_ = nullptr;
  std::size_t count_ = 0;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CREATION_ORDER_HANDLES_H
