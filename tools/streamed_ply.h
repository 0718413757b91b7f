// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangulation of a sampler's points written window by window into one
// binary little-endian PLY, for constructions larger than memory: each
// window of a grid is triangulated alone (Penrose_Delaunay_window_2), in
// parallel where TBB is linked, and written in the grid's order, so that
// memory holds the windows in flight, not the mesh.
//
// A window's samples are numbered after those of the windows before it, by
// key. Most of its triangles have all their vertices in it, or in windows
// already written (the one to the left, the row below), whose numbers come
// from their keys; a triangle with a vertex in a window not yet written
// waits for that window, and so do the border's triangles
// (Penrose_Delaunay_border_2), computed first. The keys of the last row of
// windows are kept; an older window's keys, if ever needed (a margin grown
// over a hole), are sampled again: the sampler is deterministic.
//
// The vertices go to the file as they are numbered and the faces to a
// second file beside it, appended at the end; the counts, unknown until
// then, are written into the header's fixed-width fields, and the file is
// renamed over the target only when it is complete (both files are
// CGAL::IO::internal::Output_file's temporary files; that of the faces is
// never committed, and goes).

#ifndef PENROSE_TOOLS_STREAMED_PLY_H
#define PENROSE_TOOLS_STREAMED_PLY_H

#include <CGAL/Penrose_Delaunay_border_2.h>
#include <CGAL/Penrose_Delaunay_window_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the streamed PLY is written from the machine's words: little-endian machines only"
#endif

namespace penrose_tools {

struct Streamed_mesh
{
  std::uint64_t vertices = 0, faces = 0;
  std::size_t windows = 0;
};

template <class K>
class Streamed_ply_writer
{
  typedef CGAL::Penrose_importance_sampler<K> Sampler;
  typedef CGAL::Penrose_Delaunay_window_2<K> Window;
  typedef std::uint64_t Key;
  typedef std::array<Key, 3> Triangle;

public:
  // About 2^18 points a window by default: its mesh stays in the caches'
  // reach, and the margin adds under 2% of points.
  static constexpr double default_points_per_window = 262144.;

  explicit Streamed_ply_writer(const Sampler& sampler, double points_per_window = default_points_per_window)
    : s_(sampler)
  {
    const auto& r = s_.region();
    x0_ = CGAL::to_double(r.xmin()); y0_ = CGAL::to_double(r.ymin());
    x1_ = CGAL::to_double(r.xmax()); y1_ = CGAL::to_double(r.ymax());
    const double windows = (std::max)(1., s_.expected_number_of_points() / points_per_window);
    const double side = std::sqrt((x1_ - x0_) * (y1_ - y0_) / windows);
    kx_ = std::size_t((std::max)(1., std::round((x1_ - x0_) / side)));
    ky_ = std::size_t((std::max)(1., std::round((y1_ - y0_) / side)));
    for(std::size_t i = 0; i <= kx_; ++i) cx_.push_back(i == kx_ ? x1_ : x0_ + (x1_ - x0_) * double(i) / double(kx_));
    for(std::size_t j = 0; j <= ky_; ++j) cy_.push_back(j == ky_ ? y1_ : y0_ + (y1_ - y0_) * double(j) / double(ky_));
    // a uint index while the count, with a generous margin, fits in 32 bits
    wide_ = s_.expected_number_of_points() * 1.2 + 1e6 > 4294967295.;
  }

  std::size_t number_of_windows() const { return kx_ * ky_; }

  // The bytes the file will take, about.
  double expected_bytes() const
  {
    return s_.expected_number_of_points() * (16. + 2. * double(face_bytes())) + 4096.;
  }

