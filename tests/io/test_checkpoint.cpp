// Checkpoints: what a solver saves reads back bit for bit, a checkpoint of
// another case is refused naming the key that differs, saving follows the
// policy, and a pending SIGINT saves then stops the loop. Also the clean-stop
// flag itself and the removal of files left by killed processes. A damaged
// checkpoint (flipped bytes, other types, an older format) is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <cmath>
#include <fstream>
#include <sstream>
#include <limits>

#include <sys/wait.h>
#include <unistd.h>

#include "h5_fixture.hpp"
#include "input_error_of.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir dir("wearscale_checkpoint_");
  return dir.file(name);
}

const std::string case_a = R"({"scale":{"macro":{"grid":64,"backend":"bem-pin-on-disc"}}})";
const std::string case_b = R"({"scale":{"macro":{"grid":128,"backend":"bem-pin-on-disc"}}})";

CheckpointState sample_state() {
  CheckpointState s;
  const std::vector<double> odd = {0.1, -0.0, 5e-324, std::numeric_limits<double>::max(), 1.0 / 3.0};
  s.put("odd", odd);
  s.put("distance", 0.012345678901234567);
  s.put("empty", std::vector<double>{});
  s.put_text("integrator", "explicit");
  s.put_text("multi", "line one\nline two");
  return s;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST(Checkpoint, StatesReadBackBitForBit) {
  const auto file = scratch("roundtrip.h5");
  Checkpointer writer(file, case_a, {0.0, 1});
  CheckpointState s = sample_state();
  s.step = 42;
  writer.save("macro/bem-pin-on-disc", s);
  writer.save("nano/dem", CheckpointState{});  // a second owner keeps the first's state
  EXPECT_EQ(writer.saves(), 2);

  Checkpointer reader(file, case_a, {0.0, 1});
  reader.load();
  const CheckpointState* r = reader.restored("macro/bem-pin-on-disc");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->step, 42);
  ASSERT_EQ(r->array("odd").size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_TRUE(same_bits(r->array("odd")[k], s.array("odd")[k])) << k;
  EXPECT_TRUE(same_bits(r->scalar("distance"), 0.012345678901234567));
  EXPECT_TRUE(r->array("empty").empty());
  EXPECT_EQ(r->text("integrator"), "explicit");
  EXPECT_EQ(r->text("multi"), "line one\nline two");
  EXPECT_NE(reader.restored("nano/dem"), nullptr);
  EXPECT_EQ(reader.restored("macro/other"), nullptr);
  EXPECT_THAT(input_error_of([&] { (void)r->array("missing"); }), HasSubstr("no entry 'missing'"));
  EXPECT_THAT(input_error_of([&] { (void)r->scalar("odd"); }), HasSubstr("5 values"));
}

TEST(Checkpoint, ACheckpointOfAnotherCaseIsRefusedNamingTheKey) {
  const auto file = scratch("other_case.h5");
  Checkpointer(file, case_a, {0.0, 1}).save("macro/x", CheckpointState{});
  Checkpointer reader(file, case_b, {0.0, 1});
  const auto msg = input_error_of([&] { reader.load(); });
  EXPECT_THAT(msg, HasSubstr("other parameters"));
  EXPECT_THAT(msg, HasSubstr("key 'scale.macro.grid' was 64, is now 128"));
}

TEST(Checkpoint, AFileThatIsNotACheckpointIsRefused) {
  const auto file = scratch("not_a_checkpoint.h5");
  std::ofstream(file) << "just text\n";
  EXPECT_THAT(input_error_of([&] { Checkpointer(file, case_a, {}).load(); }), HasSubstr("not an HDF5 file"));
  EXPECT_THAT(input_error_of([&] { Checkpointer(scratch("absent.h5"), case_a, {}).load(); }), HasSubstr("no such file"));
}

TEST(Checkpoint, SavesEveryNStepsAndNotInBetween) {
  const auto file = scratch("policy.h5");
  Checkpointer c(file, case_a, {0.0, 10});  // by steps only
  int made = 0;
  auto make = [&] {
    ++made;
    return CheckpointState{};
  };
  for (long step = 1; step <= 35; ++step) c.at_step("macro/x", step, make);
  EXPECT_EQ(made, 3);  // at steps 10, 20, 30
  EXPECT_EQ(c.saves(), 3);
  Checkpointer reader(file, case_a, {});
  reader.load();
  EXPECT_EQ(reader.restored("macro/x")->step, 30);
  c.discard();
  EXPECT_FALSE(fs::exists(file));
}

TEST(Checkpoint, APendingInterruptSavesThenStopsTheLoop) {
  const auto file = scratch("interrupt.h5");
  Checkpointer c(file, case_a, {0.0, 1000});
  request_interrupt(SIGINT);
  try {
    c.at_step("macro/x", 7, [] { return CheckpointState{}; });
    FAIL() << "expected Interrupted";
  } catch (const Interrupted& e) {
    EXPECT_THAT(e.what(), HasSubstr("interrupted by SIGINT"));
  }
  clear_interrupt();
  Checkpointer reader(file, case_a, {});
  reader.load();
  EXPECT_EQ(reader.restored("macro/x")->step, 7);

  // Without checkpoints the loop still stops, and nothing is written.
  Checkpointer none = Checkpointer::disabled();
  request_interrupt(SIGTERM);
  EXPECT_THROW(none.at_step("macro/x", 1, [] { return CheckpointState{}; }), Interrupted);
  clear_interrupt();
  EXPECT_NO_THROW(none.at_step("macro/x", 2, [] { return CheckpointState{}; }));
  EXPECT_EQ(none.saves(), 0);
}

TEST(Interrupt, SigintRaisesTheFlagInsteadOfKillingTheProcess) {
  install_interrupt_handlers();
  clear_interrupt();
  EXPECT_FALSE(interrupt_requested());
  EXPECT_NO_THROW(throw_if_interrupted("loop"));
  std::raise(SIGINT);  // the process carries on
  EXPECT_TRUE(interrupt_requested());
  EXPECT_EQ(interrupt_signal(), SIGINT);
  EXPECT_THROW(throw_if_interrupted("loop"), Interrupted);
  clear_interrupt();
}

TEST(AtomicFile, FilesLeftByDeadProcessesAreRemovedOthersKept) {
  const auto dir = scratch("stale").parent_path() / "stale";
  fs::create_directories(dir);
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);  // a process that no longer exists
  const auto dead = dir / (".run.h5.partial-" + std::to_string(child));
  const auto ours = partial_path(dir / "friction.csv");
  std::ofstream(dead) << "half a file";
  std::ofstream(ours) << "being written";
  std::ofstream(dir / "run.h5") << "complete";
  EXPECT_EQ(remove_stale_partials(dir), 1u);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(ours));
  EXPECT_TRUE(fs::exists(dir / "run.h5"));
}

