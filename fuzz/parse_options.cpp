// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: penrose_mesh's option parser on any command line (the
// input's lines are the arguments) either returns options or throws
// Usage_error.

#include "command_line_arguments.h"
#include "mesh_options.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const Command_line c(data, size);
  try {
    penrose_tools::parse(int(c.argv.size()), c.argv.data());
  } catch(const penrose_tools::Usage_error&) {
  }
  return 0;
}
