// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Allocators for the construction's large flat arrays (a few to tens of
// bytes per point each): those that live to the end of a construction are
// backed by transparent huge pages, the others by small pages. The construction touches each such array once at growth and then
// walks it with little reuse: with 4 KiB pages, a fresh process spends a
// large share of the construction in page faults, and each walk misses the
// TLB. Huge pages (2 MiB) remove both
// costs where the system offers them (transparent_hugepage set to `always`
// or `madvise`); elsewhere, and for small arrays, this is std::allocator.
// Define CGAL_PENROSE_NO_HUGE_PAGES to use std::allocator always.
//
// Released blocks are kept, up to 16 and 1 GiB in all, for the next request
// of the same size: a construction needs the same arrays as the last one of
// its size. On a virtual machine that hands free memory back to its host
// (free page reporting), a fresh huge page may be one the host took back:
// its first touch then costs a host fault, tens of times slower than a
// page freed shortly before, and a base mesh on such pages may take twice
// as long. The kernel serves huge pages
// from whole free 2 MiB blocks, the very ones it reports to the host, and
// small pages from memory freed shortly before, which it has not reported:
// so only the arrays that live to the end of a construction are on huge
// pages (the flat mesh, whose walks also gain from them), and the arrays
// that the base mesh needs alone are on small ones.
//
// release_kept_blocks() unmaps the blocks that are kept and not taken back;
// a construction calls it before the storage of its TDS is reserved, its
// peak, so that the peak is the same as without keeping them. (Marking the
// kept blocks MADV_FREE instead, so that the kernel could take them back,
// made the next constructions' base meshes several times slower.)

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__) && !defined(CGAL_PENROSE_NO_HUGE_PAGES)
#  include <sys/mman.h>
#  if defined(MADV_HUGEPAGE)
#    define CGAL_PENROSE_HUGE_PAGES 1
#    include <mutex>
#  endif
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

#if defined(CGAL_PENROSE_HUGE_PAGES)
// The huge-page blocks released and kept for reuse, shared by all threads.
class Released_huge_blocks
{
public:
  // A kept block of exactly `bytes`, or nullptr.
  static void* take(std::size_t bytes)
  {
    Released_huge_blocks& r = instance();
    std::lock_guard<std::mutex> lock(r.mutex_);
    for(std::size_t i = r.blocks_.size(); i-- > 0;)
      if(r.blocks_[i].second == bytes) {
        void* p = r.blocks_[i].first;
        r.bytes_ -= bytes;
        r.blocks_.erase(r.blocks_.begin() + i);
        return p;
      }
    return nullptr;
  }

  // Keeps the block, unmapping the oldest ones beyond the limits.
  static void give(void* p, std::size_t bytes)
  {
    if(bytes > most_bytes) { munmap(p, bytes); return; }
    Released_huge_blocks& r = instance();
    std::lock_guard<std::mutex> lock(r.mutex_);
    r.blocks_.emplace_back(p, bytes);  // within the capacity reserved: no allocation
    r.bytes_ += bytes;
    while(r.blocks_.size() > most_blocks || r.bytes_ > most_bytes) {
      munmap(r.blocks_.front().first, r.blocks_.front().second);
      r.bytes_ -= r.blocks_.front().second;
      r.blocks_.erase(r.blocks_.begin());
    }
  }

  // Unmaps every kept block.
  static void release()
  {
    Released_huge_blocks& r = instance();
    std::lock_guard<std::mutex> lock(r.mutex_);
    for(const auto& b : r.blocks_) munmap(b.first, b.second);
    r.blocks_.clear();
    r.bytes_ = 0;
  }

private:
  // a construction releases about half a dozen large arrays after its peak
  static constexpr std::size_t most_blocks = 16;
  static constexpr std::size_t most_bytes = std::size_t(1) << 30;

  Released_huge_blocks() { blocks_.reserve(most_blocks + 1); }

  // never destroyed: a block may be released by a static array after every
  // local static is gone; the process's end unmaps what is kept
  static Released_huge_blocks& instance()
  {
    static Released_huge_blocks* r = new Released_huge_blocks;
    return *r;
  }

  std::mutex mutex_;
  std::vector<std::pair<void*, std::size_t>> blocks_;  // oldest first
  std::size_t bytes_ = 0;
};
#endif

// Unmaps the released blocks kept for reuse (see above).
inline void release_kept_blocks()
{
#if defined(CGAL_PENROSE_HUGE_PAGES)
  Released_huge_blocks::release();
#endif
}

