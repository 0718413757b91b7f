// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: penrose_mesh's option parser on any command line (the
// input's lines are the arguments) either returns options or throws
// Usage_error.

#include "mesh_options.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> arguments{"penrose_mesh"};
  const std::string text(reinterpret_cast<const char*>(data), size);
  for(std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    arguments.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  std::vector<const char*> argv;
  for(const std::string& a : arguments) argv.push_back(a.c_str());
  try {
    penrose_tools::parse(int(argv.size()), argv.data());
  } catch(const penrose_tools::Usage_error&) {
  }
  return 0;
}