TEST(Checkpoint, CaseDifferencesAreDescribedByKey) {
  EXPECT_EQ(describe_case_difference(case_a, case_a), "");
  EXPECT_EQ(describe_case_difference(R"({"a":{"b":1}})", R"({"a":{"b":1,"c":"x"}})"), "key 'a.c' was absent, is now x");
  EXPECT_EQ(describe_case_difference("not json", case_a), "");
}

// ---------------------------------------------------------------------------
// Damaged checkpoints are refused, never resumed from.

namespace {
std::string bytes_of(const fs::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p, std::ios::binary).rdbuf();
  return ss.str();
}

// A file laid out as a checkpoint of one owner "o" with one array, whose
// attributes and dataset type the test chooses.
void fake_checkpoint(const fs::path& file, const std::string& format, hid_t array_type, double step) {
  h5fixture::File f(file);
  f.group("/owners/o");
  f.string_attribute("/", "format", format);
  f.string_attribute("/", "fingerprint", case_a);
  f.string_attribute("/", "fftw_wisdom", "");
  f.string_attribute("/", "owners", "o");
  f.string_attribute("/", "sha256", "0");
  f.number_attribute("/owners/o", "step", {step}, false, std::isnan(step) ? H5T_IEEE_F64LE : H5T_STD_I64LE);
  f.string_attribute("/owners/o", "arrays", "x");
  f.string_attribute("/owners/o", "texts", "");
  f.dataset("/owners/o/a0", {3}, {1.0, 2.0, 3.0}, array_type);
}
}  // namespace