#if defined(CGAL_PENROSE_HUGE_PAGES)
// Where the large blocks of the arrays that live to the end of a
// construction come from: whole huge pages at a huge-page boundary, kept
// once released.
struct Kept_huge_pages
{
  static constexpr std::size_t page = std::size_t(1) << 21;
  // below a few huge pages, rounding up would waste more than it saves
  static constexpr std::size_t least_bytes = 4 * page;

  // A kept block, or a fresh one: one more page than asked for is mapped,
  // and what lies before and after the aligned range is unmapped again.
  static void* map(std::size_t size)
  {
    if(void* kept = Released_huge_blocks::take(size)) return kept;
    void* raw = mmap(nullptr, size + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if(raw == MAP_FAILED) throw std::bad_alloc();
    char* const begin = static_cast<char*>(raw);
    const std::size_t head = (page - std::uintptr_t(begin) % page) % page;
    char* const aligned = begin + head;
    if(head > 0) munmap(begin, head);
    munmap(aligned + size, page - head);
    madvise(aligned, size, MADV_HUGEPAGE);  // advice: its failure is harmless
    return aligned;
  }

  static void unmap(void* p, std::size_t size) { Released_huge_blocks::give(p, size); }
};

// Where the large blocks of the arrays that serve one step of a construction
// come from: small pages, mapped and unmapped directly. Through malloc, such
// an array would raise its threshold for mapping and, freed, stay resident in
// the heap, adding to the peak of the next construction.
struct Small_pages
{
  static constexpr std::size_t page = 4096;
  static constexpr std::size_t least_bytes = std::size_t(1) << 20;

  static void* map(std::size_t size)
  {
    void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if(p == MAP_FAILED) throw std::bad_alloc();
    return p;
  }

  static void unmap(void* p, std::size_t size) { munmap(p, size); }
};
#else
struct Kept_huge_pages {};
struct Small_pages {};
#endif

// Faults in, writable, the whole small pages of [begin, end), which must be
// mapped: the first touch of a fresh page costs a fault wherever it comes,
// and a thread with nothing else to do can take it off the thread that will
// write there. Returns false where the system cannot (before Linux 5.14,
// elsewhere), and then does nothing.
inline bool populate_pages(const void* begin, const void* end)
{
#if defined(CGAL_PENROSE_HUGE_PAGES) && defined(MADV_POPULATE_WRITE)
  const std::uintptr_t first = (std::uintptr_t(begin) + Small_pages::page - 1) & ~(Small_pages::page - 1);
  const std::uintptr_t last = std::uintptr_t(end) & ~(Small_pages::page - 1);
  return last <= first || madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE) == 0;
#else
  (void)begin; (void)end;
  return false;
#endif
}

// An allocator whose large blocks come from `Pages`; elsewhere, and for
// small arrays, this is std::allocator.
template <class T, class Pages>
class Mapped_allocator
{
public:
  typedef T value_type;

  Mapped_allocator() = default;
  template <class U> Mapped_allocator(const Mapped_allocator<U, Pages>&) {}

  T* allocate(std::size_t n)
  {
#if defined(CGAL_PENROSE_HUGE_PAGES)
    if(is_large(n)) {
      if(n > (std::size_t(-1) - 2 * Pages::page) / sizeof(T)) throw std::bad_alloc();
      return static_cast<T*>(Pages::map(rounded(n)));
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n)
  {
#if defined(CGAL_PENROSE_HUGE_PAGES)
    if(is_large(n)) { Pages::unmap(p, rounded(n)); return; }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <class U> bool operator==(const Mapped_allocator<U, Pages>&) const { return true; }
  template <class U> bool operator!=(const Mapped_allocator<U, Pages>&) const { return false; }

private:
#if defined(CGAL_PENROSE_HUGE_PAGES)
  static bool is_large(std::size_t n) { return n >= Pages::least_bytes / sizeof(T); }
  static std::size_t rounded(std::size_t n) { return (n * sizeof(T) + Pages::page - 1) & ~(Pages::page - 1); }
#endif
};

template <class T>
using Huge_page_allocator = Mapped_allocator<T, Kept_huge_pages>;

// A vector for the arrays that grow with the number of points and live to
// the end of a construction.
template <class T>
using Large_vector = std::vector<T, Huge_page_allocator<T>>;

// A vector for the arrays that grow with the number of points and serve one
// step of a construction.
template <class T>
using Scratch_vector = std::vector<T, Mapped_allocator<T, Small_pages>>;

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
