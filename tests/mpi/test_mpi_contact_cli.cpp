// `mpirun -np P wearscale contact`: the fields in slabs over the ranks, the
// serial study's summary and files (rank 0 alone writes and prints); what the
// slabs cannot do is refused on every rank (status 2, the key named, nothing
// written). Runs mpirun itself (label "mpi"); 128² and 160², one thread a rank;
// Coulomb and Tresca friction on 64²; a free (zero-padded) window on 128².
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "scratch_dir.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_mpi_contact_cli_");
const fs::path work = work_scratch.path();
const std::string rough_case = "'" WEARSCALE_SOURCE_DIR "/cases/rough_contact.toml'";
const std::string frictional_case = "'" WEARSCALE_SOURCE_DIR "/cases/frictional_contact.toml'";

// `wearscale args` on `ranks` ranks (0: without mpirun); `env` adds variables.
CliResult run(int ranks, const std::string& args, const std::string& env = {}) {
  return run_cli(args, work, "OMP_NUM_THREADS=1 " + env, mpi_launcher(ranks));
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The error messages in `err`: the lines that start with "error: ".
std::size_t error_lines(const std::string& err) {
  std::size_t n = err.starts_with("error: ") ? 1 : 0;
  return n + count(err, "\nerror: ");
}

// Every headline figure within 1e-12 relative, counts equal. The residual ε
// (Σp|g| / Σp·h_rms at the last iteration, g ≈ 0 on the contact) is the
// round-off of the transforms itself: below the tolerance in both and equal
// to 1e-12 absolute (measured: 1e-16 apart, 1e-6 of its value, at 128²).
void expect_same_results(const nlohmann::json& serial, const nlohmann::json& slab, int ranks) {
  ASSERT_EQ(serial["results"].size(), slab["results"].size());
  const auto& contact = serial["parameters"]["contact"];
  const double tolerance = contact.contains("tolerance") ? contact["tolerance"].get<double>() : 1e-10;
  for (const auto& [name, v] : serial["results"].items()) {
    ASSERT_TRUE(slab["results"].contains(name)) << name;
    if (name == "error") {
      const double a = v["value"].get<double>(), b = slab["results"][name]["value"].get<double>();
      EXPECT_LT(a, tolerance);
      EXPECT_LT(b, tolerance);
      EXPECT_LE(std::abs(a - b), 1e-12) << "error at P = " << ranks;
      continue;
    }
    const double a = v["value"].get<double>(), b = slab["results"][name]["value"].get<double>();
    EXPECT_LE(std::abs(a - b), 1e-12 * std::abs(a)) << name << " at P = " << ranks << ": " << a << " vs " << b;
  }
  EXPECT_EQ(serial["results"]["iterations"], slab["results"]["iterations"]);
  EXPECT_EQ(serial["results"]["clusters"], slab["results"]["clusters"]);
}

// The datasets of contact.h5 within 1e-12 of each field's largest value; the
// contact map and the micro-contacts' table equal.
// (`more`: the datasets of a frictional contact besides.)
void expect_same_files(const fs::path& serial, const fs::path& slab, const std::vector<std::string>& more = {}) {
  for (const char* f : {"run.h5", "contact.h5", "contact.xdmf", "clusters.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(slab / f)) << slab / f;
  const wearscale::H5Reader a(serial / "contact.h5"), b(slab / "contact.h5");
  std::vector<std::string> datasets = {"/surface/height", "/fields/pressure",    "/fields/gap",
                                       "/fields/displacement", "/fields/contact", "/clusters/area",
                                       "/clusters/centroid_x", "/clusters/centroid_y"};
  datasets.insert(datasets.end(), more.begin(), more.end());
  for (const std::string& name : datasets) {
    const char* d = name.c_str();
    const auto read = [d](const wearscale::H5Reader& h5) {
      if (std::string(d).starts_with("/clusters")) return h5.read_series(d);
      const auto f = h5.read_field(d);
      return std::vector<double>(f.values().begin(), f.values().end());
    };
    const auto x = read(a), y = read(b);
    ASSERT_EQ(x.size(), y.size()) << d;
    double largest = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
      largest = std::max(largest, std::abs(x[k]));
      worst = std::max(worst, std::abs(x[k] - y[k]));
    }
    EXPECT_LE(worst, 1e-12 * largest) << d;
  }
  EXPECT_EQ(slurp(serial / "clusters.csv").size(), slurp(slab / "clusters.csv").size());
}

// CSV text without the (0-based) columns `drop`.
std::string csv_without_columns(const std::string& text, const std::vector<std::size_t>& drop) {
  std::string out, line;
  std::istringstream lines(text);
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::string cell;
    for (std::size_t c = 0; std::getline(cells, cell, ','); ++c)
      if (std::find(drop.begin(), drop.end(), c) == drop.end()) out += cell + ',';
    out += '\n';
  }
  return out;
}

// `wearscale args` serially (-q, into <name>_serial) and on `ranks` ranks (into
// <name>_slab), both succeeding; the two summaries and the slab run's messages.
struct SerialAndSlab {
  nlohmann::json serial, slab;
  std::string slab_err;
};
SerialAndSlab serial_and_slab(const std::string& args, int ranks, const std::string& name) {
  const auto serial = run(0, args + " -q --out " + name + "_serial");
  EXPECT_EQ(serial.status, 0) << serial.err;
  const auto slab = run(ranks, args + " --out " + name + "_slab");
  EXPECT_EQ(slab.status, 0) << slab.err;
  if (serial.status != 0 || slab.status != 0) return {};
  return {nlohmann::json::parse(serial.out), nlohmann::json::parse(slab.out), slab.err};
}
}  // namespace

