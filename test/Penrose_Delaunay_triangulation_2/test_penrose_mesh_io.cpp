// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The readers and writers of Penrose_Delaunay_triangulation_2/IO: images and
// height fields read back what was written (by stb_image_write or by the
// package), meshes are re-read with CGAL's own OFF, PLY and OBJ readers, and
// every bad file (missing, empty, truncated, wrong format, absurd dimensions)
// gives an exception whose message names the file.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_rgb_image.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/write_triangulation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Projection_traits_xy_3.h>

#include <stb/stb_image_write.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace IO = CGAL::IO;

std::set<std::string>& temporary_files()
{
  static std::set<std::string> files;
  return files;
}

// The temporary files go when the tests of the process end.
struct Remove_temporary_files : ::testing::Environment
{
  void TearDown() override
  {
    for(const std::string& f : temporary_files()) std::remove(f.c_str());
  }
};
::testing::Environment* const remove_temporary_files =
  ::testing::AddGlobalTestEnvironment(new Remove_temporary_files);

// A file of the running test: ctest runs the tests in parallel processes.
std::string temp(const std::string& name)
{
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string file =
    ::testing::TempDir() + "penrose_io_" + test->test_suite_name() + "_" + test->name() + "_" + name;
  temporary_files().insert(file);
  return file;
}

