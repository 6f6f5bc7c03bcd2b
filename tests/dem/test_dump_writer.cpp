// Snapshots for OVITO: LAMMPS dump text and extended XYZ, frames appended to
// one file that appears under its name only once committed. The files are
// parsed back line by line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "wearscale/dem/dump_writer.hpp"
#include "scratch_dir.hpp"

using namespace wearscale::dem;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir dir("wearscale-dem-dump-");
  return dir.file(name);
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}

Particles three() {
  Particles p;
  p.add({{1.0, 2.0, 3.0}, 0.5, 1.0, {0.1, 0.2, 0.3}, 0, 1});
  p.add({{4.0, 5.0, 6.5}, 0.25, 1.0, {}, 1, 2});
  p.add({{7.5, 8.0, -2.0}, 0.5, 1.0, {}, 0, 2});
  p.wall[2] = 0;
  return p;
}

const Box box_xy_periodic{{0, 0, 0}, {10, 10, 10}, {true, true, false}};
}  // namespace

TEST(DumpWriter, LammpsDumpParsesBackFrameByFrame) {
  const auto path = scratch("frames.dump");
  auto p = three();
  const std::vector<double> worn{0.0, 1.0, 0.0};
  {
    DumpWriter out(path);
    out.write(0, 0.0, p, box_xy_periodic, {{"worn", worn}});
    p.position[0].x = 1.25;
    out.write(100, 0.5, p, box_xy_periodic, {{"worn", worn}});
    EXPECT_FALSE(fs::exists(path));  // not before commit
    EXPECT_EQ(out.frames(), 2u);
    out.commit();
  }
  ASSERT_TRUE(fs::exists(path));
  const auto lines = lines_of(path);
  // Per frame: 9 header lines + one per particle.
  ASSERT_EQ(lines.size(), 2u * (9u + 3u));
  for (std::size_t f = 0; f < 2; ++f) {
    const std::size_t o = f * 12;
    EXPECT_EQ(lines[o], "ITEM: TIMESTEP");
    EXPECT_EQ(lines[o + 1], f == 0 ? "0" : "100");
    EXPECT_EQ(lines[o + 2], "ITEM: NUMBER OF ATOMS");
    EXPECT_EQ(lines[o + 3], "3");
    EXPECT_EQ(lines[o + 4], "ITEM: BOX BOUNDS pp pp ff");
    EXPECT_EQ(fields(lines[o + 5]), (std::vector<std::string>{"0", "10"}));
    // The open z axis encloses the particle at z = −2 (radius 0.5).
    EXPECT_EQ(fields(lines[o + 7]), (std::vector<std::string>{"-2.5", "10"}));
    const auto header = fields(lines[o + 8]);
    ASSERT_EQ(header.size(), 2u + 15u);
    EXPECT_EQ(header[2], "id");
    EXPECT_EQ(header.back(), "worn");
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(fields(lines[o + 9 + i]).size(), 15u);
  }
  // Columns: id type x y z radius vx vy vz fx fy fz body wall worn.
  const auto first = fields(lines[9]);
  EXPECT_EQ(first[0], "1");
  EXPECT_EQ(first[1], "1");
  EXPECT_DOUBLE_EQ(std::stod(first[2]), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(first[5]), 0.5);
  EXPECT_DOUBLE_EQ(std::stod(first[8]), 0.3);
  EXPECT_EQ(first[12], "1");
  EXPECT_EQ(first[13], "0");  // mobile
  EXPECT_EQ(fields(lines[10])[1], "2");      // material 1 → type 2
  EXPECT_EQ(fields(lines[10])[14], "1");     // worn
  EXPECT_EQ(fields(lines[11])[13], "1");     // wall 0 → 1
  EXPECT_DOUBLE_EQ(std::stod(fields(lines[12 + 9])[2]), 1.25);  // the second frame moved
  fs::remove_all(path.parent_path());
}

