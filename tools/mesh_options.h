// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of penrose_mesh: its options, their checks and its usage
// text. Apart from the tool, so that a fuzz target can parse command lines.

#ifndef PENROSE_TOOLS_MESH_OPTIONS_H
#define PENROSE_TOOLS_MESH_OPTIONS_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>

#include "tiles.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace penrose_tools {

inline const char* const usage_text =
  "usage: penrose_mesh (--density constant|ramp|radial|image:FILE | --terrain FILE)\n"
  "                    [--points N | --scale S] [--max-error E] [--base-fraction F] [--fit-heights]\n"
  "                    [--region X0 Y0 X1 Y1] [--no-correction] [--boundary | --no-boundary]\n"
  "                    [--gamma G] [--log] [--invert] [--gradient] [--height-scale S] [--viewer X Y]\n"
  "                    [--out-points FILE] [--out-mesh FILE] [--svg FILE] [--png FILE]\n"
  "                    [--reconstruct FILE] [--stats-json FILE] [--max-pixels N]\n"
  "                    [--tiles K [--tile I J]] [--streamed]\n"
  "\n"
  "density:\n"
  "  --density constant|ramp|radial\n"
  "                uniform; proportional to (x - X0) / (X1 - X0); or\n"
  "                exp(-r^2 / (2 s^2)) around the centre, s = 0.2 width, plus 5% of the peak\n"
  "  --density image:FILE\n"
  "                the luminance of a PNG, JPG, PGM/PPM (8 or 16 bit) or Radiance .hdr image,\n"
  "                for importance sampling (stippling, the paper's Figure 9); with --reconstruct\n"
  "                and none of --log, --invert, --gradient and --gamma, the mesh is made to\n"
  "                render the image back instead: a sample for a fraction of the vertices (see\n"
  "                --base-fraction; uniform for a black image), the rest inserted where the\n"
  "                luminance is worst interpolated\n"
  "  --terrain FILE\n"
  "                a height field: a 16-bit grey PNG or PGM, or an ESRI ASCII grid (.asc);\n"
  "                density from its curvature (largest absolute Hessian eigenvalue, smoothed,\n"
  "                to the power 2/3; uniform if it is zero everywhere: a flat terrain);\n"
  "                the mesh is 3D, with the heights\n"
  "  --gamma G     raise the density to the power G (after the options below)\n"
  "  --log         image: use log(1 + L / mean L) instead of L (for HDR images)\n"
  "  --invert      image: dense where the image is dark\n"
  "  --gradient    image: use the smoothed gradient magnitude (edges), plus a tenth of its mean\n"
  "  --height-scale S   terrain: multiply the heights by S (default 1)\n"
  "  --viewer X Y  terrain: divide the density by 1 + d / d0, d the distance to (X, Y),\n"
  "                d0 a fiftieth of the diagonal (view-dependent mesh), scaled so that\n"
  "                the cell nearest the viewer keeps its density\n"
  "  --max-pixels N  refuse an image or height field of more than N pixels (cells),\n"
  "                from its header, before reading it (default 67108864 = 8192 x 8192:\n"
  "                at that size an RGB image takes up to 1.5 GiB of memory, 2.5 GiB with\n"
  "                --reconstruct or --max-error, a 16-bit terrain 0.7 GiB)\n"
  "\n"
  "sampling:\n"
  "  --points N    scale the density so that about N points come out (default 10000);\n"
  "                for a terrain, the number of vertices (see --base-fraction), at most\n"
  "                one a cell where greedy insertion refines\n"
  "  --scale S     multiply the density (in points per unit area) by S instead\n"
  "  --max-error E terrain or image: insert vertices until the vertical error (in the\n"
  "                heights' unit; for an image, of the luminance of its colours, from 0\n"
  "                to 1) of every cell that the mesh covers is at most E or, if --points\n"
  "                is given, until the mesh has N vertices: whichever comes first (the\n"
  "                message and \"max_error_reached\" say which). Alone, it starts from a\n"
  "                sample of a point per 1024 cells\n"
  "  --base-fraction F  terrain, or image with --max-error or --reconstruct (see\n"
  "                --density image:FILE): sample F x N of the N\n"
  "                vertices, then insert, one at a time, the centre of the cell of\n"
  "                largest vertical error (greedy insertion, as in delatin) until N\n"
  "                (default 0.05; 1: samples only)\n"
  "  --fit-heights terrain, or image meshed for --reconstruct: once the mesh is made,\n"
  "                give its vertices the heights that minimise the squared vertical error\n"
  "                over all the cells it covers (least squares); for an image, its colours,\n"
  "                channel by channel, and its luminance (the heights of --out-mesh). The\n"
  "                RMS error drops (the PSNR rises), the mesh no longer interpolates the\n"
  "                grid, and its max error may grow. Not with --max-error, whose bound is\n"
  "                that of the interpolating mesh\n"
  "  --region      the rectangle sampled (default 0 0 1 1; an image or a height field is\n"
  "                stretched over it, and by default covers 0 0 WIDTH HEIGHT, or the\n"
  "                extent in the header of an .asc grid)\n"
  "  --no-correction  keep the raw tile vertices (no correction vectors)\n"
  "  --boundary    add points along the border of the region at the local density, so\n"
  "                that the mesh covers the whole rectangle (default for images and\n"
  "                terrains); samples closer to the border than half the spacing there\n"
  "                are left out, and the triangles with a vertex on the border are\n"
  "                refined (circumcentres, midpoints of border edges) until none has\n"
  "                an angle under 15 degrees; with --points, the vertices that greedy\n"
  "                insertion added last make room for those. With --max-error, border\n"
  "                points are also added where the heights along the border need them\n"
  "  --no-boundary do not\n"
  "\n"
  "output:\n"
  "  --out-points  one \"x y\" line per point (\"x y z\" for a terrain), full precision\n"
  "  --out-mesh    the triangulation as .off, .ply or .obj (by extension), the vertices\n"
  "                in the order of --out-points, triangles counter-clockwise\n"
  "  --svg         draw the triangulation and the points (over the image, if any,\n"
  "                linked by its path from the SVG's folder)\n"
  "  --png         draw the triangulation over the image or the height field\n"
  "                (--svg and --png drawings are 1024 pixels on the region's longer side)\n"
  "  --reconstruct image: render the mesh back to a PNG, colours interpolated linearly\n"
  "                over each triangle from the image at its vertices\n"
  "  --stats-json  write {\"points\": ..., \"sample_seconds\": ..., \"triangulate_seconds\": ...,\n"
  "                \"vertices\": ..., \"faces\": ..., \"flips\": ..., \"fallbacks\": ..., ...}; for a\n"
  "                terrain also the vertical \"max_error\" and \"rms_error\" of the mesh and\n"
  "                \"grid_max_error\", \"grid_rms_error\" of the regular grid of as many\n"
  "                vertices, \"inserted_points\" and \"refine_seconds\" of the greedy\n"
  "                insertion; for an image \"psnr\" and \"grid_psnr\" likewise; with\n"
  "                --fit-heights \"fit_rms_error_before\", \"fit_rms_error_after\" (over the\n"
  "                cells covered; of the luminance for an image), \"fit_iterations\" and\n"
  "                \"fit_seconds\". The tile tree is\n"
  "                sampled while the triangulation is derived from it: sample_seconds is the\n"
  "                sampler's preparation, triangulate_seconds the rest\n"
  "  Each output is written to a temporary file beside it, then renamed over it\n"
  "  once complete: a run that fails or is killed leaves the file as it was (a\n"
  "  read-only file is refused). An output that is the input or another output\n"
  "  (through ./, a symbolic or a hard link too) is refused before anything is\n"
  "  read; devices such as /dev/null are written in place and not checked.\n"
  "\n"
  "tiles:\n"
  "  --tiles K     cut the region into K x K tiles and write one mesh each,\n"
  "                NAME_I_J.EXT for --out-mesh NAME.EXT, I from west to east and J from\n"
  "                south to north, from 0 (1 <= K <= 1024; K x K at most the vertices\n"
  "                expected, and a tile must have 8 x 8 cells of an image or height\n"
  "                field at least). A tile's vertices are the\n"
  "                samples of the whole region that lie in it, points along its sides\n"
  "                computed from each side alone (the same in the tiles that share it:\n"
  "                the tiles meet without gaps or skirts), vertices that greedy\n"
  "                insertion puts strictly inside it, and those that shape its\n"
  "                triangles at the region's border (the sides shared with another\n"
  "                tile are never split, and their triangles are not mended).\n"
  "                --points N is for the whole region: each tile inserts greedily up\n"
  "                to its share of N, that of its samples in the region's; --max-error\n"
  "                E holds in each tile. On an image or height field, the sides lie\n"
  "                between cells. The tiles are computed in parallel where TBB\n"
  "                is linked, each alone: the same bytes as with --tile. Only\n"
  "                --out-mesh applies (not --fit-heights), and the border is always on\n"
  "  --tile I J    compute and write tile (I, J) of --tiles K only\n"
  "\n"
  "larger than memory:\n"
  "  --streamed    write --out-mesh (a .ply) window by window: windows of about 2^18\n"
  "                points are triangulated alone, in parallel where TBB is linked,\n"
  "                and written as they come, so that memory holds the windows in\n"
  "                flight (about 0.3 GB), not the mesh: any number of points, as the\n"
  "                disk allows. The same triangulation (of the samples alone, without\n"
  "                border points), its vertices numbered window by window; binary\n"
  "                little-endian, x and y as doubles, 32-bit indices (64-bit beyond\n"
  "                3.5 x 10^9 points). Chosen by itself for a --density with only\n"
  "                --out-mesh FILE.ply when the mesh would take more than half the\n"
  "                memory. Not with --terrain, --boundary, --tiles or other outputs\n"
  "  --window-points N  about N points in a window of --streamed (default 262144)\n"
  "  --threads T   run --streamed and --tiles on T threads (default: all that TBB\n"
  "                allows, where TBB is linked)\n"
  "\n"
  "A progress bar is drawn on stderr, when it is a terminal, for runs over a second.\n"
  "A file that cannot be read or written ends the run with status 1 and one line\n"
  "naming it and the problem; a bad option, with status 2 (control characters of\n"
  "the names and values echoed are written \\xHH). A reader reads no further than\n"
  "the dimensions in the file's header allow: a pipe or a device that does not end\n"
  "is refused.\n"
  "\n"
  "examples:\n"
  "  penrose_mesh --density ramp --points 20000 --svg ramp.svg --out-mesh ramp.off\n"
  "  penrose_mesh --density image:photo.jpg --points 20000 --reconstruct photo_mesh.png \\\n"
  "               --png photo_edges.png --stats-json photo.json      (to render it back)\n"
  "  penrose_mesh --density image:memorial.hdr --log --points 50000 --svg memorial.svg\n"
  "                                                                  (to stipple it)\n"
  "  penrose_mesh --terrain dem.asc --max-error 0.5 --out-mesh dem.ply --stats-json dem.json\n"  "  penrose_mesh --terrain dem.asc --points 20000 --fit-heights --out-mesh dem.ply\n"
  "  penrose_mesh --terrain dem.asc --points 100000 --base-fraction 1 --viewer 0 0 \\\n"
  "               --out-mesh dem.ply --png dem.png --stats-json dem.json\n";