TEST(MpiContactCli, TwoAndThreeRanksGiveTheSerialSummaryAndFiles) {
  const std::string args = "contact " + rough_case + " --set contact.grid=128 --json";
  const auto serial = run(0, args + " -q --out serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto s = nlohmann::json::parse(serial.out);
  for (int ranks : {2, 3}) {
    const std::string dir = "slab" + std::to_string(ranks);
    const auto slab = run(ranks, args + " --out " + dir);
    ASSERT_EQ(slab.status, 0) << slab.err;
    expect_same_results(s, nlohmann::json::parse(slab.out), ranks);  // one JSON object: rank 0's alone
    EXPECT_EQ(count(slab.err, "contact: "), 1u) << slab.err;         // the other ranks print nothing
    expect_same_files(work / "serial", work / dir);
  }
}

TEST(MpiContactCli, AboveTheGatherLimitEveryRankWritesItsRowsAndTheMicroContactsAreJoinedAcrossSlabs) {
  // [run] gather_limit below the grid (128² = 16 384 points): no rank gathers a
  // field, yet contact.h5 holds the serial fields (rank 0 lays it out, each
  // rank writes its rows) and the micro-contacts are the serial ones (each rank
  // labels its rows, rank 0 joins the pieces across the slabs' edges and the
  // cell's periodic edges): same count, areas and centroids, same order.
  for (const char* connectivity : {"four", "eight"}) {
    const std::string args = "contact " + rough_case + " --set contact.grid=128 --set contact.connectivity=" +
                             connectivity + " --json";
    const std::string serial_dir = std::string("inplace_serial_") + connectivity;
    const auto serial = run(0, args + " -q --out " + serial_dir + " --set run.gather_limit=10000");  // read, unused
    ASSERT_EQ(serial.status, 0) << serial.err;
    const auto s = nlohmann::json::parse(serial.out);
    EXPECT_EQ(s["parameters"]["run"]["gather_limit"], 10000);
    EXPECT_GT(s["results"]["clusters"]["value"].get<double>(), 20.0);
    for (int ranks : {2, 3}) {
      const std::string dir = "inplace" + std::to_string(ranks) + connectivity;
      const auto slab = run(ranks, args + " --set run.gather_limit=10000 --out " + dir);
      ASSERT_EQ(slab.status, 0) << slab.err;
      EXPECT_THAT(slab.err, HasSubstr("every rank writes its rows of the fields into contact.h5"));
      expect_same_results(s, nlohmann::json::parse(slab.out), ranks);  // the number of micro-contacts too
      expect_same_files(work / serial_dir, work / dir);  // fields, micro-contacts' areas and centroids
      EXPECT_EQ(slurp(work / serial_dir / "clusters.csv"), slurp(work / dir / "clusters.csv")) << connectivity;
      for (const auto& entry : fs::directory_iterator(work / dir))  // no temporary file left behind
        EXPECT_FALSE(entry.path().filename().string().starts_with(".")) << entry.path();
      // ParaView's view of the pressure (x fastest) reads the rows the ranks wrote.
      const wearscale::H5Reader b(work / dir / "contact.h5");
      const auto pressure = b.read_field("/fields/pressure");
      const auto view = b.read_series("/xdmf/fields/pressure");
      ASSERT_EQ(view.size(), pressure.size());
      const std::size_t nx = pressure.grid().nx, ny = pressure.grid().ny;
      for (std::size_t i = 0; i < nx; i += 7)
        for (std::size_t j = 0; j < ny; j += 5) EXPECT_EQ(view[j * nx + i], pressure[i * ny + j]) << i << ", " << j;
    }
  }
}

TEST(MpiContactCli, ADiskThatFailsWhileTheRanksWriteTheirRowsIsStatus2AndLeavesNothing) {
  // The disk fails (tests/support/fail_writes.c) while HDF5 lays contact.h5
  // out (its first write, its closing writes) or while a rank flushes its rows
  // in place: status 2 on every rank, said once, no crash, nothing left.
  const std::string args = "contact " + rough_case + " --set contact.grid=128 --set run.gather_limit=10000 -q";
  const std::pair<const char*, int> faults[] = {{"write", 2}, {"write", 3}, {"fsync", 1}, {"fsync", 4}};
  for (const auto& [op, at] : faults) {
    const std::string dir = std::string("disk_") + op + std::to_string(at);
    const std::string env = "LD_PRELOAD='" WEARSCALE_FAULT_SHIM "' FAULT_DIR='" + (work / dir).string() +
                            "' FAULT_OP=" + op + " FAULT_AT=" + std::to_string(at);
    const auto r = run(2, args + " --out " + dir, env);
    EXPECT_EQ(r.status, 2) << op << " " << at << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("contact.h5 was not written")) << op << " " << at;
    EXPECT_EQ(error_lines(r.err), 1u) << op << " " << at << "\n" << r.err;
    EXPECT_FALSE(fs::exists(work / dir / "contact.h5")) << op << " " << at;
    EXPECT_FALSE(fs::exists(work / dir / "summary.json")) << op << " " << at;
    if (fs::exists(work / dir))
      for (const auto& entry : fs::directory_iterator(work / dir)) ADD_FAILURE() << "left behind: " << entry.path();
  }
}

