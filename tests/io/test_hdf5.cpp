// HDF5 output: what is written reads back identically, and an output file
// appears under its final name only once complete. HDF5 input: a file of
// another tool or a damaged one gives InputError naming what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <numeric>

#include "h5_fixture.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/version.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/hdf5_file.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("wearscale_h5_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}
}  // namespace

TEST(HDF5, SeriesTableFieldAndAttributesReadBack) {
  const auto path = scratch("roundtrip.h5");
  std::vector<double> t(100), mu(100);
  std::iota(t.begin(), t.end(), 0.0);
  for (std::size_t k = 0; k < mu.size(); ++k) mu[k] = 0.14 + 1e-3 * static_cast<double>(k);
  RealField p(Grid2D(64, 32, 2e-3, 1e-3));
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::sin(static_cast<double>(k));
  {
    H5Writer w(path);
    w.write_series("/series/time", t, "s");
    w.write_table("/curves/friction", {"s", "mu"}, {t, mu}, {"m", "1"});
    w.write_field("/fields/pressure", p, "Pa");
    w.write_scalar("/results/mu_mean", 0.5, "1");
    w.set_attribute("/", "provenance", "macro/bem-pin-on-disc");
    w.set_attribute("/fields/pressure", "time", 1.25);
    w.commit();
  }
  H5Reader r(path);
  EXPECT_EQ(r.read_series("/series/time"), t);
  EXPECT_EQ(r.read_series("/curves/friction/mu"), mu);
  EXPECT_EQ(r.string_attribute("/curves/friction", "columns"), "s,mu");
  EXPECT_EQ(r.string_attribute("/series/time", "unit"), "s");
  EXPECT_EQ(r.read_scalar("/results/mu_mean"), 0.5);
  EXPECT_EQ(r.string_attribute("/", "provenance"), "macro/bem-pin-on-disc");
  EXPECT_EQ(r.number_attribute("/fields/pressure", "time"), 1.25);
  const RealField q = r.read_field("/fields/pressure");
  EXPECT_EQ(q.grid(), p.grid());
  for (std::size_t k = 0; k < p.size(); ++k) ASSERT_EQ(q[k], p[k]);
  EXPECT_FALSE(r.exists("/fields/gap"));
  EXPECT_FALSE(r.exists("/nothing/here"));
  fs::remove_all(path.parent_path());
}

// What h5py users expect (h5py's norms): text attributes are variable-length
// UTF-8 strings (h5py reads a str, so attrs['unit'] == 'Pa'), a scalar is a
// dataset of shape (), and a field says what its axes are and what it is.
TEST(HDF5, TextIsVariableLengthUtf8ScalarsHaveShapeNoneAndFieldsNameTheirAxes) {
  const auto path = scratch("h5py_norms.h5");
  RealField p(Grid2D(4, 2, 2e-3, 1e-3));
  {
    H5Writer w(path);
    w.write_field("/fields/pressure", p, "Pa", "contact pressure", {-1e-3, -0.5e-3});
    w.write_scalar("/results/mu_mean", 0.5, "1");
    w.set_attribute("/", "note", "µm³ ∞");
    w.commit();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const auto& [object, name] : std::vector<std::pair<std::string, std::string>>{
           {"/fields/pressure", "unit"}, {"/fields/pressure", "axes"}, {"/fields/pressure", "description"},
           {"/", "note"}, {"/", "wearscale_version"}}) {
    const hid_t attr = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(attr, 0) << object << " " << name;
    const hid_t type = H5Aget_type(attr), space = H5Aget_space(attr);
    EXPECT_GT(H5Tis_variable_str(type), 0) << object << " " << name;
    EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8) << object << " " << name;
    EXPECT_EQ(H5Sget_simple_extent_type(space), H5S_SCALAR) << object << " " << name;
    H5Sclose(space), H5Tclose(type), H5Aclose(attr);
  }
  H5Fclose(file);
  H5Reader r(path);
  EXPECT_TRUE(r.shape("/results/mu_mean").empty()) << "shape (), not (1,)";
  EXPECT_EQ(r.read_scalar("/results/mu_mean"), 0.5);
  EXPECT_EQ(r.string_attribute("/fields/pressure", "axes"), "x,y");
  EXPECT_EQ(r.string_attribute("/fields/pressure", "description"), "contact pressure");
  EXPECT_EQ(r.number_attribute("/fields/pressure", "x0"), -1e-3);
  EXPECT_EQ(r.number_attribute("/fields/pressure", "y0"), -0.5e-3);
  EXPECT_EQ(r.string_attribute("/", "note"), "µm³ ∞");
  fs::remove_all(path.parent_path());
}