struct Options
{
  bool help = false;
  std::string density = "constant", terrain;
  double points = 10000.;
  bool points_given = false;
  double scale = 0.;
  double region[4] = {0, 0, 1, 1};
  bool region_given = false, correction = true, boundary = false;
  double max_error = 0.;      // 0: not given
  double base_fraction = 0.05;
  bool fit_heights = false;
  // an image meshed for its reconstruction, by greedy insertion on its luminance
  bool reconstruction_mesh = false;
  double gamma = 1., height_scale = 1.;
  bool log = false, invert = false, gradient = false;
  bool viewer_given = false;
  double viewer[2] = {0, 0};
  std::string out_points, out_mesh, svg, png, reconstruct, stats_json;
  bool streamed = false;     // --out-mesh written window by window
  double window_points = 262144.;
  int threads = 0;           // 0: as many as TBB allows
  int tiles = 0;             // 0: one mesh
  int tile[2] = {-1, -1};    // -1: every tile
  double max_pixels = double(CGAL::IO::default_max_pixels);
};

// A bad option or option value; penrose_mesh exits with status 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

[[noreturn]] inline void usage_error(const std::string& why) { throw Usage_error(why); }

inline double number(const char* s, const std::string& option)
{
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if(end == s || *end != '\0' || !std::isfinite(v)) usage_error(option + " expects a number, not '" + s + "'");
  return v;
}

