// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fuzz targets' command lines: a fuzzer's input read as penrose_mesh's
// arguments, one a line.

#ifndef PENROSE_FUZZ_COMMAND_LINE_ARGUMENTS_H
#define PENROSE_FUZZ_COMMAND_LINE_ARGUMENTS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

struct Command_line
{
  std::vector<std::string> arguments;  // "penrose_mesh" first
  std::vector<const char*> argv;       // into `arguments`

  Command_line(const std::uint8_t* data, std::size_t size) : arguments{"penrose_mesh"}
  {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for(std::size_t at = 0; at <= text.size();) {
      const std::size_t end = std::min(text.find('\n', at), text.size());
      arguments.push_back(text.substr(at, end - at));
      at = end + 1;
    }
    for(const std::string& a : arguments) argv.push_back(a.c_str());
  }
  Command_line(const Command_line&) = delete;
};

#endif // PENROSE_FUZZ_COMMAND_LINE_ARGUMENTS_H
