// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Streaming traversal of the tile tree: depth first, with a fixed-size stack,
// so that sampling alone needs memory for its output only.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DEPTH_FIRST_SAMPLING_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DEPTH_FIRST_SAMPLING_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_subdivision.h>

#include <array>
#include <cstdint>
#include <utility>

namespace CGAL {
namespace internal {
namespace Penrose {

// Calls visit(x, y, importance, birth) for every sample vertex of the tree
// whose tile is subdivided for a sample of `window` (see
// Sampling_context::should_refine), in depth-first order, when the tile that
// creates it is subdivided: every sample of the window among others near it,
// in time proportional to their number plus the depth of the tree.
template <class Visitor>
void for_each_sample_depth_first(const Sampling_context& context, const Sample_window& window, Visitor&& visit)
{
  struct Node
  {
    double x[3], y[3], importance[3];
    Tile_label label;
    std::uint8_t level;
  };
  // each subdivision pops one node and pushes at most three. A child is
  // assembled in the free slot above the top and tested there: it is pushed
  // only if it is to be subdivided, so that the leaves, most of the tiles,
  // cost no pop
  std::array<Node, 2 * max_level + 8> stack;
  std::size_t top = 0;

  Node& root = stack[0];
  for(int i = 0; i < 3; ++i) {
    root.x[i] = context.root_x(i);
    root.y[i] = context.root_y(i);
    root.importance[i] = context.importance(root.x[i], root.y[i]);
  }
  root.label = root_label();
  root.level = 0;
  if(!window.is_empty() && context.should_refine(root.level, root.label.threshold, root.x, root.y, root.importance, window)) ++top;

  double x[5], y[5], importance[5];
  for(std::size_t refined = 1; top > 0; ++refined) {
    context.check_refinement(refined);
    // read in place, not copied: a copy of a node just pushed stalls on the
    // stores that wrote it. Its children overwrite it, once it is read.
    const Node& t = stack[--top];
    const Tile_label label = t.label;
    const Subdivision_rule& r = rule(label.type);
    for(int i = 0; i < 3; ++i) { x[i] = t.x[i]; y[i] = t.y[i]; importance[i] = t.importance[i]; }
    const int child_level = t.level + 1;
    place_new_vertices(r, x, y);
    for(int k = 0; k < r.number_of_new_vertices; ++k) {
      importance[3 + k] = context.importance(x[3 + k], y[3 + k]);
      if(r.new_vertices[k].is_sample) visit(x[3 + k], y[3 + k], importance[3 + k], sample_birth(label, r, child_level));
    }
    for(int c = r.number_of_children - 1; c >= 0; --c) {
      const Child_rule& cr = r.children[c];
      Node& n = stack[top];
      for(int i = 0; i < 3; ++i) {
        n.x[i] = x[cr.corners[i]];
        n.y[i] = y[cr.corners[i]];
        n.importance[i] = importance[cr.corners[i]];
      }
      if(!context.should_refine(child_level, child_threshold(label.threshold, cr, child_level), n.x, n.y,
                                n.importance, window))
        continue;
      n.label = child_label(label, cr, child_level);
      n.level = static_cast<std::uint8_t>(child_level);
      ++top;
    }
  }
}

// The same over the whole region.
template <class Visitor>
void for_each_sample_depth_first(const Sampling_context& context, Visitor&& visit)
{
  for_each_sample_depth_first(context, context.region_window(), std::forward<Visitor>(visit));
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DEPTH_FIRST_SAMPLING_H
