// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every file that the package and its tools write goes through Output_file:
// the bytes go to a temporary file beside the target, which replaces the
// target by a rename only once it is complete and closed. A run that fails,
// or is killed, while writing leaves the previous file as it was, never half
// a file (a kill may leave the temporary file, a hidden name beside it).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_OUTPUT_FILE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_OUTPUT_FILE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <system_error>

namespace CGAL {
namespace IO {
namespace internal {

class Output_file
{
public:
  // Opens the temporary file. A symbolic link is followed: the file that it
  // names is replaced and the link kept. A device or a pipe (/dev/null,
  // /dev/stdout), which a rename cannot replace, is written in place.
  explicit Output_file(const std::string& file) : file_(file)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(file, error);
    if(fs::exists(status) && !fs::is_regular_file(status)) {
      stream_ = std::fopen(file.c_str(), "wb");
      if(!stream_) throw failure("cannot write");
      errno = 0;
      return;
    }
    // a rename would replace a file that its permissions protect from writing
    if(fs::exists(status) && (status.permissions() & (fs::perms::owner_write | fs::perms::group_write
                                                      | fs::perms::others_write)) == fs::perms::none)
      throw file_error(file, "cannot write (it is read-only)");
    target_ = fs::exists(status) ? fs::canonical(file, error) : fs::path(file);
    if(error) target_ = file;
    // "x": created here, never an existing file; "+": penrose_mesh's streamed
    // PLY reads its faces back from a second one. The name is cut to stay within NAME_MAX
    const std::string name = "." + target_.filename().string().substr(0, 200) + ".";
    std::random_device random;
    for(int attempt = 0; attempt < 64 && !stream_; ++attempt) {
      temporary_ = target_.parent_path() / (name + std::to_string(random()) + ".tmp");
      stream_ = std::fopen(temporary_.string().c_str(), "w+bx");
      if(!stream_ && errno != EEXIST) break;
    }
    if(!stream_) {
      temporary_.clear();
      throw failure("cannot write a temporary file beside it");
    }
    if(fs::exists(status)) fs::permissions(temporary_, status.permissions(), error);  // those of the file replaced
    errno = 0;  // so that a failed write reports its own cause
  }

  Output_file(const Output_file&) = delete;
  Output_file& operator=(const Output_file&) = delete;

  ~Output_file()
  {
    if(stream_) std::fclose(stream_);
    std::error_code error;
    if(!temporary_.empty()) std::filesystem::remove(temporary_, error);
  }

  void write(const char* bytes, std::size_t n)
  {
    if(n && std::fwrite(bytes, 1, n, stream_) != n) throw failure("cannot write");
  }

  void write(const std::string& bytes) { write(bytes.data(), bytes.size()); }

  // For fprintf(); commit() checks what it wrote.
  std::FILE* stream() { return stream_; }

  // Closes the file, checking every write, and renames it over the target.
  void commit()
  {
    const bool failed = std::ferror(stream_) != 0;
    const bool closed = std::fclose(stream_) == 0;
    stream_ = nullptr;
    if(failed || !closed) throw failure("cannot write");
    if(temporary_.empty()) return;
    std::error_code error;
    std::filesystem::rename(temporary_, target_, error);
    if(error) throw file_error(file_, "cannot replace it (" + error.message() + ")");
    temporary_.clear();
  }

private:
  std::runtime_error failure(const std::string& what) const
  {
    return file_error(file_, what + (errno ? std::string(" (") + std::strerror(errno) + ")" : std::string()));
  }

  std::string file_;
  std::filesystem::path target_, temporary_;
  std::FILE* stream_ = nullptr;
};

// Writes `bytes` to `file` through an Output_file.
inline void write_bytes(const std::string& file, const std::string& bytes)
{
  Output_file out(file);
  out.write(bytes);
  out.commit();
}

} // namespace internal
} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_OUTPUT_FILE_H