TEST(MpiContactCli, TheCommandsFlagsCountUnderMpirunAsWithout) {
  // --pressure is the flag of contact.mean_pressure: half the case's load, under mpirun as without it.
  const std::string args = "contact " + rough_case + " --set contact.grid=128 --pressure 0.015 --json";
  const auto r = serial_and_slab(args, 2, "flag");
  ASSERT_FALSE(r.slab.is_null());
  EXPECT_DOUBLE_EQ(r.slab["parameters"]["contact"]["mean_pressure"].get<double>(), 0.015) << r.slab;
  expect_same_results(r.serial, r.slab, 2);
}

TEST(MpiContactCli, TheFullPreconditionerOnThreeRanksGivesTheSerialSummary) {
  // The two-level default runs in the tests above (128 rows on 3 ranks: 43, 43, 42, slabs that start on odd
  // rows, moved to even ones for the coarse grid); the full preconditioner S alike.
  const std::string args = "contact " + rough_case + " --set contact.grid=128 --set contact.preconditioner=full --json";
  const auto r = serial_and_slab(args, 3, "full");
  ASSERT_FALSE(r.slab.is_null());
  expect_same_results(r.serial, r.slab, 3);
}

TEST(MpiContactCli, ASphereOnARoughSurfaceGivesTheSerialSummaryAndFiles) {
  const std::string args = "contact " + rough_case +
                           " --set contact.grid=160 --set contact.sphere.radius=2 --set contact.rough.hprime_rms=0.2 "
                           "--set contact.mean_pressure=0.01 --json -q";
  const auto r = serial_and_slab(args, 2, "sphere");
  ASSERT_FALSE(r.slab.is_null());
  expect_same_results(r.serial, r.slab, 2);
  expect_same_files(work / "sphere_serial", work / "sphere_slab");
}

