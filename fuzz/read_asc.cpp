// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the ESRI ASCII grid reader on any text either reads a
// grid or throws std::runtime_error.

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    CGAL::IO::internal::parse_ESRI_ASCII_grid("fuzz", std::string(reinterpret_cast<const char*>(data), size),
                                              std::size_t(1) << 20);
  } catch(const std::runtime_error&) {
  }
  return 0;
}
