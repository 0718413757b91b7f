// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the readers and writers of IO/ share about files: a format is chosen
// by the file's extension, and every error names the file. Apart from the
// readers, so that the mesh writer does not need stb_image.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_FILE_NAMES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_FILE_NAMES_H

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace IO {
namespace internal {

// `s` as one printable line: control bytes (ESC, CR, form feed, ...) as
// \xHH, so that a message that echoes a file name or a header neither
// breaks into lines nor changes the terminal; cut after `most` bytes.
inline std::string printable(const std::string& s, std::size_t most = std::string::npos)
{
  std::string p;
  for(std::size_t k = 0; k < s.size() && k < most; ++k) {
    const unsigned char c = static_cast<unsigned char>(s[k]);
    if(c >= 0x20 && c != 0x7f) p += char(c);
    else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      p += hex;
    }
  }
  return s.size() > most ? p + "..." : p;
}

inline std::runtime_error file_error(const std::string& file, const std::string& why)
{
  return std::runtime_error(printable(file) + ": " + why);
}

// The dimensions that a header claims, refused before anything is allocated.
inline void check_dimensions(const std::string& file, double w, double h, std::size_t max_cells)
{
  if(!(w >= 1. && h >= 1. && w * h <= double(max_cells))) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "absurd dimensions %.15g x %.15g (the limit is %zu pixels)", w, h, max_cells);
    throw file_error(file, buf);
  }
}

// extensions and the keywords of text formats are not case-sensitive
inline std::string lowercase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

inline std::string lowercase_extension(const std::string& file)
{
  const std::size_t dot = file.find_last_of('.');
  return lowercase(dot == std::string::npos ? std::string() : file.substr(dot + 1));
}

} // namespace internal
} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_FILE_NAMES_H
