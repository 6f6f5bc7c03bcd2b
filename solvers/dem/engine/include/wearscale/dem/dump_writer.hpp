#pragma once
// Particle snapshots OVITO reads, appended frame after frame to one file:
// LAMMPS dump text (`ITEM: ATOMS id type x y z radius vx vy vz fx fy fz body
// wall ...`) or extended XYZ. Like every wearscale output, the file is
// written under a temporary name and appears under its own name only once
// committed; a writer destroyed before commit() leaves nothing, unless a
// checkpoint has recorded its position: then its temporary file stays, for
// the resumed run to continue.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

/// A per-particle quantity written beside the standard columns (e.g. the
/// worn flag or the cluster label), one value per particle.
struct DumpColumn {
  std::string name;
  std::span<const double> values;
};

enum class DumpFormat {
  lammps,        ///< LAMMPS `dump custom` text
  extended_xyz,  ///< extended XYZ (Lattice, Origin, pbc, Properties)
};

/// How far a writer has got: its temporary file (a name in the folder of the
/// final file), and the bytes and frames written to it.
struct DumpPosition {
  std::string partial;
  std::uintmax_t bytes = 0;
  std::size_t frames = 0;
};

class DumpWriter {
 public:
  explicit DumpWriter(std::filesystem::path final_path, DumpFormat format = DumpFormat::lammps);
  ~DumpWriter();
  DumpWriter(const DumpWriter&) = delete;
  DumpWriter& operator=(const DumpWriter&) = delete;

  /// Appends one frame. Periodic axes are written with the box bounds (pp);
  /// open axes (ff) with bounds that enclose every particle and the box.
  /// Walls are written as wall index + 1 (0: mobile particle); type is the
  /// material + 1.
  void write(long step, double time, const Particles& p, const Box& box, const std::vector<DumpColumn>& extra = {});
  void write(const Simulation& sim, const std::vector<DumpColumn>& extra = {});
  void write(const Engine& engine, const std::vector<DumpColumn>& extra = {});

  std::size_t frames() const { return frames_; }
  /// Where the file stands now, for a checkpoint. From now on the
  /// temporary file is kept if the writer is destroyed uncommitted.
  DumpPosition position();
  /// Continues the file of a killed or interrupted run from `at` (what its
  /// checkpoint recorded): its temporary file becomes this writer's, under
  /// its own name and kept if this run stops too (the checkpoint refers to
  /// it), cut back to `at.bytes` (frames written after the checkpoint are
  /// dropped). False, and an empty file, if that file is gone or shorter than
  /// `at.bytes`.
  bool resume(const DumpPosition& at);
  /// Closes the file and moves it to its final name.
  void commit();
  const std::filesystem::path& final_path() const { return final_; }

 private:
  std::filesystem::path final_, partial_;
  DumpFormat format_;
  std::FILE* file_ = nullptr;
  std::size_t frames_ = 0;
  bool committed_ = false;
  bool keep_partial_ = false;  // a checkpoint refers to it
};

}  // namespace wearscale::dem
