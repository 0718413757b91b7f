// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// penrose_mesh: samples a density over a rectangle with the Penrose
// importance sampler and writes the points, an SVG drawing and statistics.

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "svg_writer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Penrose_importance_sampler<K> Sampler;

const char* usage_text =
  "usage: penrose_mesh --density constant|ramp|radial|image:FILE\n"
  "                    [--points N | --scale S] [--region X0 Y0 X1 Y1] [--no-correction]\n"
  "                    [--out-points FILE] [--svg FILE] [--stats-json FILE]\n"
  "\n"
  "  --density     constant: uniform; ramp: proportional to (x - X0) / (X1 - X0);\n"
  "                radial: exp(-r^2 / (2 s^2)) around the centre, s = 0.2 width, plus 5% of the peak;\n"
  "                image:FILE: luminance of a PNG, JPG, PGM/PPM or Radiance .hdr image over the region\n"
  "  --points N    scale the density so that about N points come out (default 10000)\n"
  "  --scale S     multiply the density (in points per unit area) by S instead\n"
  "  --region      the rectangle sampled (default 0 0 1 1)\n"
  "  --no-correction  keep the raw tile vertices (no correction vectors)\n"
  "  --out-points  one \"x y\" line per point, full precision\n"
  "  --svg         draw the points (over the image, if any)\n"
  "  --stats-json  write {\"points\": ..., \"sample_seconds\": ..., ...}\n"
  "\n"
  "example: penrose_mesh --density ramp --points 20000 --svg ramp.svg\n";

struct Options
{
  std::string density = "constant";
  double points = 10000.;
  double scale = 0.;
  double region[4] = {0, 0, 1, 1};
  bool correction = true;
  std::string out_points, svg, stats_json;
};

[[noreturn]] void usage_error(const std::string& why)
{
  std::cerr << "penrose_mesh: " << why << "\n\n" << usage_text;
  std::exit(2);
}

double number(const char* s, const std::string& option)
{
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if(end == s || *end != '\0' || !std::isfinite(v)) usage_error(option + " expects a number, not '" + s + "'");
  return v;
}

Options parse(int argc, char** argv)
{
  Options o;
  bool have_points = false, have_scale = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](int k = 1) -> const char* {
      if(i + k >= argc) usage_error(a + " needs a value");
      return argv[i + k];
    };
    if(a == "--help" || a == "-h") { std::cout << usage_text; std::exit(0); }
    else if(a == "--density") { o.density = value(); ++i; }
    else if(a == "--points") { o.points = number(value(), a); have_points = true; ++i; }
    else if(a == "--scale") { o.scale = number(value(), a); have_scale = true; ++i; }
    else if(a == "--region") { for(int k = 0; k < 4; ++k) o.region[k] = number(value(k + 1), a); i += 4; }
    else if(a == "--no-correction") o.correction = false;
    else if(a == "--out-points") { o.out_points = value(); ++i; }
    else if(a == "--svg") { o.svg = value(); ++i; }
    else if(a == "--stats-json") { o.stats_json = value(); ++i; }
    else usage_error("unknown option '" + a + "'");
  }
  if(have_points && have_scale) usage_error("give --points or --scale, not both");
  if(have_scale) o.points = 0.;
  if(have_points && !(o.points >= 1.)) usage_error("--points must be at least 1");
  if(have_scale && !(o.scale > 0.)) usage_error("--scale must be positive");
  return o;
}

struct Density
{
  std::function<double(const Point&)> value;
  std::function<double(const K::Iso_rectangle_2&)> upper_bound;  // empty: probes
  std::string image_file;
};

