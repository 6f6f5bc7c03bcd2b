#include "wearscale/dem/dump_writer.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace {
// Bounds of each axis: the box on periodic axes; on open ones, the box
// widened to enclose every particle (they may leave it).
std::array<std::pair<double, double>, 3> bounds(const Particles& p, const Box& box) {
  std::array<std::pair<double, double>, 3> b{};
  for (int a = 0; a < 3; ++a) {
    auto& [lo, hi] = b[static_cast<std::size_t>(a)];
    lo = box.lo[a];
    hi = box.hi[a];
    if (box.periodic[static_cast<std::size_t>(a)]) continue;
    for (std::size_t i = 0; i < p.size(); ++i) {
      lo = std::min(lo, p.position[i][a] - p.radius[i]);
      hi = std::max(hi, p.position[i][a] + p.radius[i]);
    }
  }
  return b;
}

// One line per particle, the same columns in both formats:
// id type x y z radius vx vy vz fx fy fz body wall [extra...].
void particle_rows(fmt::memory_buffer& out, const Particles& p, const std::vector<DumpColumn>& extra) {
  auto it = std::back_inserter(out);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 &x = p.position[i], &v = p.velocity[i], &f = p.force[i];
    fmt::format_to(it, "{} {} {:.10g} {:.10g} {:.10g} {:.10g} {:.8g} {:.8g} {:.8g} {:.8g} {:.8g} {:.8g} {} {}", p.id[i],
                   p.material[i] + 1, x.x, x.y, x.z, p.radius[i], v.x, v.y, v.z, f.x, f.y, f.z, p.body[i],
                   p.wall[i] + 1);
    for (const auto& c : extra) fmt::format_to(it, " {:.10g}", c.values[i]);
    fmt::format_to(it, "\n");
  }
}

void lammps_frame(fmt::memory_buffer& out, long step, const Particles& p, const Box& box,
                  const std::vector<DumpColumn>& extra) {
  auto it = std::back_inserter(out);
  const auto b = bounds(p, box);
  fmt::format_to(it, "ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\nITEM: BOX BOUNDS", step, p.size());
  for (std::size_t a = 0; a < 3; ++a) fmt::format_to(it, " {}", box.periodic[a] ? "pp" : "ff");
  fmt::format_to(it, "\n");
  for (const auto& [lo, hi] : b) fmt::format_to(it, "{:.17g} {:.17g}\n", lo, hi);
  fmt::format_to(it, "ITEM: ATOMS id type x y z radius vx vy vz fx fy fz body wall");
  for (const auto& c : extra) fmt::format_to(it, " {}", c.name);
  fmt::format_to(it, "\n");
  particle_rows(out, p, extra);
}

void xyz_frame(fmt::memory_buffer& out, long step, double time, const Particles& p, const Box& box,
               const std::vector<DumpColumn>& extra) {
  auto it = std::back_inserter(out);
  const auto b = bounds(p, box);
  fmt::format_to(it, "{}\n", p.size());
  fmt::format_to(it, "Lattice=\"{:.17g} 0 0 0 {:.17g} 0 0 0 {:.17g}\" Origin=\"{:.17g} {:.17g} {:.17g}\" ",
                 b[0].second - b[0].first, b[1].second - b[1].first, b[2].second - b[2].first, b[0].first,
                 b[1].first, b[2].first);
  fmt::format_to(it, "pbc=\"{} {} {}\" Timestep={} Time={:.17g} ", box.periodic[0] ? 'T' : 'F',
                 box.periodic[1] ? 'T' : 'F', box.periodic[2] ? 'T' : 'F', step, time);
  fmt::format_to(it, "Properties=id:I:1:species:S:1:pos:R:3:radius:R:1:velo:R:3:force:R:3:body:I:1:wall:I:1");
  for (const auto& c : extra) fmt::format_to(it, ":{}:R:1", c.name);
  fmt::format_to(it, "\n");
  particle_rows(out, p, extra);
}

