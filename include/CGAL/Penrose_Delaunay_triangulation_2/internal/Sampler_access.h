// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sampler's context and the conversion of its placed samples, which the
// triangulation and the tests of the internals use and the public API hides.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLER_ACCESS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLER_ACCESS_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>

namespace CGAL {

template <class Traits> class Penrose_importance_sampler;

namespace internal {
namespace Penrose {

struct Sampler_access
{
  template <class Traits>
  static const Sampling_context& context(const Penrose_importance_sampler<Traits>& s) { return *s.context_; }

  template <class Traits>
  static typename Penrose_importance_sampler<Traits>::Sample
  sample(const Penrose_importance_sampler<Traits>& s, const Placed_sample& p) { return s.to_sample(p); }

  // `window` in the sampler's terms, checked as its operator()(window, out) checks it.
  template <class Traits>
  static Sample_window window(const Penrose_importance_sampler<Traits>& s, const typename Traits::Iso_rectangle_2& window)
  {
    return s.sample_window(window);
  }
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SAMPLER_ACCESS_H