TEST(DumpWriter, ExtendedXyzParsesBack) {
  const auto path = scratch("frames.xyz");
  const auto p = three();
  {
    DumpWriter out(path, DumpFormat::extended_xyz);
    out.write(7, 1.5, p, box_xy_periodic);
    out.write(8, 2.0, p, box_xy_periodic);
    out.commit();
  }
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 2u * (2u + 3u));
  EXPECT_EQ(lines[0], "3");
  const std::string& comment = lines[1];
  EXPECT_NE(comment.find("Lattice=\"10 0 0 0 10 0 0 0 12.5\""), std::string::npos) << comment;
  EXPECT_NE(comment.find("Origin=\"0 0 -2.5\""), std::string::npos) << comment;
  EXPECT_NE(comment.find("pbc=\"T T F\""), std::string::npos);
  EXPECT_NE(comment.find("Timestep=7"), std::string::npos);
  // Properties declare as many columns as each line has.
  const auto props = comment.substr(comment.find("Properties=") + 11);
  std::size_t declared = 0;
  std::istringstream spec(props);
  std::vector<std::string> parts;
  for (std::string part; std::getline(spec, part, ':');) parts.push_back(part);
  ASSERT_EQ(parts.size() % 3, 0u);
  for (std::size_t k = 2; k < parts.size(); k += 3) declared += std::stoul(parts[k]);
  for (std::size_t i = 2; i < 5; ++i) EXPECT_EQ(fields(lines[i]).size(), declared);
  EXPECT_EQ(declared, 14u);  // id species pos(3) radius velo(3) force(3) body wall
  EXPECT_DOUBLE_EQ(std::stod(fields(lines[3])[4]), 6.5);
  fs::remove_all(path.parent_path());
}

TEST(DumpWriter, NothingAppearsWithoutCommit) {
  const auto path = scratch("abandoned.dump");
  {
    DumpWriter out(path);
    out.write(0, 0.0, three(), box_xy_periodic);
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(path.parent_path()));  // the temporary file is gone too
  fs::remove_all(path.parent_path());
}

TEST(DumpWriter, RefusesAColumnOfTheWrongLength) {
  const auto path = scratch("bad.dump");
  {
    DumpWriter out(path);
    const std::vector<double> two{1.0, 2.0};
    EXPECT_THROW(out.write(0, 0.0, three(), box_xy_periodic, {{"worn", two}}), std::invalid_argument);
    const std::vector<double> ok{1.0, 2.0, 3.0};
    EXPECT_THROW(out.write(0, 0.0, three(), box_xy_periodic, {{"has space", ok}}), std::invalid_argument);
  }
  fs::remove_all(path.parent_path());
}

// A run resumed from a checkpoint continues the file its killed predecessor
// was writing: cut back to the frames the checkpoint recorded, then appended
// to, it holds exactly the frames an uninterrupted run writes.
TEST(DumpWriter, AResumedWriterContinuesTheFileFromTheCheckpointedPosition) {
  const auto straight = scratch("straight.dump"), resumed = scratch("resumed.dump");
  const Particles p = three();
  {
    DumpWriter w(straight);
    for (long step = 0; step < 3; ++step) w.write(step, 0.0, p, box_xy_periodic);
    w.commit();
  }
  DumpPosition at;
  {
    DumpWriter killed(resumed);
    killed.write(0, 0.0, p, box_xy_periodic);
    killed.write(1, 0.0, p, box_xy_periodic);
    at = killed.position();                          // the checkpoint, after frame 1
    killed.write(7, 0.0, p, box_xy_periodic);      // written after it: dropped on resume
  }  // destroyed uncommitted, as by an interrupt: the file a checkpoint refers to stays
  EXPECT_EQ(at.frames, 2u);
  EXPECT_TRUE(fs::exists(resumed.parent_path() / at.partial));
  EXPECT_FALSE(fs::exists(resumed));
  // The killed run was another process: its temporary file bears its pid.
  const std::string other = ".resumed.dump.partial-1";
  fs::rename(resumed.parent_path() / at.partial, resumed.parent_path() / other);
  at.partial = other;

  DumpWriter w(resumed);
  ASSERT_TRUE(w.resume(at));
  EXPECT_EQ(w.frames(), 2u);
  w.write(2, 0.0, p, box_xy_periodic);
  w.commit();
  EXPECT_EQ(lines_of(resumed), lines_of(straight));

  // Nothing to continue: an empty file, and the caller is told.
  DumpWriter fresh(scratch("fresh.dump"));
  EXPECT_FALSE(fresh.resume({".gone.partial-1", 100, 1}));
  EXPECT_EQ(fresh.frames(), 0u);
}