// An attribute may take at most 64 KiB of its object's header: a resolved
// case of megabytes (a long name, a sweep of thousands of values) would not
// fit as a fixed-length string. Variable-length text lives in the file's heap,
// whatever its length.
TEST(HDF5, ATextAttributeOfMegabytesIsWrittenAndReadBack) {
  const auto path = scratch("long_attribute.h5");
  std::string text(3 << 20, 'x');
  for (std::size_t k = 0; k < text.size(); k += 97) text[k] = '\n';
  {
    H5Writer w(path);
    w.set_attribute("/", "case_toml", text);
    w.set_attribute("/", "name", std::string(70000, 'y'));
    w.commit();
  }
  H5Reader r(path);
  EXPECT_EQ(r.string_attribute("/", "case_toml"), text);
  EXPECT_EQ(r.string_attribute("/", "name"), std::string(70000, 'y'));
  fs::remove_all(path.parent_path());
}

// h5py, as a user reads a file: str attributes, () scalars, a field's axes.
TEST(HDF5, H5pyReadsTextAsStrAndScalarsAsShapeNone) {
  const std::string python = WEARSCALE_TEST_PYTHON;
  if (std::system((python + " -c 'import h5py' >/dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "h5py is not installed (Debian: python3-h5py)";
  const auto path = scratch("h5py.h5");
  RealField p(Grid2D(4, 2, 2e-3, 1e-3));
  {
    H5Writer w(path);
    w.write_field("/fields/pressure", p, "Pa", "contact pressure");
    w.write_scalar("/results/mu_mean", 0.5, "1");
    w.set_attribute("/", "case_toml", std::string(70000, 'x'));
    w.commit();
  }
  const std::string check =
      "import h5py, sys\n"
      "f = h5py.File(sys.argv[1], 'r')\n"
      "assert f['/fields/pressure'].attrs['unit'] == 'Pa', repr(f['/fields/pressure'].attrs['unit'])\n"
      "assert f['/results/mu_mean'].attrs['unit'] == '1'\n"
      "assert f['/results/mu_mean'].shape == (), f['/results/mu_mean'].shape\n"
      "assert f['/results/mu_mean'][()] == 0.5\n"
      "assert f['/fields/pressure'].attrs['axes'] == 'x,y'\n"
      "assert f['/fields/pressure'].attrs['description'] == 'contact pressure'\n"
      "assert f.attrs['case_toml'] == 'x' * 70000\n"
      "assert isinstance(f.attrs['wearscale_version'], str)\n";
  const auto script = scratch("check.py");
  std::ofstream(script) << check;
  EXPECT_EQ(std::system((python + " '" + script.string() + "' '" + path.string() + "'").c_str()), 0);
  fs::remove_all(path.parent_path());
}

// Whatever writes it (a run, a contact study, a wear map, a generated
// surface), a file says which wearscale made it, from which revision and when.
TEST(HDF5, EveryFileCarriesTheVersionTheRevisionAndItsCreationTime) {
  const auto path = scratch("provenance.h5");
  {
    H5Writer w(path);
    w.write_scalar("/x", 1.0);
    w.commit();
  }
  H5Reader r(path);
  EXPECT_EQ(r.string_attribute("/", "wearscale_version"), version());
  EXPECT_THAT(r.string_attribute("/", "created"),
              ::testing::MatchesRegex("20[0-9][0-9]-[01][0-9]-[0-3][0-9]T[0-2][0-9]:[0-5][0-9]:[0-6][0-9]Z"));
  EXPECT_EQ(r.string_attribute_if("/", "git_revision").value_or(""), git_revision())
      << "the revision when built from git, no attribute otherwise";
  fs::remove_all(path.parent_path());
}

TEST(HDF5, AWriterThatIsNotCommittedLeavesNoFile) {
  const auto path = scratch("aborted.h5");
  try {
    H5Writer w(path);
    w.write_series("/x", std::vector<double>(10, 1.0));
    throw std::runtime_error("solver diverged");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(files_in(path.parent_path()), 0u);  // the partial file is removed too
  fs::remove_all(path.parent_path());
}

TEST(HDF5, FieldsReservedOnDiskAndWrittenInPlaceByRowsReadBackExactly) {
  // The layout a slab run uses above its gather limit: rank 0 reserves the
  // field, two writers (here one process) put their rows at its offset.
  const auto path = scratch("in_place.h5");
  const Grid2D g(5, 3, 2.0, 0.75);
  RealField f(g);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = std::sin(0.7 * static_cast<double>(k)) * 1e-6;
  {
    H5Writer w(path, Commit::Now, H5Storage::Disk);
    const std::uint64_t at = w.reserve_field("/fields/pressure", g, "Pa");
    w.write_scalar("/results/mean_pressure", 0.5, "Pa");
    w.finish_layout();
    write_in_place(w.partial(), at + 2 * g.ny * sizeof(double), f.data() + 2 * g.ny, 3 * g.ny * sizeof(double));
    write_in_place(w.partial(), at, f.data(), 2 * g.ny * sizeof(double));
    EXPECT_FALSE(fs::exists(path));  // not before the commit
    w.commit();
  }
  const H5Reader r(path);
  const RealField back = r.read_field("/fields/pressure");
  ASSERT_EQ(back.grid().nx, 5u);
  ASSERT_EQ(back.grid().ny, 3u);
  EXPECT_EQ(back.grid().lx, 2.0);
  EXPECT_EQ(back.grid().ly, 0.75);
  for (std::size_t k = 0; k < f.size(); ++k) EXPECT_EQ(back[k], f[k]) << k;
  EXPECT_EQ(r.read_scalar("/results/mean_pressure"), 0.5);
  // In memory there is no offset to give, and a disk file left uncommitted leaves nothing.
  H5Writer memory(scratch("memory.h5"));
  EXPECT_THROW(memory.reserve_field("/f", g), std::logic_error);
  const auto dropped = scratch("dropped.h5");
  {
    H5Writer w(dropped, Commit::Now, H5Storage::Disk);
    w.reserve_field("/f", g);
    w.finish_layout();
  }
  EXPECT_FALSE(fs::exists(dropped));
  EXPECT_FALSE(fs::exists(partial_path(dropped)));  // nor its temporary file
}

TEST(HDF5, AKilledWriterLeavesThePreviousCompleteFile) {
  const auto path = scratch("killed.h5");
  {
    H5Writer w(path);
    w.write_series("/version", std::vector<double>{1.0});
    w.commit();
  }
  const pid_t child = ::fork();
  if (child == 0) {
    H5Writer w(path);
    w.write_series("/version", std::vector<double>{2.0});
    w.write_series("/big", std::vector<double>(1 << 16, 3.0));
    ::kill(::getpid(), SIGKILL);  // dies mid-run, before commit
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  H5Reader r(path);  // still the complete first version
  EXPECT_EQ(r.read_series("/version"), std::vector<double>{1.0});
  fs::remove_all(path.parent_path());
}

TEST(HDF5, ReadingSomethingThatIsNotHDF5IsBadInput) {
  const auto path = scratch("text.h5");
  std::ofstream(path) << "not hdf5";
  EXPECT_THROW(H5Reader{path}, InputError);
  EXPECT_THROW(H5Reader{scratch("missing.h5")}, InputError);
  fs::remove_all(path.parent_path());
}

TEST(HDF5, MissingDatasetIsBadInputNamingIt) {
  const auto path = scratch("small.h5");
  {
    H5Writer w(path);
    w.write_series("/a", std::vector<double>{1.0, 2.0});
    w.commit();
  }
  H5Reader r(path);
  try {
    r.read_field("/heights");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/heights"), std::string::npos);
  }
  EXPECT_THROW(r.read_field("/a"), InputError);  // 1D is not a field
  fs::remove_all(path.parent_path());
}

// ---------------------------------------------------------------------------
// Files from other tools, and damaged ones: every reader checks type and
// shape before it reads, and the size against the memory limit.

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}
}  // namespace

TEST(HDF5, AnArrayAttributeWhereOneNumberIsExpectedIsRefusedNamingItsLength) {
  const auto path = scratch("array_attr.h5");
  {
    h5fixture::File f(path);
    f.dataset("/surface/height", {4, 4}, std::vector<double>(16, 1.0));
    f.number_attribute("/surface/height", "lx", std::vector<double>(1000, 1e-3));
    f.number_attribute("/surface/height", "ly", std::vector<double>{1e-3, 2e-3, 3e-3, 4e-3});
  }
  H5Reader r(path);
  EXPECT_THAT(error_of([&] { r.number_attribute("/surface/height", "lx"); }),
              ::testing::AllOf(::testing::HasSubstr("attribute 'lx' on '/surface/height' holds 1000 values"),
                               ::testing::HasSubstr("allowed: one")));
  EXPECT_THAT(error_of([&] { r.number_attribute("/surface/height", "ly"); }), ::testing::HasSubstr("holds 4 values"));
  EXPECT_THAT(error_of([&] { r.read_field("/surface/height"); }), ::testing::HasSubstr("'lx'"));
  fs::remove_all(path.parent_path());
}

TEST(HDF5, AStringWhereANumberIsExpectedIsRefusedShowingTheString) {
  const auto path = scratch("string_attr.h5");
  {
    h5fixture::File f(path);
    f.dataset("/surface/height", {4, 4}, std::vector<double>(16, 1.0));
    f.string_attribute("/surface/height", "lx", "1 mm");
  }
  H5Reader r(path);
  EXPECT_THAT(error_of([&] { r.number_attribute_if("/surface/height", "lx"); }),
              ::testing::HasSubstr("attribute 'lx' on '/surface/height' is the string '1 mm'; allowed: one number"));
  EXPECT_EQ(r.number_attribute_if("/surface/height", "absent"), std::nullopt);
  fs::remove_all(path.parent_path());
}

// h5py writes str attributes as variable-length UTF-8 strings.
TEST(HDF5, VariableLengthStringAttributesAsH5pyWritesThemReadAsText) {
  const auto path = scratch("vlen.h5");
  {
    h5fixture::File f(path);
    f.group("/strength");
    f.string_attribute("/strength", "material", "Si");
    f.string_attribute("/strength", "source", "σ from MD, 10 nm box");
    f.string_attribute("/strength", "fixed", "SiO2", false);
    f.number_attribute("/strength", "count", {3.0});
  }
  H5Reader r(path);
  EXPECT_EQ(r.string_attribute("/strength", "material"), "Si");
  EXPECT_EQ(r.string_attribute("/strength", "source"), "σ from MD, 10 nm box");
  EXPECT_EQ(r.string_attribute("/strength", "fixed"), "SiO2");
  EXPECT_THAT(error_of([&] { r.string_attribute("/strength", "count"); }), ::testing::HasSubstr("not a string"));
  EXPECT_EQ(r.string_attribute_if("/strength", "absent"), std::nullopt);
  fs::remove_all(path.parent_path());
}

// What is saved to be read back bit for bit (checkpoints) must be 64-bit floats.
TEST(HDF5, ExactReadsRefuseAnythingButASeriesOf64BitFloats) {
  const auto path = scratch("types.h5");
  {
    h5fixture::File f(path);
    f.dataset("/f64", {3}, {1.0, 2.0, 3.0});
    f.dataset("/f32", {3}, {1.0, 2.0, 3.0}, H5T_IEEE_F32LE);
    f.dataset("/i32", {3}, {1.0, 2.0, 3.0}, H5T_STD_I32LE);
    f.dataset("/grid", {2, 2}, {1.0, 2.0, 3.0, 4.0});
    f.number_attribute("/", "step", {std::nan("")});
    f.number_attribute("/", "count", {7.0}, false, H5T_STD_I64LE);
  }
  H5Reader r(path);
  EXPECT_EQ(r.read_exact("/f64"), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_THAT(error_of([&] { r.read_exact("/f32"); }), ::testing::HasSubstr("4 bytes each"));
  EXPECT_THAT(error_of([&] { r.read_exact("/i32"); }), ::testing::HasSubstr("an integer"));
  EXPECT_THAT(error_of([&] { r.read_exact("/grid"); }), ::testing::HasSubstr("2 × 2"));
  EXPECT_EQ(r.read_series("/f32"), (std::vector<double>{1.0, 2.0, 3.0}));  // other readers convert
  EXPECT_EQ(r.read_series("/i32"), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_THAT(error_of([&] { r.integer_attribute("/", "step"); }), ::testing::HasSubstr("allowed: one integer"));
  EXPECT_EQ(r.integer_attribute("/", "count"), 7);
  fs::remove_all(path.parent_path());
}

// A file of a few KB may declare any size: the reader checks it before allocating.
TEST(HDF5, ADatasetLargerThanTheMemoryLimitIsRefusedBeforeItIsRead) {
  const auto path = scratch("huge.h5");
  { h5fixture::File(path).dataset("/surface/height", {200000, 200000}, {}); }
  EXPECT_LT(fs::file_size(path), 10000u);
  H5Reader r(path);
  EXPECT_THAT(error_of([&] { r.read_series("/surface/height"); }),
              ::testing::AllOf(::testing::HasSubstr("'/surface/height' (200000 × 200000 values) needs 298 GiB"),
                               ::testing::HasSubstr("this process may use")));
  fs::remove_all(path.parent_path());
}

TEST(HDF5, AnImageInMemoryReadsAsTheFile) {
  const auto path = scratch("image.h5");
  {
    H5Writer w(path);
    w.write_series("/a", std::vector<double>{1.0, 2.0});
    w.commit();
  }
  const std::string bytes = [&] {
    std::stringstream ss;
    ss << std::ifstream(path, std::ios::binary).rdbuf();
    return ss.str();
  }();
  const H5Reader r = H5Reader::from_image(bytes, "image");
  EXPECT_EQ(r.read_series("/a"), (std::vector<double>{1.0, 2.0}));
  EXPECT_THAT(error_of([&] { H5Reader::from_image(bytes.substr(0, 100), "cut"); }),
              ::testing::HasSubstr("cut: not an HDF5 file"));
  fs::remove_all(path.parent_path());
}

// The disk refuses: an OutputError naming the file, and no file under its name.
TEST(HDF5, AWriterIntoAnUnwritableFolderFailsAtOnceNamingIt) {
  EXPECT_THROW(H5Writer("/proc/self/run.h5"), OutputError);
  try {
    H5Writer w("/proc/self/run.h5");
  } catch (const OutputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/proc/self"));
  }
}

// A file found by fuzzing (tests/fuzz) that crashes HDF5 1.10 itself when
// read: a checkpoint whose dataset layout points past the file (an
// out-of-bounds copy in H5Dread). Read through the guard, the read is tried
// in a child process first: the file is refused as damaged and the program
// carries on. An intact file reads as before.
TEST(HDF5, AFileThatCrashesTheHdf5LibraryIsRefusedAsDamaged) {
  const fs::path file = fs::path(WEARSCALE_TEST_DATA) / "hdf5_crash_dataset_read.h5";
  ASSERT_TRUE(fs::exists(file)) << file;
  Checkpointer checkpoints(file, "", {0.0, 0});
  EXPECT_THAT(error_of([&] { checkpoints.load(); }),
              ::testing::HasSubstr("damaged or not what it claims: the HDF5 library"))
      << "crashed (a signal) or, under AddressSanitizer, stopped by its report (exit status 1)";
  const auto path = scratch("intact.h5");
  {
    H5Writer w(path);
    w.write_series("/a", std::vector<double>{1.0});
    w.set_attribute("/", "text", "fine");
    w.commit();
  }
  EXPECT_EQ(H5Reader::guarded(path, [](const H5Reader& r) { return r.string_attribute("/", "text"); }), "fine");
  EXPECT_THAT(error_of([&] { H5Reader::guarded(path, [](const H5Reader& r) { return r.read_series("/b"); }); }),
              ::testing::HasSubstr("no dataset '/b'"))
      << "an ordinary error of the read is reported as such";
  fs::remove_all(path.parent_path());
}