  // Writes the PLY to `path`; `progress(f)` is called from the calling
  // thread with the share f of the windows written.
  Streamed_mesh write(const std::string& path, const std::function<void(double)>& progress)
  {
    check_free_space(path);
    CGAL::IO::internal::Output_file vertices(path), faces(path);
    vertices_ = vertices.stream();
    faces_ = faces.stream();
    for(std::FILE* f : {vertices_, faces_}) std::setvbuf(f, nullptr, _IOFBF, std::size_t(1) << 20);
    write_header();
    const CGAL::Penrose_Delaunay_border_2<K> border(s_);
    wait_for_owners(border.triangles(), border.vertices());
    offsets_.assign(number_of_windows() + 1, 0);
    for_each_window_in_order([&](std::size_t id, const Window& w) {
      write_window(id, w);
      if(progress) progress(double(id + 1) / double(number_of_windows()));
    });
    if(!pending_.empty()) throw std::logic_error("streamed PLY: triangles left waiting for a window");
    finish(vertices_, faces_);
    vertices.commit();
    return {next_vertex_, faces_written_, number_of_windows()};
  }

private:
  // A face's record: its count of vertices, then three indices.
  std::size_t face_bytes() const { return 1 + 3 * (wide_ ? 8 : 4); }

  void check_free_space(const std::string& path) const
  {
    const std::size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    struct statvfs fs;
    if(statvfs(folder.c_str(), &fs) != 0) return;  // the writes will say
    const double available = double(fs.f_bavail) * double(fs.f_frsize);
    // the faces are written beside the vertices, then appended: they take their room twice for a while
    const double needed = 1.05 * (expected_bytes() + s_.expected_number_of_points() * 2. * double(face_bytes()));
    if(needed > available) {
      char msg[160];
      std::snprintf(msg, sizeof msg, ": about %.3g GB needed while it is written, %.3g GB free there", needed / 1e9,
                    available / 1e9);
      throw std::runtime_error(path + msg);
    }
  }

  static constexpr int count_width = 20;

  void write_header()
  {
    std::string h = header(0, 0);
    put(vertices_, h.data(), h.size());
    header_size_ = h.size();
  }

  std::string header(std::uint64_t vertices, std::uint64_t faces) const
  {
    char v[32], f[32];
    std::snprintf(v, sizeof v, "%*llu", count_width, static_cast<unsigned long long>(vertices));
    std::snprintf(f, sizeof f, "%*llu", count_width, static_cast<unsigned long long>(faces));
    return std::string("ply\nformat binary_little_endian 1.0\ncomment Delaunay triangulation written window by window by penrose_mesh\n")
           + "element vertex " + v + "\nproperty double x\nproperty double y\n"
           + "element face " + f + "\nproperty list uchar " + (wide_ ? "uint64" : "uint") + " vertex_indices\nend_header\n";
  }

  static void put(std::FILE* file, const void* data, std::size_t size)
  {
    if(size && std::fwrite(data, 1, size, file) != size)
      throw std::runtime_error(std::string("cannot write the mesh: ") + std::strerror(errno));
  }

  std::size_t owner_along(const std::vector<double>& cuts, double v) const
  {
    const std::size_t i = std::size_t(std::upper_bound(cuts.begin(), cuts.end(), v) - cuts.begin());
    return std::min<std::size_t>(i == 0 ? 0 : i - 1, cuts.size() - 2);
  }

  template <class Point>
  std::size_t owner(const Point& p) const
  {
    return owner_along(cy_, CGAL::to_double(p.y())) * kx_ + owner_along(cx_, CGAL::to_double(p.x()));
  }

  typename K::Iso_rectangle_2 rectangle(std::size_t id) const
  {
    const std::size_t i = id % kx_, j = id / kx_;
    return typename K::Iso_rectangle_2(cx_[i], cy_[j], cx_[i + 1], cy_[j + 1]);
  }

  // Computes the windows, in parallel where TBB is linked, and hands them
  // to `write` one after the other, in order: a batch of windows, four a
  // thread, is computed in TBB's tasks while the calling thread writes the
  // batch before it (fewer make the threads wait at each batch's end).
  template <class Write>
  void for_each_window_in_order(const Write& write)
  {
    using CGAL::internal::Penrose::for_each_block;
    using CGAL::internal::Penrose::run_beside;
#ifdef CGAL_LINKED_WITH_TBB
    typedef CGAL::Parallel_tag Tag;
    const std::size_t batch = 4 * std::size_t(tbb::this_task_arena::max_concurrency());
#else
    typedef CGAL::Sequential_tag Tag;
    const std::size_t batch = 1;
#endif
    const std::size_t n = number_of_windows();
    auto make = [&](std::size_t first, std::vector<std::optional<Window>>& made) {
      made.clear();
      made.resize(first < n ? (std::min)(batch, n - first) : 0);
      for_each_block<Tag>(made.size(), 1, [&](std::size_t b, std::size_t e) {
        for(std::size_t k = b; k < e; ++k) made[k].emplace(s_, rectangle(first + k));
      });
    };
    std::vector<std::optional<Window>> current, next;
    make(0, current);
    for(std::size_t first = 0; first < n; first += batch) {
      run_beside<Tag>([&] { make(first + batch, next); },
                      [&] { for(std::size_t k = 0; k < current.size(); ++k) write(first + k, *current[k]); });
      current.swap(next);
    }
  }

