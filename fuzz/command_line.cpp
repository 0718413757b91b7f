// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the whole of penrose_mesh on any command line (the
// input's lines are the arguments), run in a scratch folder that holds small
// inputs made here (a grid, a PGM, a PNG, a Radiance file, a symbolic and a
// hard link), where the outputs, whose names are mutated like the rest, go
// too. Whatever the arguments, the status is 0, 1 or 2, the file that the
// run reads is unchanged, no temporary file is left, and a run that succeeds
// wrote every output it names. Command lines that would leave the folder (a
// '/' but for a leading "./") or ask for more than 10,000 points, 4 x 4
// tiles or 64 streamed windows are skipped, to keep each run within
// milliseconds.

#define PENROSE_MESH_NO_MAIN  // penrose_mesh() is called here
#include "command_line_arguments.h"
#include "penrose_mesh.cpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path& scratch()
{
  static const fs::path folder = fs::absolute("command_line_scratch");
  return folder;
}

// The inputs, by name: made once, written again before every run.
const std::map<std::string, std::string>& inputs()
{
  static const std::map<std::string, std::string> files = [] {
    std::map<std::string, std::string> f;
    std::string asc = "ncols 12\nnrows 10\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
    for(int j = 0; j < 10; ++j) {
      for(int i = 0; i < 12; ++i) asc += std::to_string((i * i + 3 * j * i + 7 * j) % 23) + (i < 11 ? " " : "\n");
    }
    f["in.asc"] = asc;
    std::string pgm = "P5\n16 12\n255\n", rgb;
    for(int k = 0; k < 16 * 12; ++k) {
      pgm += char(k * 37 % 256);
      for(int c = 0; c < 3; ++c) rgb += char((k * (c + 5) * 11) % 256);
    }
    f["in.pgm"] = pgm;
    std::string png;
    auto append = [](void* to, void* bytes, int n) { static_cast<std::string*>(to)->append(static_cast<char*>(bytes), std::size_t(n)); };
    stbi_write_png_to_func(append, &png, 16, 12, 3, rgb.data(), 16 * 3);
    f["in.png"] = png;
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
    for(int k = 0; k < 32; ++k) hdr += std::string{char(20 + k), char(40 + k), char(60 + k), char(128 + k % 4)};
    f["in.hdr"] = hdr;
    return f;
  }();
  return files;
}

void make_inputs()
{
  fs::remove_all(scratch());
  fs::create_directories(scratch());
  for(const auto& [name, bytes] : inputs()) std::ofstream(scratch() / name, std::ios::binary) << bytes;
  fs::create_symlink("in.asc", scratch() / "link.asc");
  fs::create_hard_link(scratch() / "in.png", scratch() / "hard.png");
}

std::optional<std::string> contents(const fs::path& file)
{
  std::error_code error;
  if(!fs::is_regular_file(file, error)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

[[noreturn]] void finding(const std::string& what)
{
  std::fprintf(stderr, "command_line: %s\n", what.c_str());
  std::abort();
}

// A file name within the scratch folder: no '/' but for a leading "./".
bool stays_inside(std::string a)
{
  if(a.rfind("image:", 0) == 0) a = a.substr(6);
  if(a.rfind("./", 0) == 0) a = a.substr(2);
  return a.find('/') == std::string::npos;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  make_inputs();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const Command_line c(data, size);
  for(const std::string& a : c.arguments)
    if(!stays_inside(a)) return 0;
  Options o;
  try {
    o = penrose_tools::parse(int(c.argv.size()), c.argv.data());
  } catch(const penrose_tools::Usage_error&) {
  }
  if(!(o.points > 0. && o.points <= 10000.) || o.tiles > 4 || (o.streamed && o.points > 64. * o.window_points))
    return 0;

  // the file that the run reads, as it was
  const std::string read = !o.terrain.empty() ? o.terrain : o.density.rfind("image:", 0) == 0 ? o.density.substr(6) : "";
  const std::optional<std::string> before = read.empty() ? std::nullopt : contents(scratch() / read);

  const fs::path home = fs::current_path();
  fs::current_path(scratch());
  std::ostringstream discarded;
  std::streambuf* const err = std::cerr.rdbuf(discarded.rdbuf());
  std::streambuf* const out = std::cout.rdbuf(discarded.rdbuf());
  const int status = penrose_mesh(int(c.argv.size()), c.argv.data());
  std::cerr.rdbuf(err);
  std::cout.rdbuf(out);
  fs::current_path(home);

  if(status < 0 || status > 2) finding("status " + std::to_string(status));
  if(before && contents(scratch() / read) != before) finding("the input " + read + " changed");
  for(const auto& entry : fs::directory_iterator(scratch())) {
    const std::string name = entry.path().filename().string();
    if(name.size() > 4 && name[0] == '.' && name.compare(name.size() - 4, 4, ".tmp") == 0)
      finding("a temporary file is left: " + name);
  }
  if(status == 0 && !o.help) {
    std::vector<std::string> written{o.out_points, o.svg, o.png, o.reconstruct, o.stats_json};
    if(!o.tiles) written.push_back(o.out_mesh);
    for(int j = 0; j < o.tiles; ++j)
      for(int i = 0; i < o.tiles; ++i)
        if(o.tile[0] < 0 || (i == o.tile[0] && j == o.tile[1])) written.push_back(penrose_tools::tile_file_name(o.out_mesh, i, j));
    for(const std::string& file : written)
      if(!file.empty() && !fs::exists(scratch() / file)) finding("the output " + file + " was not written");
  }
  make_inputs();  // the outputs go; an input overwritten as another's output comes back
  return 0;
}