TEST(MpiContactCli, AFreeBoundaryOnRanksGivesTheSerialHertzContactGatheredOrWrittenInPlace) {
  // A sphere (R = 1) on a free window of four Hertz radii (a = 0.1 at this
  // load, 64 cells across the contact): the slabs give the serial summary and
  // files, whether rank 0 gathers the fields or every rank writes its rows,
  // and the approach is Hertz's a²/R = 0.01 without an image correction.
  const std::string args = "contact --set contact.grid=128 --set contact.size=0.4 --set contact.e_star=1 "
                           "--set 'contact.boundary=\"free\"' --set contact.normal_load=0.0013333333333333333 "
                           "--set contact.sphere.radius=1 --set contact.tolerance=1e-10 --json";
  const auto serial = run(0, args + " -q --out free_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto s = nlohmann::json::parse(serial.out);
  EXPECT_NEAR(s["results"]["interference"]["value"].get<double>(), 0.01, 0.01 * 0.01);
  for (const auto& [ranks, limit] : {std::pair{2, 1000000}, std::pair{3, 1000000}, std::pair{2, 10000}}) {
    const std::string dir = "free" + std::to_string(ranks) + "_" + std::to_string(limit);
    const auto slab = run(ranks, args + " --set run.gather_limit=" + std::to_string(limit) + " --out " + dir);
    ASSERT_EQ(slab.status, 0) << slab.err;
    EXPECT_THAT(slab.err, HasSubstr("free boundary, in slabs over " + std::to_string(ranks) + " MPI ranks"));
    expect_same_results(s, nlohmann::json::parse(slab.out), ranks);
    expect_same_files(work / "free_serial", work / dir);
    EXPECT_EQ(slurp(work / "free_serial" / "clusters.csv"), slurp(work / dir / "clusters.csv"));
  }
  // Ten times the load: the contact (a = 0.215) reaches the window's edge.
  // Refused on every rank, said once, nothing written, as serially.
  for (const int ranks : {0, 3}) {
    const std::string dir = "free_edge" + std::to_string(ranks);
    const auto r = run(ranks, args + " --set contact.normal_load=0.013333333333333333 -q --out " + dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("reaches the edge of the 0.4 m × 0.4 m window"));
    EXPECT_EQ(error_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(work / dir)) << dir;
  }
}

TEST(MpiContactCli, AMeasuredSurfaceFileIsReadInSlabsAndGivesTheSerialSummaryAndFiles) {
  // A rectangular surface of odd rows (99 × 64 points over 1.5 × 1 mm), read
  // from its HDF5 file: every rank keeps its rows; P = 2 and 3 against serial.
  ASSERT_EQ(run(0, "surface generate --nx 99 --ny 64 --size '1.5 mm,1 mm' --hurst 0.8 --kl 2 --kr 4 --ks 32 --seed 5 "
                   "--hprime-rms 0.5 -q --out measured_surface")
                .status,
            0);
  const std::string args = "contact --set contact.surface=measured_surface/surface.h5 --set 'contact.e_star=\"30 GPa\"' "
                           "--set 'contact.mean_pressure=\"50 MPa\"' --json";
  for (int ranks : {2, 3}) {
    const auto r = serial_and_slab(args, ranks, "measured" + std::to_string(ranks));
    ASSERT_FALSE(r.slab.is_null());
    expect_same_results(r.serial, r.slab, ranks);
    EXPECT_GT(r.serial["results"]["contact_fraction"]["value"].get<double>(), 0.01);
    const std::string dir = "measured" + std::to_string(ranks);
    expect_same_files(work / (dir + "_serial"), work / (dir + "_slab"));
  }
  // Fewer rows than ranks: refused on every rank, naming the file's key, nothing written.
  ASSERT_EQ(run(0, "surface generate --nx 4 --ny 64 --size 1e-3 --hurst 0.8 --kl 1 --ks 2 --hprime-rms 0.5 -q "
                   "--out thin_surface")
                .status,
            0);
  const auto thin = run(5, "contact --set contact.surface=thin_surface/surface.h5 --set contact.e_star=1e9 "
                           "--set contact.mean_pressure=1e6 -q --out thin_slab");
  EXPECT_EQ(thin.status, 2) << thin.err;
  EXPECT_THAT(thin.err, HasSubstr("contact.surface"));
  EXPECT_THAT(thin.err, HasSubstr("fewer than the 5 ranks"));
  EXPECT_EQ(error_lines(thin.err), 1u) << thin.err;
  EXPECT_FALSE(fs::exists(work / "thin_slab"));
}

// The datasets a frictional contact writes besides the normal ones.
const std::vector<std::string> frictional_datasets = {
    "/fields/traction_x", "/fields/traction_y", "/fields/stick_slip",       "/fields/slip_x",
    "/fields/slip_y",     "/fields/displacement_x", "/fields/displacement_y", "/stress/surface/sigma_I",
    "/stress/surface/tau_max", "/stress/depth_0/tau_max", "/stress/depth_1/sigma_I"};

TEST(MpiContactCli, TrescaFrictionOnTwoRanksGivesTheSerialSummaryAndFiles) {
  // The shipped frictional case (a rough sphere, Tresca, ν = 0.17, stresses at
  // two depths and (4.25) per micro-contact) on 64²: the serial summary and files.
  const std::string args = "contact " + frictional_case +
                           " --set contact.grid=64 --set contact.rough.k_l=8 --set contact.rough.k_r=8 "
                           "--set contact.rough.k_s=16 --json";
  const auto r = serial_and_slab(args, 2, "tresca");
  ASSERT_FALSE(r.slab.is_null());
  expect_same_results(r.serial, r.slab, 2);
  EXPECT_EQ(r.serial["results"]["bound_updates"], r.slab["results"]["bound_updates"]);
  EXPECT_EQ(r.serial["results"]["crack_initiation_sites"], r.slab["results"]["crack_initiation_sites"]);
  EXPECT_EQ(count(r.slab_err, "contact: 64×64"), 1u) << r.slab_err;  // rank 0's line alone
  expect_same_files(work / "tresca_serial", work / "tresca_slab", frictional_datasets);
}

TEST(MpiContactCli, FrictionAboveTheGatherLimitWritesTheSerialFieldsAndStressesInPlace) {
  // [run] gather_limit below the grid: every rank computes its rows of the
  // stresses (surface and two depths) and writes its rows of every field, and
  // crack initiation (4.25) is checked at the micro-contacts' edges across the
  // slabs; the serial figures, fields, stresses, micro-contacts and their
  // crack checks at P = 2 and 3.
  const std::string args = "contact " + rough_case +
                           " --set contact.grid=64 --set contact.rough.k_s=16 --set contact.friction=coulomb "
                           "--set contact.poisson=0.3 --set contact.friction_coefficient=0.5 "
                           "--set contact.tangential_pressure=0.006 --set 'contact.stress_depths=[0.01, 0.03]' "
                           "--set contact.tensile_strength=0.11 --set run.gather_limit=1000 --json";
  const auto serial = run(0, args + " -q --out friction_inplace_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto s = nlohmann::json::parse(serial.out);
  EXPECT_GT(s["results"]["stick_fraction"]["value"].get<double>(), 0.0);
  EXPECT_GT(s["results"]["slip_fraction"]["value"].get<double>(), 0.0);
  EXPECT_GT(s["results"]["clusters"]["value"].get<double>(), 10.0);
  // σ_m between the micro-contacts' edge stresses: some meet (4.25), some do not.
  const double sites = s["results"]["crack_initiation_sites"]["value"].get<double>();
  EXPECT_GT(sites, 0.0);
  EXPECT_LT(sites, s["results"]["clusters"]["value"].get<double>());
  std::vector<std::string> datasets = frictional_datasets;
  datasets.insert(datasets.end(), {"/stress/surface/sigma_III", "/stress/depth_0/sigma_I", "/stress/depth_1/tau_max",
                                   "/clusters/trailing_sigma_I", "/clusters/leading_sigma_III",
                                   "/clusters/crack_initiation"});
  for (int ranks : {2, 3}) {
    const std::string dir = "friction_inplace" + std::to_string(ranks);
    const auto slab = run(ranks, args + " --out " + dir);
    ASSERT_EQ(slab.status, 0) << slab.err;
    EXPECT_THAT(slab.err, HasSubstr("every rank computes its rows of the stresses"));
    expect_same_results(s, nlohmann::json::parse(slab.out), ranks);
    expect_same_files(work / "friction_inplace_serial", work / dir, datasets);
    // The micro-contacts and the criterion's outcome byte for byte; the edge
    // stresses (columns 4-5) come from the slabs' transforms and agree to
    // their round-off (the /clusters datasets above), which can print a
    // near-zero value otherwise.
    EXPECT_EQ(csv_without_columns(slurp(work / "friction_inplace_serial" / "clusters.csv"), {3, 4}),
              csv_without_columns(slurp(work / dir / "clusters.csv"), {3, 4}));
    const wearscale::H5Reader b(work / dir / "contact.h5");
    EXPECT_EQ(b.string_attribute("/fields/stick_slip", "values"), "0 open, 1 stick, 2 slip");
    EXPECT_DOUBLE_EQ(b.number_attribute("/stress/depth_1", "depth"), 0.03);
  }
}

TEST(MpiContactCli, CoulombFrictionOnThreeRanksGivesTheSerialSummaryAndFiles) {
  const std::string args = "contact " + rough_case +
                           " --set contact.grid=64 --set contact.rough.k_s=16 --set contact.friction=coulomb "
                           "--set contact.poisson=0.3 --set contact.friction_coefficient=0.5 "
                           "--set contact.tangential_pressure=0.006 --json -q";
  const auto r = serial_and_slab(args, 3, "coulomb");
  ASSERT_FALSE(r.slab.is_null());
  expect_same_results(r.serial, r.slab, 3);
  EXPECT_GT(r.serial["results"]["stick_fraction"]["value"].get<double>(), 0.0);
  EXPECT_GT(r.serial["results"]["slip_fraction"]["value"].get<double>(), 0.0);
  expect_same_files(work / "coulomb_serial", work / "coulomb_slab",
                    {"/fields/traction_x", "/fields/stick_slip", "/fields/slip_x", "/stress/surface/sigma_I"});
}

TEST(MpiContactCli, WhatTheSlabsCannotDoIsRefusedOnEveryRankNamingTheKey) {
  const std::string args = "contact " + rough_case + " --set contact.grid=128 -q";
  const std::pair<const char*, const char*> cases[] = {
      {"--set contact.boundary=free --set contact.friction=coulomb --set contact.poisson=0.3 "
       "--set contact.friction_coefficient=0.5",
       "contact.boundary"},  // friction on a free window (refused serially alike)
      {"--set run.gather_limit=0", "run.gather_limit"},
      {"--set contact.grid=7", "contact.grid"},
      {"--resume elsewhere", "--resume"}};
  int k = 0;
  for (const auto& [set, key] : cases) {
    const std::string dir = "refused" + std::to_string(k++);
    const auto r = run(3, args + " " + set + " --out " + dir);
    EXPECT_EQ(r.status, 2) << set << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(key)) << set;
    EXPECT_EQ(error_lines(r.err), 1u) << set << "\n" << r.err;  // said once, by one rank
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("MPI_ABORT"))) << set;
    EXPECT_FALSE(fs::exists(work / dir)) << set;  // nothing written, not even the folder
  }
  // More than a rank's share of memory (rank 0's, which gathers the fields): refused before any work.
  const auto r = run(2, "contact " + rough_case + " --set contact.grid=2048 -q --out refused_memory",
                     "WEARSCALE_MEMORY_LIMIT=100MiB");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("contact.grid"));
  EXPECT_THAT(r.err, HasSubstr("rank 0's share"));
  EXPECT_FALSE(fs::exists(work / "refused_memory"));
}