void write_file(const std::string& file, const std::string& bytes)
{
  std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string read_file(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// `read(file)` must throw a std::runtime_error whose message names the file
// and contains `why`, on one line.
void expect_failure(const std::function<void(const std::string&)>& read, const std::string& file,
                    const std::string& why)
{
  try {
    read(file);
    ADD_FAILURE() << file << ": no exception, expected '" << why << "'";
  } catch(const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(file + ": ", 0), 0u) << m;
    EXPECT_NE(m.find(why), std::string::npos) << m << " (expected '" << why << "')";
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

IO::Height_field ramp_field(std::size_t w, std::size_t h)
{
  IO::Height_field hf;
  hf.width = w;
  hf.height = h;
  hf.x1 = double(w);
  hf.y1 = double(h);
  for(std::size_t j = 0; j < h; ++j)
    for(std::size_t i = 0; i < w; ++i) hf.values.push_back(double(i * 1000 + j * 7));
  return hf;
}

// ---------------------------------------------------------------- height fields

TEST(HeightField, SixteenBitPngAndPgmKeepEveryValue)
{
  const IO::Height_field hf = ramp_field(61, 23);
  for(const char* ext : {"png", "pgm"}) {
    const std::string file = temp(std::string("field.") + ext);
    IO::write_height_field(file, hf);
    const IO::Height_field r = IO::read_height_field(file);
    ASSERT_EQ(r.width, 61u);
    ASSERT_EQ(r.height, 23u);
    EXPECT_EQ(r.values, hf.values) << ext;
    EXPECT_EQ(r.x0, 0.);
    EXPECT_EQ(r.x1, 61.);
    EXPECT_EQ(r.y1, 23.);
  }
}

TEST(HeightField, EightBitImagesGiveTheirRawValues)
{
  write_file(temp("grey8.pgm"), std::string("P5\n# a comment\n3 1\n255\n", 23) + std::string("\x00\x80\xff", 3));
  EXPECT_EQ(IO::read_height_field(temp("grey8.pgm")).values, (std::vector<double>{0., 128., 255.}));
  const unsigned char grey[3] = {0, 128, 255};
  ASSERT_TRUE(stbi_write_png(temp("grey8.png").c_str(), 3, 1, 1, grey, 3));
  EXPECT_EQ(IO::read_height_field(temp("grey8.png")).values, (std::vector<double>{0., 128., 255.}));
}

TEST(HeightField, AsciiGridRoundTripAndGeoreference)
{
  IO::Height_field hf = ramp_field(5, 4);
  hf.values[3] = -12.625;
  hf.x0 = 1000.5; hf.x1 = 1000.5 + 5 * 30.; hf.y0 = -20.; hf.y1 = -20. + 4 * 30.;
  IO::write_height_field(temp("grid.asc"), hf);
  const IO::Height_field r = IO::read_height_field(temp("grid.asc"));
  EXPECT_EQ(r.values, hf.values);
  EXPECT_EQ(r.x0, hf.x0);
  EXPECT_EQ(r.y0, hf.y0);
  EXPECT_EQ(r.x1, hf.x1);
  EXPECT_EQ(r.y1, hf.y1);
}

TEST(HeightField, AsciiGridCentresAndNodata)
{
  write_file(temp("nodata.asc"), "NCOLS 3\nNROWS 2\nXLLCENTER 10\nYLLCENTER 20\nCELLSIZE 2\nNODATA_value -9999\n"
                                 "5 -9999 7\n8 9 -9999\n");
  const IO::Height_field r = IO::read_height_field(temp("nodata.asc"));
  EXPECT_EQ(r.values, (std::vector<double>{5, 5, 7, 8, 9, 5}));  // NODATA takes the lowest height
  EXPECT_EQ(r.x0, 9.);
  EXPECT_EQ(r.y0, 19.);
  EXPECT_EQ(r.x1, 15.);
  EXPECT_EQ(r.y1, 23.);
}

TEST(HeightField, AsciiGridRowsByLine)
{
  write_file(temp("crlf.asc"), "ncols 2\r\nnrows 2\r\nxllcorner 0\r\nyllcorner 0\r\ncellsize 1\r\n\r\n1 2\r\n\r\n3 4 \r\n\n");
  EXPECT_EQ(IO::read_height_field(temp("crlf.asc")).values, (std::vector<double>{1, 2, 3, 4}));
}

// The numbers strtod() reads and std::from_chars() alone does not: a plus
// sign, and a value too small for a double (zero, as strtod() makes it).
TEST(HeightField, AsciiGridNumbersAsStrtodReadsThem)
{
  write_file(temp("numbers.asc"), "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                                   "+1.5 -2e3 .25\n1e-400 +0 7.\n");
  EXPECT_EQ(IO::read_height_field(temp("numbers.asc")).values, (std::vector<double>{1.5, -2000, 0.25, 0, 0, 7}));
}

TEST(HeightField, BadFiles)
{
  auto read = [](const std::string& f) { IO::read_height_field(f); };
  expect_failure(read, temp("missing.png"), "cannot open");
  expect_failure(read, temp("missing.asc"), "cannot open");
  expect_failure(read, ::testing::TempDir(), "is a directory");
  IO::write_height_field(temp("good.png"), ramp_field(40, 40));
  write_file(temp("png.asc"), read_file(temp("good.png")));
  expect_failure(read, temp("png.asc"), "not an ESRI ASCII grid");
  const std::string png = read_file(temp("good.png"));
  write_file(temp("truncated.png"), png.substr(0, png.size() / 2));
  expect_failure(read, temp("truncated.png"), "corrupt");
  IO::write_height_field(temp("good.pgm"), ramp_field(40, 40));
  const std::string pgm = read_file(temp("good.pgm"));
  write_file(temp("truncated.pgm"), pgm.substr(0, pgm.size() - 7));
  expect_failure(read, temp("truncated.pgm"), "truncated");
  std::string wide = png;  // the IHDR width, bytes 16 to 19: 2^24 (stb_image's largest)
  wide[16] = '\x01'; wide[17] = wide[18] = wide[19] = '\0';
  write_file(temp("huge.png"), wide);
  expect_failure(read, temp("huge.png"), "absurd dimensions 16777216 x 40");
  const unsigned char rgb[6] = {1, 2, 3, 4, 5, 6};
  ASSERT_TRUE(stbi_write_png(temp("colour.png").c_str(), 2, 1, 3, rgb, 6));
  expect_failure(read, temp("colour.png"), "colour channels");

  // files given by their content: name, content, the problem the message names
  const char* header = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n";
  const std::vector<std::array<std::string, 3>> files = {
    {"empty.png", "", "empty file"},
    {"empty.asc", "", "empty file"},
    {"text.png", "this is not an image\n", "cannot read as an image"},
    {"header.pgm", "P5\n40", "PNM header"},
    {"huge.pgm", "P5\n1000000 1000000\n65535\n\x01\x02", "absurd dimensions 1000000 x 1000000"},
    {"zero.pgm", "P5\n0 5\n255\n", "absurd dimensions 0 x 5"},
    {"huge.asc", "ncols 100000000\nnrows 100000000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n", "absurd dimensions"},
    {"short.asc", std::string(header) + "cellsize 1\n1 2 3\n", "truncated: 1 of 2 rows"},
    {"long.asc", std::string(header) + "cellsize 1\n1 2 3 4 5\n6\n", "line 6: more values than ncols (3)"},
    {"row.asc", std::string(header) + "cellsize 1\n1 2 3\n4 5\n", "line 7: 2 values where ncols is 3"},
    {"rows.asc", std::string(header) + "cellsize 1\n1 2 3\n4 5 6\n\n7 8 9\n", "line 9: more rows than nrows (2)"},
    {"word.asc", std::string(header) + "cellsize 1\n1 2 x\n4 5 6\n", "line 6: value 3 is not a number"},
    {"sign.asc", std::string(header) + "cellsize 1\n1 2 3\n4 5 +-6\n", "line 7: value 3 is not a number"},
    {"huge_value.asc", std::string(header) + "cellsize 1\n1 2 1e400\n4 5 6\n", "line 6: value 3 is not finite"},
    {"nan.asc", std::string(header) + "cellsize 1\n1 2 3\nnan 5 6\n", "line 7: value 1 is not finite"},
    {"extent.asc", std::string(header) + "cellsize 1e308\n1 2 3\n4 5 6\n", "extent"},
    {"cell.asc", std::string(header) + "cellsize -1\n1 2 3 4 5 6\n", "cellsize must be positive"},
    {"corner.asc", "ncols 3\nnrows 2\ncellsize 1\n1 2 3 4 5 6\n", "xllcorner"},
    {"void.asc", "ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\nnodata_value -1\n-1 -1\n", "every cell is NODATA"}};
  for(const auto& f : files) {
    write_file(temp(f[0]), f[1]);
    expect_failure(read, temp(f[0]), f[2]);
  }

  expect_failure([](const std::string& f) { IO::write_height_field(f, ramp_field(2, 2)); },
                 temp("field.tif"), "unknown height field format");
  expect_failure([](const std::string& f) { IO::write_height_field(f, ramp_field(2, 2)); },
                 temp("no/such/dir/field.png"), "cannot write");
}

// ---------------------------------------------------------------- images

TEST(Image, EightBitPngAndJpg)
{
  const unsigned char rgb[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
  ASSERT_TRUE(stbi_write_png(temp("rgb.png").c_str(), 2, 2, 3, rgb, 6));
  const IO::Rgb_image img = IO::read_rgb_image(temp("rgb.png"));
  ASSERT_EQ(img.width, 2u);
  ASSERT_EQ(img.height, 2u);
  EXPECT_FALSE(img.high_dynamic_range);
  for(int k = 0; k < 12; ++k) EXPECT_FLOAT_EQ(img.values[std::size_t(k)], rgb[k] / 255.f);
  const IO::Luminance_image lum = IO::read_luminance_image(temp("rgb.png"));
  EXPECT_NEAR(lum.values[1], 0.7152, 1e-9);  // the green pixel, Rec. 709 weights

  std::vector<unsigned char> grey(16 * 16, 200);
  ASSERT_TRUE(stbi_write_jpg(temp("grey.jpg").c_str(), 16, 16, 1, grey.data(), 95));
  const IO::Rgb_image jpg = IO::read_rgb_image(temp("grey.jpg"));
  ASSERT_EQ(jpg.width, 16u);
  for(float v : jpg.values) EXPECT_NEAR(v, 200.f / 255.f, 2.f / 255.f);
  EXPECT_NEAR(IO::read_luminance_image(temp("grey.jpg")).values[0], 200. / 255., 2. / 255.);
}

TEST(Image, SixteenBitPnmAndGreyToRgb)
{
  // one 16-bit PPM pixel (1, 32768, 65535) and one 16-bit PGM pixel 257, big-endian
  write_file(temp("rgb16.ppm"), std::string("P6\n1 1\n65535\n\x00\x01\x80\x00\xff\xff", 19));
  const IO::Rgb_image ppm = IO::read_rgb_image(temp("rgb16.ppm"));
  EXPECT_FLOAT_EQ(ppm.values[0], 1.f / 65535.f);
  EXPECT_FLOAT_EQ(ppm.values[1], 32768.f / 65535.f);
  EXPECT_FLOAT_EQ(ppm.values[2], 1.f);
  write_file(temp("grey16.pgm"), std::string("P5 1 1 65535\n\x01\x01", 15));
  const IO::Rgb_image pgm = IO::read_rgb_image(temp("grey16.pgm"));
  for(float v : pgm.values) EXPECT_FLOAT_EQ(v, 257.f / 65535.f);
  IO::write_PNG_16(temp("grey16.png"), ramp_field(3, 2));
  const IO::Rgb_image png = IO::read_rgb_image(temp("grey16.png"));
  EXPECT_FLOAT_EQ(png.values[3 * 2], 2000.f / 65535.f);
  EXPECT_NEAR(IO::read_luminance_image(temp("grey16.png")).values[2], 2000. / 65535., 1e-7);  // float channels
}

TEST(Image, RadianceHdr)
{
  const float rgb[3 * 3] = {0.5f, 1.f, 2.f, 100.f, 200.f, 300.f, 0.f, 0.f, 0.f};
  ASSERT_TRUE(stbi_write_hdr(temp("light.hdr").c_str(), 3, 1, 3, rgb));
  const IO::Rgb_image img = IO::read_rgb_image(temp("light.hdr"));
  EXPECT_TRUE(img.high_dynamic_range);
  for(int k = 0; k < 9; ++k) EXPECT_NEAR(img.values[std::size_t(k)], rgb[k], 0.01 * rgb[k]);  // RGBE: 8-bit mantissas
  const IO::Luminance_image lum = IO::read_luminance_image(temp("light.hdr"));
  EXPECT_TRUE(lum.high_dynamic_range);
  EXPECT_NEAR(lum.values[1], 0.2126 * 100 + 0.7152 * 200 + 0.0722 * 300, 2.);
}

// Run-length encoded scanlines (8 to 32767 pixels wide) are read as stb_image reads them.
TEST(Image, RadianceHdrRunLengthEncoded)
{
  std::vector<float> rgb(3 * 64 * 5);
  for(std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = k % 7 == 0 ? 0.f : float(k % 13) * (k % 3 == 0 ? 40.f : 0.01f);
  ASSERT_TRUE(stbi_write_hdr(temp("rle.hdr").c_str(), 64, 5, 3, rgb.data()));
  const std::string bytes = read_file(temp("rle.hdr"));
  int w = 0, h = 0, c = 0;
  float* expected = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()),
                                           &w, &h, &c, 3);
  ASSERT_TRUE(expected);
  const IO::Rgb_image img = IO::read_rgb_image(temp("rle.hdr"));
  ASSERT_EQ(img.values.size(), rgb.size());
  EXPECT_EQ(img.values, std::vector<float>(expected, expected + rgb.size()));
  stbi_image_free(expected);
}

// The dimensions of the JPEG `bytes` (its first SOF0 segment) set to w x h.
std::string with_jpeg_size(std::string bytes, unsigned w, unsigned h)
{
  const std::size_t sof = bytes.find("\xff\xc0");
  bytes[sof + 5] = char(h >> 8); bytes[sof + 6] = char(h & 0xff);
  bytes[sof + 7] = char(w >> 8); bytes[sof + 8] = char(w & 0xff);
  return bytes;
}

// Headers that claim more pixels than the file holds are refused before
// stb_image allocates them, and files cut short are refused, not decoded.
TEST(Image, TruncatedFilesAndLyingHeaders)
{
  auto read = [](const std::string& f) { IO::read_rgb_image(f); };
  std::vector<unsigned char> noise(64 * 64 * 3);
  for(std::size_t k = 0; k < noise.size(); ++k) noise[k] = (unsigned char)(k * 7919 % 251);
  ASSERT_TRUE(stbi_write_jpg(temp("noise.jpg").c_str(), 64, 64, 3, noise.data(), 90));
  const std::string jpg = read_file(temp("noise.jpg"));
  write_file(temp("cut.jpg"), jpg.substr(0, jpg.size() / 2));
  expect_failure(read, temp("cut.jpg"), "run past the end of the file");
  write_file(temp("16384.jpg"), with_jpeg_size(jpg, 16384, 16384));
  expect_failure(read, temp("16384.jpg"), "absurd dimensions 16384 x 16384");
  write_file(temp("8192.jpg"), with_jpeg_size(jpg, 8192, 8192));
  expect_failure(read, temp("8192.jpg"), "cannot hold its 8192 x 8192 pixels");
  ASSERT_TRUE(stbi_write_png(temp("noise.png").c_str(), 64, 64, 3, noise.data(), 64 * 3));
  std::string png = read_file(temp("noise.png")).substr(0, 57);  // the IHDR, bytes 16 to 23: width, height
  png[16] = png[17] = png[20] = png[21] = '\0'; png[18] = png[22] = '\x1f'; png[19] = png[23] = '\x40';
  write_file(temp("8000.png"), png);
  expect_failure(read, temp("8000.png"), "cannot hold its 8000 x 8000 pixels");
  // an IDAT chunk that claims 822 MB, which stb_image allocated before reading it (found by fuzz/read_image)
  const std::string idat = read_file(temp("noise.png"));
  write_file(temp("idat.png"), idat.substr(0, 33) + std::string("\x31\x00\x39\x91IDAT", 8) + idat.substr(41));
  expect_failure(read, temp("idat.png"), "run past the end of the file");

  std::vector<float> rgb(3 * 64 * 8, 0.25f);
  ASSERT_TRUE(stbi_write_hdr(temp("rle.hdr").c_str(), 64, 8, 3, rgb.data()));
  const std::string rle = read_file(temp("rle.hdr"));
  write_file(temp("cut_rle.hdr"), rle.substr(0, rle.size() - 20));
  expect_failure(read, temp("cut_rle.hdr"), "truncated: 6 of 8 scanlines");
  ASSERT_TRUE(stbi_write_hdr(temp("flat.hdr").c_str(), 4, 2, 3, rgb.data()));
  const std::string flat = read_file(temp("flat.hdr"));
  write_file(temp("cut_flat.hdr"), flat.substr(0, flat.size() - 1));
  expect_failure(read, temp("cut_flat.hdr"), "truncated: 1 of 2 scanlines");
  write_file(temp("no_pixels.hdr"), flat.substr(0, flat.size() - 32));
  expect_failure(read, temp("no_pixels.hdr"), "truncated: 0 of 2 scanlines");
  write_file(temp("16384.hdr"), "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 16384\n\x02\x02\x40");
  expect_failure(read, temp("16384.hdr"), "absurd dimensions 16384 x 16384");
  write_file(temp("8000.hdr"), "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8000 +X 8000\n\x02\x02\x1f\x40\x80");
  expect_failure(read, temp("8000.hdr"), "truncated: 0 of 8000 scanlines");
  write_file(temp("zero_run.hdr"), std::string("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\x00\x00", 28));
  expect_failure(read, temp("zero_run.hdr"), "corrupt Radiance HDR run");
  write_file(temp("xyz.hdr"), "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x01\x01\x01\x80");
  expect_failure(read, temp("xyz.hdr"), "unsupported FORMAT=32-bit_rle_xyze");
  expect_failure(read, ::testing::TempDir(), "is a directory");
}

TEST(Image, BadFiles)
{
  auto read = [](const std::string& f) { IO::read_rgb_image(f); };
  auto read_luminance = [](const std::string& f) { IO::read_luminance_image(f); };
  expect_failure(read, temp("missing.jpg"), "cannot open");
  expect_failure(read_luminance, temp("missing.jpg"), "cannot open");
  write_file(temp("empty.jpg"), "");
  expect_failure(read, temp("empty.jpg"), "empty file");
  expect_failure(read_luminance, temp("empty.jpg"), "empty file");
  write_file(temp("text.hdr"), "#?RADIANCE\nnot really\n");
  expect_failure(read, temp("text.hdr"), "cannot read as an image");
  std::vector<unsigned char> noise(64 * 64 * 3);
  for(std::size_t k = 0; k < noise.size(); ++k) noise[k] = (unsigned char)(k * 7919 % 251);
  ASSERT_TRUE(stbi_write_png(temp("noise.png").c_str(), 64, 64, 3, noise.data(), 64 * 3));
  const std::string png = read_file(temp("noise.png"));
  write_file(temp("truncated.png"), png.substr(0, png.size() / 2));
  expect_failure(read, temp("truncated.png"), "corrupt");
  expect_failure(read_luminance, temp("truncated.png"), "corrupt");
  write_file(temp("truncated.ppm"), std::string("P6\n4 4\n255\n\x01\x02\x03", 14));
  expect_failure(read, temp("truncated.ppm"), "truncated: 3 bytes of pixels, 48 expected");
  write_file(temp("huge.ppm"), "P6\n70000 70000\n255\n\x01");
  expect_failure(read, temp("huge.ppm"), "absurd dimensions 70000 x 70000");
  expect_failure([](const std::string& f) { IO::read_rgb_image(f, 100); }, temp("noise.png"), "absurd dimensions 64 x 64");
  expect_failure([](const std::string& f) { IO::read_luminance_image(f, 100); }, temp("noise.png"), "absurd dimensions");
}

// PNM samples above the maxval would be brighter than white.
TEST(Image, PnmSamplesWithinTheirMaxval)
{
  auto read = [](const std::string& f) { IO::read_rgb_image(f); };
  write_file(temp("maxval1.pgm"), std::string("P5 2 1 1\n\x00\xff", 11));
  expect_failure(read, temp("maxval1.pgm"), "sample 1 is 255, more than the maxval 1");
  write_file(temp("maxval256.pgm"), std::string("P5 1 1 256\n\xff\xff", 13));
  expect_failure([](const std::string& f) { IO::read_height_field(f); }, temp("maxval256.pgm"),
                 "sample 0 is 65535, more than the maxval 256");
  write_file(temp("bits.pgm"), std::string("P5 2 1 1\n\x00\x01", 11));
  const IO::Rgb_image bits = IO::read_rgb_image(temp("bits.pgm"));
  EXPECT_EQ(bits.values, std::vector<float>({0.f, 0.f, 0.f, 1.f, 1.f, 1.f}));
}

// Old-style run-length pixels (1, 1, 1, n) repeat the pixel before n times,
// n << 8 times when they follow one another, as Radiance reads them.
TEST(Image, RadianceHdrOldStyleRuns)
{
  auto pixel = [](unsigned char r, unsigned char g, unsigned char b, unsigned char e) {
    return std::string{char(r), char(g), char(b), char(e)};
  };
  const std::string p = pixel(128, 64, 32, 129), q = pixel(200, 100, 50, 130), run3 = pixel(1, 1, 1, 3);
  // 4 x 2, flat: p and a run of 3; q, p and a run of 2
  write_file(temp("old.hdr"), "#?RADIANCE\n\n-Y 2 +X 4\n" + p + run3 + q + p + pixel(1, 1, 1, 2));
  const IO::Rgb_image img = IO::read_rgb_image(temp("old.hdr"));
  auto value = [](const std::string& rgbe, int c) { return float(std::ldexp((unsigned char)rgbe[c], (unsigned char)rgbe[3] - 136)); };
  const std::string expected[8] = {p, p, p, p, q, p, p, p};
  for(int i = 0; i < 8; ++i)
    for(int c = 0; c < 3; ++c) EXPECT_EQ(img.values[std::size_t(3 * i + c)], value(expected[i], c)) << i;
  // 2 + (1 << 8) copies: 259 pixels
  write_file(temp("long.hdr"), "#?RADIANCE\n\n-Y 1 +X 259\n" + q + pixel(1, 1, 1, 2) + pixel(1, 1, 1, 1));
  const IO::Rgb_image long_run = IO::read_rgb_image(temp("long.hdr"));
  ASSERT_EQ(long_run.width, 259u);
  EXPECT_EQ(long_run.values[3 * 258], value(q, 0));
  auto read = [](const std::string& f) { IO::read_rgb_image(f); };
  write_file(temp("first.hdr"), "#?RADIANCE\n\n-Y 1 +X 2\n" + run3 + p);
  expect_failure(read, temp("first.hdr"), "corrupt Radiance HDR old-style run");
  write_file(temp("past.hdr"), "#?RADIANCE\n\n-Y 1 +X 2\n" + p + run3);
  expect_failure(read, temp("past.hdr"), "corrupt Radiance HDR old-style run");
}

// A header echoed in a message has its control bytes escaped: the message
// is one line and leaves the terminal's colours alone.
TEST(Image, EchoedHeadersArePrintable)
{
  auto read = [](const std::string& f) { IO::read_rgb_image(f); };
  write_file(temp("esc.hdr"), "#?RADIANCE\nFORMAT=\x1b[31mred\x0c\n\n-Y 1 +X 1\n\x01\x01\x01\x80");
  expect_failure(read, temp("esc.hdr"), "unsupported FORMAT=\\x1b[31mred\\x0c");
  write_file(temp("cr.hdr"), "#?RADIANCE\n\n-Y 1 +X 1\r\n\x01\x01\x01\x80");
  expect_failure(read, temp("cr.hdr"), "unsupported resolution line '-Y 1 +X 1\\x0d'");
}

// Devices and pipes never end, and a file may hold more than its header's
// dimensions can take: the readers stop at what the header allows.
TEST(Image, ReadsBoundedByTheHeader)
{
  expect_failure([](const std::string& f) { IO::read_rgb_image(f); }, "/dev/zero", "cannot read as an image");
  expect_failure([](const std::string& f) { IO::read_height_field(f); }, "/dev/zero", "cannot read as an image");
  EXPECT_THROW(IO::read_height_field("/dev/urandom"), std::runtime_error);
  std::string grid = "ncols 12\nnrows 10\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
  const std::size_t header = grid.size();
  while(grid.size() < (1 << 20)) grid += "1 2 3 4 5 6 7 8 9 10 11 12\n";
  write_file(temp("long.asc"), grid);
  expect_failure([](const std::string& f) { IO::read_height_field(f); }, temp("long.asc"),
                 "more than the " + std::to_string(header + 64 * 120) + " bytes that its 12 x 10 cells");
  // a PNM file may hold more images: the first is read, the rest ignored
  write_file(temp("more.pgm"), "P5 4 4 255\n" + std::string(16, '\x07') + std::string(1 << 17, '\x01'));
  const IO::Height_field first = IO::read_height_field(temp("more.pgm"));
  EXPECT_EQ(first.values, std::vector<double>(16, 7.));
}

// ---------------------------------------------------------------- meshes

typedef std::array<std::size_t, 3> Face;

// Re-reads a mesh file with CGAL's reader of its format.
template <class Point_3>
bool read_mesh(const std::string& file, std::vector<Point_3>& points, std::vector<std::vector<std::size_t>>& faces)
{
  const std::string e = file.substr(file.size() - 3);
  if(e == "off") return CGAL::IO::read_OFF(file, points, faces);
  if(e == "ply") return CGAL::IO::read_PLY(file, points, faces);
  return CGAL::IO::read_OBJ(file, points, faces);
}

// Writes t in each format with its vertices reversed, re-reads it and checks
// the order of the vertices, their coordinates, the faces (as vertex sets)
// and their orientation.
template <class Triangulation, class Z>
void check_mesh_files(const Triangulation& t, Z z)
{
  std::vector<typename Triangulation::Vertex_handle> order;
  for(auto v : t.finite_vertex_handles()) order.insert(order.begin(), v);
  std::set<std::array<double, 6>> expected;  // each face by its corners' x and y, sorted
  auto key = [](std::array<std::array<double, 2>, 3> c) {
    std::sort(c.begin(), c.end());
    return std::array<double, 6>{c[0][0], c[0][1], c[1][0], c[1][1], c[2][0], c[2][1]};
  };
  for(auto f : t.finite_face_handles())
    expected.insert(key({{{f->vertex(0)->point().x(), f->vertex(0)->point().y()},
                          {f->vertex(1)->point().x(), f->vertex(1)->point().y()},
                          {f->vertex(2)->point().x(), f->vertex(2)->point().y()}}}));
  for(const char* ext : {"off", "ply", "obj"}) {
    const std::string file = temp(std::string("mesh.") + ext);
    IO::write_triangulation(file, t, order);
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t>> faces;
    ASSERT_TRUE(read_mesh(file, points, faces)) << file;
    ASSERT_EQ(points.size(), t.number_of_vertices()) << file;
    ASSERT_EQ(faces.size(), t.number_of_faces()) << file;
    for(std::size_t k = 0; k < points.size(); ++k) {
      EXPECT_EQ(points[k].x(), order[k]->point().x()) << file;
      EXPECT_EQ(points[k].y(), order[k]->point().y()) << file;
      EXPECT_EQ(points[k].z(), z(order[k]->point())) << file;
    }
    std::set<std::array<double, 6>> got;
    for(const auto& f : faces) {
      ASSERT_EQ(f.size(), 3u);
      const K::Point_3 &a = points[f[0]], &b = points[f[1]], &c = points[f[2]];
      EXPECT_EQ(CGAL::orientation(K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y()), K::Point_2(c.x(), c.y())),
                CGAL::LEFT_TURN) << file;
      got.insert(key({{{a.x(), a.y()}, {b.x(), b.y()}, {c.x(), c.y()}}}));
    }
    EXPECT_EQ(got, expected) << file;
  }
}

CGAL::Penrose_importance_sampler<K> radial_sampler(std::size_t n)
{
  return CGAL::Penrose_importance_sampler<K>(K::Iso_rectangle_2(0, 0, 1, 1),
    [](const K::Point_2& p) { return std::exp(-8 * ((p.x() - 0.5) * (p.x() - 0.5) + (p.y() - 0.5) * (p.y() - 0.5))); },
    CGAL::parameters::number_of_output_points(n));
}

TEST(Mesh, PlanarTriangulationInEachFormat)
{
  const CGAL::Penrose_Delaunay_triangulation_2<K> t(radial_sampler(2000));
  ASSERT_GT(t.number_of_vertices(), 1500u);
  check_mesh_files(t, [](const K::Point_2&) { return 0.; });
}

TEST(Mesh, TerrainKeepsItsHeights)
{
  typedef CGAL::Projection_traits_xy_3<K> Gt;
  auto height = [](double x, double y) { return 100. * std::sin(3 * x) * std::cos(2 * y); };
  const CGAL::Penrose_Delaunay_triangulation_2<Gt> t(radial_sampler(1000), [&](double x, double y) {
    return K::Point_3(x, y, height(x, y));
  });
  check_mesh_files(t, [&](const K::Point_3& p) { return height(p.x(), p.y()); });
}

TEST(Mesh, WriterFailures)
{
  const CGAL::Penrose_Delaunay_triangulation_2<K> t(radial_sampler(100));
  auto write = [&](const std::string& f) { IO::write_triangulation(f, t); };
  expect_failure(write, temp("mesh.stl"), "unknown mesh format");
  expect_failure(write, temp("no/such/dir/mesh.off"), "cannot write");
  std::vector<CGAL::Penrose_Delaunay_triangulation_2<K>::Vertex_handle> some;
  some.push_back(t.finite_vertices_begin());
  expect_failure([&](const std::string& f) { IO::write_triangulation(f, t, some); }, temp("partial.off"),
                 "not listed");
}

// The files beside `file` whose names start with '.' + its name: the temporary ones.
std::vector<std::string> temporaries_of(const std::string& file)
{
  namespace fs = std::filesystem;
  const std::string prefix = "." + fs::path(file).filename().string() + ".";
  std::vector<std::string> found;
  for(const auto& entry : fs::directory_iterator(fs::path(file).parent_path()))
    if(entry.path().filename().string().rfind(prefix, 0) == 0) found.push_back(entry.path().string());
  return found;
}

// A file is replaced only by a complete one: until commit(), the old file
// stays; an Output_file destroyed without commit() (an exception while
// writing) leaves no temporary file behind.
TEST(Output, ReplacedOnlyWhenComplete)
{
  const std::string file = temp("out.txt");
  write_file(file, "old\n");
  {
    IO::internal::Output_file out(file);
    out.write("new, half");
    EXPECT_EQ(read_file(file), "old\n");
    EXPECT_EQ(temporaries_of(file).size(), 1u);
  }
  EXPECT_EQ(read_file(file), "old\n");
  EXPECT_TRUE(temporaries_of(file).empty());
  IO::internal::Output_file out(file);
  out.write("new\n");
  std::fprintf(out.stream(), "%d\n", 42);
  out.commit();
  EXPECT_EQ(read_file(file), "new\n42\n");
  EXPECT_TRUE(temporaries_of(file).empty());
}

// Through a symbolic link, the file linked to is replaced and the link
// kept; the permissions of the file replaced are kept.
TEST(Output, LinksFollowedAndPermissionsKept)
{
  namespace fs = std::filesystem;
  const std::string target = temp("target.txt"), link = temp("link.txt");
  write_file(target, "old\n");
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
  fs::remove(link);
  fs::create_symlink(target, link);
  IO::internal::write_bytes(link, "new\n");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_file(target), "new\n");
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  // a file that its permissions protect is not replaced (a rename could)
  fs::permissions(target, fs::perms::owner_read);
  expect_failure([](const std::string& f) { IO::internal::write_bytes(f, "newer\n"); }, target, "read-only");
  EXPECT_EQ(read_file(target), "new\n");
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
}

// A device is written in place (a rename cannot replace it), and a failed
// write names the file and its cause.
TEST(Output, DevicesWrittenInPlace)
{
  IO::internal::write_bytes("/dev/null", "nothing\n");
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  expect_failure([](const std::string& f) { IO::internal::write_bytes(f, std::string(1 << 16, 'x')); }, "/dev/full",
                 "cannot write (No space left on device)");
}

} // namespace