Density make_density(const Options& o, const K::Iso_rectangle_2& region)
{
  const double x0 = o.region[0], y0 = o.region[1], x1 = o.region[2], y1 = o.region[3];
  Density d;
  if(o.density == "constant") d.value = [](const Point&) { return 1.; };
  else if(o.density == "ramp") d.value = [=](const Point& p) { return (p.x() - x0) / (x1 - x0); };
  else if(o.density == "radial") {
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), s = 0.2 * (x1 - x0);
    d.value = [=](const Point& p) {
      const double r2 = (p.x() - cx) * (p.x() - cx) + (p.y() - cy) * (p.y() - cy);
      return std::exp(-r2 / (2 * s * s)) + 0.05;
    };
  } else if(o.density.rfind("image:", 0) == 0) {
    d.image_file = o.density.substr(6);
    CGAL::IO::Luminance_image img = CGAL::IO::read_luminance_image(d.image_file);
    auto raster = std::make_shared<CGAL::Raster_density_2<K>>(img.width, img.height, std::move(img.values), region);
    d.value = [raster](const Point& p) { return (*raster)(p); };
    d.upper_bound = [raster](const K::Iso_rectangle_2& b) { return raster->upper_bound(b); };
  } else usage_error("unknown density '" + o.density + "'");
  return d;
}

std::unique_ptr<Sampler> make_sampler(const Options& o, const K::Iso_rectangle_2& region, const Density& d)
{
  using CGAL::parameters::use_correction_vectors;
  using CGAL::parameters::density_upper_bound;
  const std::size_t n = std::size_t(o.points);
  if(d.upper_bound) {
    if(n) return std::make_unique<Sampler>(region, d.value, density_upper_bound(d.upper_bound,
                 use_correction_vectors(o.correction).number_of_output_points(n)));
    return std::make_unique<Sampler>(region, d.value, density_upper_bound(d.upper_bound,
                 use_correction_vectors(o.correction).density_control_factor(o.scale)));
  }
  if(n) return std::make_unique<Sampler>(region, d.value, use_correction_vectors(o.correction).number_of_output_points(n));
  return std::make_unique<Sampler>(region, d.value, use_correction_vectors(o.correction).density_control_factor(o.scale));
}

void write_points(const std::string& file, const std::vector<Point>& p)
{
  FILE* f = std::fopen(file.c_str(), "w");
  if(!f) throw std::runtime_error(file + ": cannot open for writing");
  for(const Point& q : p) std::fprintf(f, "%.17g %.17g\n", q.x(), q.y());
  if(std::fclose(f) != 0) throw std::runtime_error(file + ": write failed");
}

void write_svg(const Options& o, const Density& d, const std::vector<Point>& p)
{
  penrose_tools::Svg_writer svg(o.svg, o.region[0], o.region[1], o.region[2], o.region[3]);
  if(!d.image_file.empty()) svg.background_image(d.image_file);
  const double r = std::max(0.6, std::min(3., 0.25 * 1024. / std::sqrt(double(p.size()) + 1.)));
  svg.begin_group("fill=\"black\"");
  for(const Point& q : p) svg.dot(q.x(), q.y(), r);
  svg.end_group();
  if(!svg.good()) throw std::runtime_error(o.svg + ": write failed");
}

} // namespace

int main(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  try {
    const K::Iso_rectangle_2 region(o.region[0], o.region[1], o.region[2], o.region[3]);
    if(!(o.region[2] > o.region[0] && o.region[3] > o.region[1]))
      throw std::invalid_argument("the region is empty or degenerate");
    const Density d = make_density(o, region);
    const auto t0 = std::chrono::steady_clock::now();
    const std::unique_ptr<Sampler> sampler = make_sampler(o, region, d);
    std::vector<Point> points;
    points.reserve(std::size_t(sampler->expected_number_of_points() * 1.05) + 16);
    (*sampler)(std::back_inserter(points));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    if(!o.out_points.empty()) write_points(o.out_points, points);
    if(!o.svg.empty()) write_svg(o, d, points);
    if(!o.stats_json.empty()) {
      FILE* f = std::fopen(o.stats_json.c_str(), "w");
      if(!f) throw std::runtime_error(o.stats_json + ": cannot open for writing");
      std::fprintf(f, "{\"points\": %zu, \"expected_points\": %.6g, \"sample_seconds\": %.6g, "
                      "\"density\": \"%s\", \"region\": [%.17g, %.17g, %.17g, %.17g], \"correction\": %s}\n",
                   points.size(), sampler->expected_number_of_points(), seconds, o.density.c_str(),
                   o.region[0], o.region[1], o.region[2], o.region[3], o.correction ? "true" : "false");
      std::fclose(f);
    }
    std::cerr << "penrose_mesh: " << points.size() << " points in " << seconds << " s\n";
  } catch(const std::exception& e) {
    std::cerr << "penrose_mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