// A whole number from `lo` to `hi`.
inline int whole_number(const char* s, const std::string& option, int lo, int hi)
{
  const double v = number(s, option);
  if(!(v >= lo && v <= hi && v == std::floor(v)))
    usage_error(option + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi)
                + ", not '" + s + "'");
  return int(v);
}

// Whether --out-mesh is the only output asked for, as --streamed needs.
inline bool streamable_outputs(const Options& o)
{
  return o.out_points.empty() && o.svg.empty() && o.png.empty() && o.reconstruct.empty() && o.stats_json.empty();
}

// The options of the command line `argv` (argv[0] the program); --help sets
// `help` and ends the parse.
inline Options parse(int argc, const char* const* argv)
{
  Options o;
  bool have_points = false, have_scale = false, have_density = false;
  bool have_boundary = false, no_boundary = false, have_max_error = false, have_base_fraction = false;
  bool have_gamma = false, have_window_points = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](int k = 1) -> const char* {
      if(i + k >= argc) usage_error(a + " needs a value");
      return argv[i + k];
    };
    auto text = [&](std::string& s) { s = value(); ++i; };
    // a file name: empty, it was taken for no file at all
    auto file = [&](std::string& s) {
      text(s);
      if(s.empty()) usage_error(a + " needs a file name, not ''");
    };
    if(a == "--help" || a == "-h") { o.help = true; return o; }
    else if(a == "--density") { text(o.density); have_density = true; }
    else if(a == "--terrain") file(o.terrain);
    else if(a == "--points") { o.points = number(value(), a); have_points = true; ++i; }
    else if(a == "--scale") { o.scale = number(value(), a); have_scale = true; ++i; }
    else if(a == "--region") { for(int k = 0; k < 4; ++k) o.region[k] = number(value(k + 1), a); i += 4; o.region_given = true; }
    else if(a == "--no-correction") o.correction = false;
    else if(a == "--boundary") { o.boundary = true; have_boundary = true; }
    else if(a == "--no-boundary") no_boundary = true;
    else if(a == "--max-error") { o.max_error = number(value(), a); have_max_error = true; ++i; }
    else if(a == "--base-fraction") { o.base_fraction = number(value(), a); have_base_fraction = true; ++i; }
    else if(a == "--fit-heights") o.fit_heights = true;
    else if(a == "--gamma") { o.gamma = number(value(), a); have_gamma = true; ++i; }
    else if(a == "--log") o.log = true;
    else if(a == "--invert") o.invert = true;
    else if(a == "--gradient") o.gradient = true;
    else if(a == "--height-scale") { o.height_scale = number(value(), a); ++i; }
    else if(a == "--viewer") { for(int k = 0; k < 2; ++k) o.viewer[k] = number(value(k + 1), a); i += 2; o.viewer_given = true; }
    else if(a == "--out-points") file(o.out_points);
    else if(a == "--out-mesh") file(o.out_mesh);
    else if(a == "--svg") file(o.svg);
    else if(a == "--png") file(o.png);
    else if(a == "--reconstruct") file(o.reconstruct);
    else if(a == "--stats-json") file(o.stats_json);
    else if(a == "--max-pixels") { o.max_pixels = number(value(), a); ++i; }
    else if(a == "--tiles") { o.tiles = whole_number(value(), a, 1, 1024); ++i; }
    else if(a == "--streamed") o.streamed = true;
    else if(a == "--threads") { o.threads = whole_number(value(), a, 1, 4096); ++i; }
    else if(a == "--window-points") { o.window_points = number(value(), a); have_window_points = true; ++i; }
    else if(a == "--tile") {
      for(int k = 0; k < 2; ++k) o.tile[k] = whole_number(value(k + 1), a, 0, 1023);
      i += 2;
    }
    else usage_error("unknown option '" + a + "'");
  }
  const bool image = o.density.rfind("image:", 0) == 0, terrain = !o.terrain.empty();
  if(!image && o.density != "constant" && o.density != "ramp" && o.density != "radial")
    usage_error("unknown density '" + o.density + "'");
  if(o.density == "image:") usage_error("--density image: needs a file name");
  if(have_points && have_scale) usage_error("give --points or --scale, not both");
  if(have_scale) o.points = 0.;
  o.points_given = have_points;
  if(have_points && !(o.points >= 1.)) usage_error("--points must be at least 1");
  // beyond, the count would not convert to a std::size_t
  if(have_points && !(o.points <= 1e18)) usage_error("--points must be at most 1e18");
  if(have_scale && !(o.scale > 0.)) usage_error("--scale must be positive");
  if(have_density && terrain) usage_error("give --density or --terrain, not both");
  if(!(o.gamma > 0.)) usage_error("--gamma must be positive");
  if(o.region_given && !(o.region[2] - o.region[0] > 0. && o.region[3] - o.region[1] > 0.
                         && std::isfinite(o.region[2] - o.region[0]) && std::isfinite(o.region[3] - o.region[1])))
    usage_error("--region: X1 - X0 and Y1 - Y0 must be positive and finite");
  // the readers take a std::size_t
  if(!(o.max_pixels >= 1. && o.max_pixels <= 1e18)) usage_error("--max-pixels must be in [1, 1e18]");
  if((o.log || o.invert || o.gradient) && !image) usage_error("--log, --invert and --gradient apply to images");
  if(!o.reconstruct.empty() && !image) usage_error("--reconstruct needs an image (--density image:FILE)");
  if((o.viewer_given || o.height_scale != 1.) && !terrain) usage_error("--viewer and --height-scale apply to --terrain");
  if(have_boundary && no_boundary) usage_error("give --boundary or --no-boundary, not both");
  o.boundary = have_boundary || (!no_boundary && (image || terrain));
  if(have_max_error && !(o.max_error > 0.)) usage_error("--max-error must be positive");
  if(have_base_fraction && !(o.base_fraction > 0. && o.base_fraction <= 1.)) usage_error("--base-fraction must be in (0, 1]");
  if((have_max_error || have_base_fraction) && !terrain && !image)
    usage_error("--max-error and --base-fraction apply to --terrain and images");
  o.reconstruction_mesh = image && !o.reconstruct.empty() && !(o.log || o.invert || o.gradient || have_gamma);
  if(have_base_fraction && image && !have_max_error && !o.reconstruction_mesh)
    usage_error("--base-fraction applies to an image with --max-error, or with --reconstruct and none of --log,"
                " --invert, --gradient and --gamma");
  if(o.fit_heights && !terrain && !o.reconstruction_mesh)
    usage_error("--fit-heights applies to --terrain, and to an image with --reconstruct and none of --log,"
                " --invert, --gradient and --gamma");
  if(o.fit_heights && have_max_error) usage_error("--fit-heights and --max-error: give one (the bound is that of the interpolating mesh)");
  if(have_base_fraction && have_max_error && !have_points) usage_error("--base-fraction is a fraction of --points: give both");
  if(o.tile[0] >= 0 && o.tiles == 0) usage_error("--tile I J needs --tiles K");
  if(o.tile[0] >= o.tiles || o.tile[1] >= o.tiles)
    usage_error("--tile I J must be within 0.." + std::to_string(o.tiles - 1) + " for --tiles " + std::to_string(o.tiles));
  if(have_window_points && !(o.window_points >= 16. && o.window_points <= 1e9))
    usage_error("--window-points must be in [16, 1e9]");
  if(have_window_points && !o.streamed) usage_error("--window-points applies to --streamed");
  if(o.streamed) {
    if(o.out_mesh.size() < 4 || o.out_mesh.compare(o.out_mesh.size() - 4, 4, ".ply") != 0)
      usage_error("--streamed needs --out-mesh FILE.ply");
    if(terrain || o.tiles || have_max_error || o.fit_heights)
      usage_error("--streamed applies to --density alone (not --terrain, --tiles, --max-error or --fit-heights)");
    if(!streamable_outputs(o)) usage_error("--streamed writes --out-mesh only");
    if(o.boundary) usage_error("--streamed triangulates the samples alone: give --no-boundary");
  }
  if(o.tiles) {
    if(o.out_mesh.empty()) usage_error(std::string(o.tile[0] >= 0 ? "--tile" : "--tiles") + " needs --out-mesh");
    const std::pair<const char*, const std::string*> others[] = {
      {"--out-points", &o.out_points}, {"--svg", &o.svg}, {"--png", &o.png}, {"--reconstruct", &o.reconstruct},
      {"--stats-json", &o.stats_json}};
    for(const auto& [option, file] : others)
      if(!file->empty()) usage_error(std::string(option) + " does not apply to --tiles, which writes --out-mesh only");
    if(no_boundary) usage_error("--no-boundary does not apply to --tiles, whose sides need their border points");
    if(o.fit_heights) usage_error("--fit-heights does not apply to --tiles: two tiles would fit their common side apart");
    o.boundary = true;
  }
  return o;
}

