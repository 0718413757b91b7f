// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the image reader (PNG, JPEG, PGM/PPM, Radiance HDR) on
// any bytes either reads an image or throws std::runtime_error; anything
// else (a crash, a hang, another exception, unbounded memory) is a finding.

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_rgb_image.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    // a lower pixel limit than the default keeps each run small
    CGAL::IO::internal::decode_rgb_image("fuzz", std::string(reinterpret_cast<const char*>(data), size),
                                         std::size_t(1) << 20);
  } catch(const std::runtime_error&) {
  }
  return 0;
}