bool valid_name(const std::string& name) {
  return !name.empty() && std::none_of(name.begin(), name.end(), [](char c) {
    return c == ' ' || c == ':' || c == '"' || c == '\n' || c == '\t' || c == '=';
  });
}
}  // namespace

DumpWriter::DumpWriter(std::filesystem::path final_path, DumpFormat format)
    : final_(std::move(final_path)), format_(format) {
  if (!final_.parent_path().empty()) std::filesystem::create_directories(final_.parent_path());
  partial_ = partial_path(final_);
  file_ = std::fopen(partial_.c_str(), "wb");
  if (!file_) throw OutputError(fmt::format("cannot write {}: {}", partial_.string(), std::strerror(errno)));
}

DumpWriter::~DumpWriter() {
  if (committed_) return;
  if (file_) std::fclose(file_);
  if (keep_partial_) return;
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
}

DumpPosition DumpWriter::position() {
  if (committed_) throw std::logic_error("DumpWriter: position() after commit()");
  if (std::fflush(file_) != 0)
    throw OutputError(fmt::format("cannot write {}: {}", partial_.string(), std::strerror(errno)));
  keep_partial_ = true;
  return {partial_.filename().string(), std::filesystem::file_size(partial_), frames_};
}

bool DumpWriter::resume(const DumpPosition& at) {
  if (committed_) throw std::logic_error("DumpWriter: resume() after commit()");
  const auto previous = partial_.parent_path() / at.partial;
  std::error_code ec;
  const auto size = std::filesystem::file_size(previous, ec);
  if (ec || size < at.bytes || at.partial.empty() || previous == partial_) return false;
  std::fclose(file_);
  file_ = nullptr;
  std::filesystem::remove(partial_, ec);  // the empty one this writer had opened
  // Continued under its own name, and kept whatever happens: the checkpoint
  // on disk refers to it until a newer one is saved (renamed, a resumed run
  // stopped before its first checkpoint lost the snapshots of the runs before).
  partial_ = previous;
  keep_partial_ = true;
  std::filesystem::resize_file(partial_, at.bytes);
  file_ = std::fopen(partial_.c_str(), "ab");
  if (!file_) throw OutputError(fmt::format("cannot write {}: {}", partial_.string(), std::strerror(errno)));
  frames_ = at.frames;
  return true;
}

void DumpWriter::write(long step, double time, const Particles& p, const Box& box,
                       const std::vector<DumpColumn>& extra) {
  if (committed_) throw std::logic_error("DumpWriter: frame written after commit()");
  for (const auto& c : extra) {
    if (!valid_name(c.name))
      throw std::invalid_argument(fmt::format("DumpWriter: column name '{}' is empty or has a space, ':', '=' or quote",
                                              c.name));
    if (c.values.size() != p.size())
      throw std::invalid_argument(fmt::format("DumpWriter: column '{}' has {} values for {} particles", c.name,
                                              c.values.size(), p.size()));
  }
  fmt::memory_buffer out;
  if (format_ == DumpFormat::lammps)
    lammps_frame(out, step, p, box, extra);
  else
    xyz_frame(out, step, time, p, box, extra);
  // One write per frame, flushed: a reader of the partial file sees whole frames.
  if (std::fwrite(out.data(), 1, out.size(), file_) != out.size() || std::fflush(file_) != 0)
    throw OutputError(fmt::format("cannot write {}: {}", partial_.string(), std::strerror(errno)));
  ++frames_;
}

void DumpWriter::write(const Simulation& sim, const std::vector<DumpColumn>& extra) {
  write(sim.step_count(), sim.time(), sim.particles(), sim.box(), extra);
}

void DumpWriter::write(const Engine& engine, const std::vector<DumpColumn>& extra) {
  write(engine.step_count(), engine.time(), engine.particles(), engine.box(), extra);
}

void DumpWriter::commit() {
  if (committed_) return;
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) throw OutputError(fmt::format("cannot write {}: {}", partial_.string(), std::strerror(errno)));
  commit_file(partial_, final_);
  committed_ = true;
}

}  // namespace wearscale::dem
