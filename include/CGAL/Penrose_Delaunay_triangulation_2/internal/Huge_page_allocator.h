// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An allocator for the construction's large flat arrays (a few to tens of
// bytes per point each), which asks Linux to back them with transparent huge
// pages. The construction touches each such array once at growth and then
// walks it with little reuse: with 4 KiB pages, a fresh process spends about
// a fifth of the construction in page faults (85,000 of them at 10^6
// points), and each walk misses the TLB. Huge pages (2 MiB) remove both
// costs where the system offers them (transparent_hugepage set to `always`
// or `madvise`); elsewhere, and for small arrays, this is std::allocator.
// Define CGAL_PENROSE_NO_HUGE_PAGES to use std::allocator always.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__) && !defined(CGAL_PENROSE_NO_HUGE_PAGES)
#  include <sys/mman.h>
#  if defined(MADV_HUGEPAGE)
#    define CGAL_PENROSE_HUGE_PAGES 1
#  endif
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

template <class T>
class Huge_page_allocator
{
public:
  typedef T value_type;

  Huge_page_allocator() = default;
  template <class U> Huge_page_allocator(const Huge_page_allocator<U>&) {}

  T* allocate(std::size_t n)
  {
#if defined(CGAL_PENROSE_HUGE_PAGES)
    if(is_large(n)) return static_cast<T*>(map(n * sizeof(T)));
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n)
  {
#if defined(CGAL_PENROSE_HUGE_PAGES)
    if(is_large(n)) { munmap(p, rounded(n * sizeof(T))); return; }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <class U> bool operator==(const Huge_page_allocator<U>&) const { return true; }
  template <class U> bool operator!=(const Huge_page_allocator<U>&) const { return false; }

private:
  static constexpr std::size_t huge_page = std::size_t(1) << 21;

  // below a few huge pages, rounding up would waste more than it saves
  static bool is_large(std::size_t n) { return n >= 4 * huge_page / sizeof(T); }
  static std::size_t rounded(std::size_t bytes) { return (bytes + huge_page - 1) & ~(huge_page - 1); }

#if defined(CGAL_PENROSE_HUGE_PAGES)
  // Maps whole huge pages at a huge-page boundary: one more page than asked
  // for is mapped, and what lies before and after the aligned range is
  // unmapped again.
  static void* map(std::size_t bytes)
  {
    if(bytes > std::size_t(-1) - 2 * huge_page) throw std::bad_alloc();
    const std::size_t size = rounded(bytes);
    void* raw = mmap(nullptr, size + huge_page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if(raw == MAP_FAILED) throw std::bad_alloc();
    char* const begin = static_cast<char*>(raw);
    const std::size_t head = (huge_page - std::uintptr_t(begin) % huge_page) % huge_page;
    char* const aligned = begin + head;
    if(head > 0) munmap(begin, head);
    munmap(aligned + size, huge_page - head);
    madvise(aligned, size, MADV_HUGEPAGE);  // advice: its failure is harmless
    return aligned;
  }
#endif
};

// A vector for the arrays that grow with the number of points.
template <class T>
using Large_vector = std::vector<T, Huge_page_allocator<T>>;

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