  // Notes which windows the vertices of `triangles` (positions in
  // `vertices`, by key) lie in; each triangle waits for the last of them.
  template <class Triangles, class Vertices>
  void wait_for_owners(const Triangles& triangles, const Vertices& vertices)
  {
    std::unordered_map<Key, std::size_t> owner_of;
    for(const auto& [k, p] : vertices) owner_of.emplace(k, owner(p));
    for(const Triangle& t : triangles) {
      std::size_t last = 0;
      for(Key k : t) {
        const std::size_t o = owner_of.at(k);
        last = (std::max)(last, o);
        wanted_[o].push_back(k);
      }
      pending_[last].push_back(t);
    }
  }

  // The sorted keys of window `id`, from the row kept or sampled again.
  const std::vector<Key>& keys_of(std::size_t id)
  {
    auto it = recent_keys_.find(id);
    if(it != recent_keys_.end()) return it->second;
    std::vector<typename Sampler::Sample> samples;
    s_.samples(rectangle(id), std::back_inserter(samples));
    std::vector<Key> keys;
    for(const auto& sample : samples) keys.push_back(sample.key);
    std::sort(keys.begin(), keys.end());
    return recent_keys_[id] = std::move(keys);
  }

  std::uint64_t number_in(std::size_t id, Key k)
  {
    const std::vector<Key>& keys = keys_of(id);
    const auto it = std::lower_bound(keys.begin(), keys.end(), k);
    if(it == keys.end() || *it != k) throw std::logic_error("streamed PLY: a vertex is missing from its window");
    return offsets_[id] + std::uint64_t(it - keys.begin());
  }

  void write_window(std::size_t id, const Window& w)
  {
    const std::size_t n = w.points().size();
    offsets_[id] = next_vertex_;
    std::vector<double> xy;
    xy.reserve(2 * n);
    for(const auto& p : w.points()) { xy.push_back(CGAL::to_double(p.x())); xy.push_back(CGAL::to_double(p.y())); }
    put(vertices_, xy.data(), xy.size() * sizeof(double));
    next_vertex_ += n;
    recent_keys_[id] = w.keys();
    if(auto it = wanted_.find(id); it != wanted_.end()) {
      for(Key k : it->second) numbers_.emplace(k, number_in(id, k));
      wanted_.erase(it);
    }
    // the number of each of the window's vertices (its own, then the others):
    // known for those of windows written, awaited for the others
    constexpr std::uint64_t awaited = std::numeric_limits<std::uint64_t>::max();
    const auto& foreign = w.foreign_vertices();
    std::vector<std::uint64_t> number(n + foreign.size());
    std::vector<std::size_t> owner_of(foreign.size());
    for(std::size_t i = 0; i < n; ++i) number[i] = offsets_[id] + i;
    for(std::size_t j = 0; j < foreign.size(); ++j) {
      owner_of[j] = owner(foreign[j].second);
      number[n + j] = owner_of[j] < id ? number_in(owner_of[j], foreign[j].first) : awaited;
    }
    std::vector<unsigned char> records;
    records.reserve(w.triangles().size() * face_bytes());
    for(std::size_t t = 0; t < w.triangles().size(); ++t) {
      const auto& local = w.triangle_indices()[t];
      if(number[local[0]] != awaited && number[local[1]] != awaited && number[local[2]] != awaited) {
        encode_face({{number[local[0]], number[local[1]], number[local[2]]}}, records);
        continue;
      }
      std::size_t last = id;
      for(int i = 0; i < 3; ++i) {
        const Key k = w.triangles()[t][std::size_t(i)];
        if(number[local[i]] != awaited) numbers_.emplace(k, number[local[i]]);
        else {
          const std::size_t o = owner_of[local[i] - n];
          wanted_[o].push_back(k);
          last = (std::max)(last, o);
        }
      }
      pending_[last].push_back(w.triangles()[t]);
    }
    if(auto p = pending_.find(id); p != pending_.end()) {
      for(const Triangle& t : p->second) encode_face({{numbers_.at(t[0]), numbers_.at(t[1]), numbers_.at(t[2])}}, records);
      pending_.erase(p);
    }
    put(faces_, records.data(), records.size());
    // the row below the next window stays; older ones are sampled again if needed
    while(!recent_keys_.empty() && recent_keys_.begin()->first + kx_ + 1 < id) recent_keys_.erase(recent_keys_.begin());
  }