// What `path` names, to compare files: the device and inode of an existing
// file, so that ./x, a symbolic link and a hard link are x; else the
// absolute path, the links of its folders resolved. Empty for what is not a
// regular file (/dev/null, a pipe), which outputs may share.
inline std::string file_identity(const std::string& path)
{
  struct stat st;
  if(::stat(path.c_str(), &st) == 0)
    return S_ISREG(st.st_mode) ? std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) : std::string();
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return "path " + std::filesystem::weakly_canonical(absolute, error).string();
}

// Refuses, before anything is read, an output that is the input or another
// output: the input would be lost, or an output overwritten by the next.
// The tiles of --tiles, the only output then, are checked against the input.
inline void check_files(const Options& o)
{
  std::vector<std::pair<std::string, std::string>> files;  // the option (and its value) and the file
  if(!o.terrain.empty()) files.emplace_back("--terrain " + o.terrain, o.terrain);
  if(o.density.rfind("image:", 0) == 0) files.emplace_back("--density " + o.density, o.density.substr(6));
  const std::size_t inputs = files.size();
  const std::pair<const char*, const std::string*> outputs[] = {
    {"--out-points", &o.out_points}, {"--out-mesh", &o.out_mesh}, {"--svg", &o.svg}, {"--png", &o.png},
    {"--reconstruct", &o.reconstruct}, {"--stats-json", &o.stats_json}};
  for(const auto& [option, file] : outputs)
    if(!file->empty() && !(o.tiles && file == &o.out_mesh)) files.emplace_back(option + (" " + *file), *file);
  std::map<std::string, std::size_t> seen;
  for(std::size_t k = 0; k < files.size(); ++k) {
    const std::string id = file_identity(files[k].second);
    if(id.empty()) continue;
    const auto [at, first] = seen.emplace(id, k);
    if(first) continue;
    if(at->second < inputs) usage_error(files[k].first + " is the input file (" + files[at->second].first + ")");
    usage_error(files[k].first + " and " + files[at->second].first + " are the same file");
  }
  if(!o.tiles || !inputs) return;
  const std::string input = file_identity(files[0].second);
  for(int j = 0; j < o.tiles; ++j)
    for(int i = 0; i < o.tiles; ++i)
      if(o.tile[0] < 0 || (i == o.tile[0] && j == o.tile[1])) {
        const std::string tile = tile_file_name(o.out_mesh, i, j);
        if(!input.empty() && file_identity(tile) == input)
          usage_error("--out-mesh " + o.out_mesh + ": tile " + std::to_string(i) + " " + std::to_string(j) + ", " + tile
                      + ", is the input file (" + files[0].first + ")");
      }
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_MESH_OPTIONS_H
