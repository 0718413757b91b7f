// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A minimal SVG canvas for the command-line tools: a region of the plane
// mapped onto a picture `longer_side_px` wide or high, y up, with an optional
// background image. close() writes the end, checks every write and only then
// puts the file in place (see CGAL::IO::internal::Output_file).

#ifndef PENROSE_TOOLS_SVG_WRITER_H
#define PENROSE_TOOLS_SVG_WRITER_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace penrose_tools {

/*
A link to `file` from an SVG written to `svg`: the path of the file relative
to the SVG's folder (a file: URI if there is none), so that it resolves
wherever the SVG is opened from, percent-encoded (RFC 3986) but for its
slashes and unreserved characters, so that %, #, ? and spaces stay part of
the path and the link holds no control character (which XML 1.0 forbids,
even escaped), no byte that is not UTF-8, and nothing XML would need escaped.
*/
inline std::string link_to(const std::string& file, const std::string& svg)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path target = fs::absolute(file, error);
  const fs::path relative = fs::relative(target, fs::absolute(svg, error).parent_path(), error);
  const std::string path = (error || relative.empty() ? target : relative).generic_string();
  std::string link = error || relative.empty() ? "file://" : "";
  for(unsigned char c : path) {
    if(std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') link += char(c);
    else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      link += hex;
    }
  }
  return link;
}

class Svg_writer
{
public:
  Svg_writer(const std::string& file, double xmin, double ymin, double xmax, double ymax,
             double longer_side_px = 1024.)
    : out_(file), xmin_(xmin), ymax_(ymax), k_(longer_side_px / std::max(xmax - xmin, ymax - ymin)),
      w_((xmax - xmin) * k_), h_((ymax - ymin) * k_)
  {
    std::fprintf(out_.stream(), "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\""
                 " width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\">\n", w_, h_, w_, h_);
    out_.write("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  }
  void close()
  {
    out_.write("</svg>\n");
    out_.commit();
  }

  // `href` a URI reference (see link_to()), which needs no escaping in XML
  void background_image(const std::string& href)
  {
    out_.write("<image xlink:href=\"" + href + "\"");
    std::fprintf(out_.stream(), " x=\"0\" y=\"0\" width=\"%g\" height=\"%g\" preserveAspectRatio=\"none\" opacity=\"0.6\"/>\n",
                 w_, h_);
  }

  void begin_group(const std::string& style) { out_.write("<g " + style + ">\n"); }
  void end_group() { out_.write("</g>\n"); }

  void dot(double x, double y, double r)
  {
    std::fprintf(out_.stream(), "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"/>\n", u(x), v(y), r);
  }

  void segment(double x0, double y0, double x1, double y1)
  {
    std::fprintf(out_.stream(), "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", u(x0), v(y0), u(x1), v(y1));
  }

private:
  double u(double x) const { return (x - xmin_) * k_; }
  double v(double y) const { return (ymax_ - y) * k_; }

  CGAL::IO::internal::Output_file out_;
  double xmin_, ymax_, k_, w_, h_;
};

} // namespace penrose_tools

#endif // PENROSE_TOOLS_SVG_WRITER_H
