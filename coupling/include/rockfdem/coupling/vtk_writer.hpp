// ParaView output: one grid per .vtu file, a time series as a .pvd collection.
// Both are written atomically (temp file beside the target, then rename), so
// ParaView reloading during a run never reads a half-written file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rockfdem/coupling/vtk_grid.hpp"

namespace rockfdem::coupling {

/// Writes `grid` as VTK XML unstructured grid: appended raw binary data,
/// zlib-compressed, float64 coordinates and the arrays' own types.
/// @throws std::invalid_argument from grid.validate() (names the array);
///         std::runtime_error naming `path` when it cannot be written.
void write_vtu(const VtkGrid& grid, const std::string& path);

/// Writes `lines` as VTK XML poly data (.vtp), one VTK_POLY_LINE cell per
/// polyline, in the same encoding as write_vtu.
/// @throws std::invalid_argument from lines.validate(); std::runtime_error
///         naming `path` when it cannot be written.
void write_vtp(const VtkPolylines& lines, const std::string& path);

/// One step of a time series: simulated time and the .vtu file name,
/// relative to the .pvd's directory (ParaView resolves it that way).
struct PvdEntry {
  double time = 0.0;
  std::string file;
};

/// Writes a ParaView collection (.pvd) listing `entries` in the given order.
/// Times are written with 17 significant digits (exact round trip).
/// @throws std::invalid_argument for an empty or empty file name or a non-finite time;
///         std::runtime_error naming `path` when it cannot be written.
void write_pvd(const std::vector<PvdEntry>& entries, const std::string& path);

/// A time series being written: add() each step's file, then write() (after
/// every step, so the .pvd is always current if the run stops early).
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  void add(double time, std::string file) { entries_.push_back({time, std::move(file)}); }
  void write() const { write_pvd(entries_, path_); }
  const std::vector<PvdEntry>& entries() const { return entries_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<PvdEntry> entries_;
};

}  // namespace rockfdem::coupling