TEST(MpiContactCli, ASolverFailureEndsEveryRankOnceWithStatus1) {
  // Three iterations cannot reach 1e-10: every rank fails alike (the same
  // sums), rank 0 says it once, the job ends (no rank waits), nothing is left.
  const auto r = run(2, "contact " + rough_case + " --set contact.grid=128 --set contact.max_iterations=3 -q --out failed");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(error_lines(r.err), 1u) << r.err;  // message lines start with "error: "
  EXPECT_THAT(r.err, HasSubstr("no convergence"));
  EXPECT_FALSE(fs::exists(work / "failed" / "summary.json"));
}

TEST(MpiContactCli, SigtermToMpirunStopsAFrictionalSlabSolveOnEveryRankAtOnce) {
  // The ranks sum their answers to "stop?" with each iteration's sums, so all
  // stop at the same iteration: status 130 from every rank, said once by rank
  // 0, no rank aborting the others, nothing written. (mpirun, signalled
  // itself, ends with its own status 1; signalled ranks give the job 130.)
  const std::string cmd = "cd '" + work.string() + "' && exec env CI=true OMP_NUM_THREADS=1 " WEARSCALE_MPIRUN
                          " -np 2 '" WEARSCALE_CLI "' contact " + frictional_case +
                          " --set contact.grid=512 --set contact.rough.k_s=128 -v --out stopped >stopped.out "
                          "2>stopped.err";
  fs::create_directories(work);
  const pid_t job = spawn_shell(cmd);
  ASSERT_GT(job, 0);
  bool sent = false, ended = false;
  int status = 0;
  for (int wait = 0; wait < 2400 && !sent && !ended; ++wait) {  // once the solve is under way
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (slurp(work / "stopped.err").find("iteration 10,") != std::string::npos) sent = ::kill(job, SIGTERM) == 0;
    ended = ::waitpid(job, &status, WNOHANG) == job;
  }
  if (!ended) ::waitpid(job, &status, 0);
  ASSERT_TRUE(sent) << slurp(work / "stopped.err");
  const std::string err = slurp(work / "stopped.err");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_NE(WEXITSTATUS(status), 0) << err;
  EXPECT_EQ(count(err, "stopped at iteration"), 1u) << err;
  EXPECT_EQ(error_lines(err), 1u) << err;
  EXPECT_THAT(err, ::testing::Not(HasSubstr("MPI_ABORT"))) << err;
  EXPECT_FALSE(fs::exists(work / "stopped" / "summary.json"));
  EXPECT_FALSE(fs::exists(work / "stopped" / "contact.h5"));
}
