// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// penrose_data_generator: makes the bundled inputs of penrose_mesh,
// deterministically (the same bytes on every machine):
// - a synthetic terrain, 16 bits: a few hills, a ridged range and fractal
//   detail that is rough in the mountains and faint in the plains;
// - a test image: smooth colour gradients under shapes with sharp edges.
// The terrain is the same landscape at every size, with finer detail.

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* usage_text =
  "usage: penrose_data_generator --terrain FILE [--size N]   (16-bit .png, .pgm or .asc)\n"
  "       penrose_data_generator --image FILE [--size N]     (8-bit RGB .png)\n"
  "\n"
  "  --size N   width and height in pixels (default 512)\n"
  "\n"
  "The bundled data/ was made with:\n"
  "  penrose_data_generator --terrain data/terrain.png\n"
  "  penrose_data_generator --image data/test_image.png\n";

std::uint64_t hash(std::int64_t i, std::int64_t j, std::uint64_t seed)
{
  std::uint64_t z = seed + std::uint64_t(i) * 0x9e3779b97f4a7c15ull + std::uint64_t(j) * 0xc2b2ae3d27d4eb4full;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Gradient noise in [-1, 1] with a unit lattice: a random unit gradient at
// each lattice point, blended with the quintic fade.
double noise(double x, double y, std::uint64_t seed)
{
  const double fx = std::floor(x), fy = std::floor(y);
  const std::int64_t i = std::int64_t(fx), j = std::int64_t(fy);
  auto fade = [](double t) { return t * t * t * (t * (6 * t - 15) + 10); };
  auto corner = [&](std::int64_t a, std::int64_t b) {
    const double angle = double(hash(a, b, seed) >> 11) * (6.283185307179586 / 9007199254740992.);
    return std::cos(angle) * (x - double(a)) + std::sin(angle) * (y - double(b));
  };
  const double u = fade(x - fx), v = fade(y - fy);
  const double bottom = corner(i, j) + u * (corner(i + 1, j) - corner(i, j));
  const double top = corner(i, j + 1) + u * (corner(i + 1, j + 1) - corner(i, j + 1));
  return 1.4 * (bottom + v * (top - bottom));
}

// Fractal sum of noise from 8 cells across down to the pixel.
double fractal(double x, double y, int octaves, std::uint64_t seed)
{
  double s = 0., amplitude = 1., frequency = 8.;
  for(int o = 0; o < octaves; ++o, amplitude *= 0.5, frequency *= 2.)
    s += amplitude * noise(frequency * x, frequency * y, seed + std::uint64_t(o));
  return s;
}

// The height at (x, y) in the unit square, about in [0, 1].
double terrain_height(double x, double y, int octaves)
{
  const double hills[5][4] = {  // centre, radius, height
    {0.30, 0.35, 0.16, 0.45}, {0.70, 0.70, 0.12, 0.30}, {0.75, 0.25, 0.20, 0.25},
    {0.25, 0.78, 0.10, 0.20}, {0.52, 0.52, 0.07, 0.15}};
  double h = 0.1;
  for(const auto& k : hills) {
    const double r2 = (x - k[0]) * (x - k[0]) + (y - k[1]) * (y - k[1]);
    h += k[3] * std::exp(-r2 / (2 * k[2] * k[2]));
  }
  // mountains in the north-west, plains in the south-east
  const double rough = 1. / (1. + std::exp(-10. * (y - x + 0.1)));
  const double ridges = 1. - std::abs(noise(3. * x + 0.5, 3. * y + 0.25, 101));
  h += rough * (0.22 * ridges * ridges + 0.08 * fractal(x, y, octaves, 7));
  h += 0.006 * fractal(x, y, octaves, 13);
  return h;
}

void make_terrain(const std::string& file, std::size_t n)
{
  const int octaves = std::max(1, int(std::ceil(std::log2(double(n) / 8.))));
  CGAL::IO::Height_field hf;
  hf.width = hf.height = n;
  hf.x1 = hf.y1 = double(n);
  hf.values.resize(n * n);
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      hf.values[j * n + i] = terrain_height((i + 0.5) / double(n), 1. - (j + 0.5) / double(n), octaves);
  const auto [lo, hi] = std::minmax_element(hf.values.begin(), hf.values.end());
  const double a = *lo, b = *hi;
  for(double& v : hf.values) v = std::round(1000. + 60000. * (v - a) / (b - a));
  CGAL::IO::write_height_field(file, hf);
}

// The colour at (x, y) of the unit square, y down: a diagonal gradient, a
// soft glow, and shapes with sharp edges and gradients of their own.
void image_colour(double x, double y, double rgb[3])
{
  rgb[0] = 0.15 + 0.6 * x;
  rgb[1] = 0.25 + 0.5 * y;
  rgb[2] = 0.7 - 0.4 * x * y;
  const double glow = std::exp(-((x - 0.7) * (x - 0.7) + (y - 0.3) * (y - 0.3)) / 0.02);
  for(int c = 0; c < 3; ++c) rgb[c] += 0.25 * glow;
  auto paint = [&](double r, double g, double b) { rgb[0] = r; rgb[1] = g; rgb[2] = b; };
  if(std::hypot(x - 0.3, y - 0.3) < 0.17) paint(0.9 - y, 0.2, 0.2 + x);                       // disc
  if(x > 0.55 && x < 0.9 && y > 0.55 && y < 0.8) paint(0.1, 0.3 + 0.8 * (x - 0.55), 0.2);     // box
  const double ring = std::hypot(x - 0.28, y - 0.75);
  if(ring > 0.1 && ring < 0.16) paint(0.95, 0.85, 0.3 * (1. - y));                              // ring
  if(y > 0.1 && y < 0.45 && x > 0.55 && x < 0.95 && x - 0.55 > 1.1 * (0.45 - y)) paint(0.2, 0.2, 0.25);  // wedge
  if(x > 0.05 && x < 0.95 && y > 0.9 && y < 0.96 && int(std::floor(x * 24.)) % 2 == 0) paint(1., 1., 1.);  // bars
}

void make_image(const std::string& file, std::size_t n)
{
  const int s = 4;  // 4 x 4 samples a pixel: antialiased edges, as in a photograph
  std::vector<unsigned char> rgb(3 * n * n);
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      double sum[3] = {0., 0., 0.}, c[3];
      for(int a = 0; a < s; ++a)
        for(int b = 0; b < s; ++b) {
          image_colour((i + (a + 0.5) / s) / double(n), (j + (b + 0.5) / s) / double(n), c);
          for(int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      for(int k = 0; k < 3; ++k)
        rgb[3 * (j * n + i) + std::size_t(k)] = (unsigned char)std::lround(255. * std::min(1., std::max(0., sum[k] / (s * s))));
    }
  // encoded in memory, then written as every output is (see CGAL::IO::internal::Output_file)
  std::string png;
  auto append = [](void* to, void* bytes, int k) { static_cast<std::string*>(to)->append(static_cast<char*>(bytes), std::size_t(k)); };
  if(!stbi_write_png_to_func(append, &png, int(n), int(n), 3, rgb.data(), int(3 * n)))
    throw std::runtime_error(file + ": cannot encode the PNG");
  CGAL::IO::internal::write_bytes(file, png);
}

} // namespace

int main(int argc, char** argv)
{
  std::string terrain, image;
  std::size_t size = 512;
  for(int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if(a == "--terrain") terrain = argv[i + 1];
    else if(a == "--image") image = argv[i + 1];
    else if(a == "--size") size = std::size_t(std::strtoul(argv[i + 1], nullptr, 10));
    else { std::cerr << usage_text; return 2; }
  }
  if(argc % 2 == 0 || (terrain.empty() && image.empty()) || size < 2 || size > 16384) {
    std::cerr << usage_text;
    return 2;
  }
  try {
    if(!terrain.empty()) make_terrain(terrain, size);
    if(!image.empty()) make_image(image, size);
  } catch(const std::exception& e) {
    std::cerr << "penrose_data_generator: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