  void encode_face(const std::array<std::uint64_t, 3>& v, std::vector<unsigned char>& records)
  {
    records.push_back(3);
    for(std::uint64_t i : v) {
      if(!wide_ && i > 0xffffffffu) throw std::length_error("streamed PLY: more vertices than 32-bit indices hold");
      const std::uint32_t narrow = std::uint32_t(i);
      const unsigned char* bytes = wide_ ? reinterpret_cast<const unsigned char*>(&i)
                                         : reinterpret_cast<const unsigned char*>(&narrow);
      records.insert(records.end(), bytes, bytes + (wide_ ? 8 : 4));
    }
    ++faces_written_;
  }

  // Appends the faces to the vertices, in the kernel where it can, and
  // writes the counts into the header.
  void finish(std::FILE* vertices, std::FILE* faces)
  {
    if(std::fflush(faces) != 0 || std::fflush(vertices) != 0 || std::fseek(faces, 0, SEEK_SET) != 0)
      throw std::runtime_error(std::string("cannot write the mesh: ") + std::strerror(errno));
    bool copied = false;
#ifdef __linux__
    loff_t from = 0;
    for(ssize_t got; (got = copy_file_range(fileno(faces), &from, fileno(vertices), nullptr, std::size_t(1) << 30, 0)) != 0;) {
      if(got < 0) break;  // not on this file system: copied by hand from `from` on
      copied = true;
    }
    if(copied && std::fseek(vertices, 0, SEEK_END) != 0) throw std::runtime_error("cannot write the mesh");
    if(std::fseek(faces, long(from), SEEK_SET) != 0) throw std::runtime_error("cannot read the mesh's faces back");
#endif
    std::vector<char> buffer(std::size_t(1) << 22);
    for(std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), faces)) > 0;) put(vertices, buffer.data(), got);
    if(std::ferror(faces)) throw std::runtime_error("cannot read the mesh's faces back");
    const std::string h = header(next_vertex_, faces_written_);
    if(h.size() != header_size_ || std::fflush(vertices) != 0 || std::fseek(vertices, 0, SEEK_SET) != 0)
      throw std::runtime_error(std::string("cannot write the mesh: ") + std::strerror(errno));
    put(vertices, h.data(), h.size());
    if(std::fflush(vertices) != 0) throw std::runtime_error(std::string("cannot write the mesh: ") + std::strerror(errno));
  }

  const Sampler& s_;
  double x0_, y0_, x1_, y1_;
  std::size_t kx_, ky_;
  std::vector<double> cx_, cy_;
  bool wide_;
  std::FILE* vertices_ = nullptr;
  std::FILE* faces_ = nullptr;
  std::size_t header_size_ = 0;
  std::uint64_t next_vertex_ = 0, faces_written_ = 0;
  std::vector<std::uint64_t> offsets_;
  std::map<std::size_t, std::vector<Key>> recent_keys_;
  std::map<std::size_t, std::vector<Key>> wanted_;            // by window: keys whose numbers are awaited
  std::map<std::size_t, std::vector<Triangle>> pending_;      // by the last window a triangle waits for
  std::unordered_map<Key, std::uint64_t> numbers_;
};

} // namespace penrose_tools

#endif // PENROSE_TOOLS_STREAMED_PLY_H