TEST(Checkpoint, FlippedBytesInItsDataAreDetectedByTheChecksum) {
  const auto file = scratch("flipped.h5");
  Checkpointer writer(file, case_a, {0.0, 1});
  CheckpointState s;
  s.put("surface", std::vector<double>(512, 0.25));  // stored as is: 512 × the bytes of 0.25
  writer.save("o", s);
  std::string bytes = bytes_of(file);
  const double quarter = 0.25;
  const std::string pattern(reinterpret_cast<const char*>(&quarter), sizeof quarter);
  const auto at = bytes.find(pattern + pattern + pattern + pattern);
  ASSERT_NE(at, std::string::npos);
  for (std::size_t k = 0; k < 64; ++k) bytes[at + 100 + k] = static_cast<char>(~bytes[at + 100 + k]);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  Checkpointer reader(file, case_a, {0.0, 1});
  EXPECT_THAT(input_error_of([&] { reader.load(); }), HasSubstr("the checkpoint is damaged"));
  EXPECT_EQ(reader.restored("o"), nullptr);
}

TEST(Checkpoint, AnyByteFlippedAnywhereIsRefusedOrIgnoredNeverRestoredWrong) {
  const auto file = scratch("every.h5");
  {
    Checkpointer writer(file, case_a, {0.0, 1});
    CheckpointState s;
    s.put("x", std::vector<double>{1.0, 2.0, 3.0});
    s.put_text("t", "explicit");
    s.step = 7;
    writer.save("o", s);
  }
  const std::string good = bytes_of(file);
  std::size_t refused = 0;
  for (std::size_t k = 0; k < good.size(); k += 17) {  // every 17th byte: a few hundred files
    std::string bad = good;
    bad[k] = static_cast<char>(bad[k] ^ 0x5a);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bad;
    Checkpointer reader(file, case_a, {0.0, 1});
    try {
      reader.load();
      // Unused bytes (padding, free space): the state must then be exactly what was saved.
      const CheckpointState* r = reader.restored("o");
      ASSERT_NE(r, nullptr) << k;
      EXPECT_EQ(r->array("x"), (std::vector<double>{1.0, 2.0, 3.0})) << k;
      EXPECT_EQ(r->text("t"), "explicit") << k;
      EXPECT_EQ(r->step, 7) << k;
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 0u);
}

TEST(Checkpoint, A32BitFloatArrayANanStepAndAnOlderFormatAreRefused) {
  const auto file = scratch("fake.h5");
  fake_checkpoint(file, "wearscale checkpoint 2", H5T_IEEE_F32LE, 3.0);
  EXPECT_THAT(input_error_of([&] { Checkpointer(file, case_a, {0.0, 1}).load(); }),
              HasSubstr("expected a series of 64-bit floats"));
  fs::remove(file);
  fake_checkpoint(file, "wearscale checkpoint 2", H5T_IEEE_F64LE, std::nan(""));
  EXPECT_THAT(input_error_of([&] { Checkpointer(file, case_a, {0.0, 1}).load(); }),
              HasSubstr("attribute 'step' on '/owners/o' is a floating-point number; allowed: one integer"));
  fs::remove(file);
  fake_checkpoint(file, "wearscale checkpoint 1", H5T_IEEE_F64LE, 3.0);
  EXPECT_THAT(input_error_of([&] { Checkpointer(file, case_a, {0.0, 1}).load(); }),
              HasSubstr("a checkpoint of format 'wearscale checkpoint 1', written by another version"));
  fs::remove(file);
  fake_checkpoint(file, "wearscale checkpoint 2", H5T_IEEE_F64LE, 3.0);  // well-formed, but the checksum is not its own
  EXPECT_THAT(input_error_of([&] { Checkpointer(file, case_a, {0.0, 1}).load(); }), HasSubstr("damaged"));
}
