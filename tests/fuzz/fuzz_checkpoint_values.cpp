// Fuzzes the values of a checkpoint, not its bytes: a real pin-on-disc state
// (an 8 × 8 run after a few steps) with entries replaced by values the input
// chooses (NaN, infinities, negatives, huge numbers, bit patterns), its
// checksum intact as a program that knows the format would leave it. Either
// restore() refuses it with InputError, or the restored state is within the
// bounds of a computed one (state_problem() is empty) and the run goes on
// from it to its end without a hang, a crash or an unphysical sample
// (a NumericalError is a failure said as one, an InputError such as a contact
// grown to the window's edge a refusal said as one). The samples' check
// (sample_problem) is fuzzed alike.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"
#include "wearscale/tribometer/state_bounds.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {

PinOnDiscSetup setup() {
  PinOnDiscSetup s;
  s.grid = 8;
  s.size = 2e-3;
  s.distance = 8e-3 * 0.02 * 6;  // six steps
  s.layer_thickness = 1e-9;       // worn through within them: both interfaces meet
  s.on_layer = {"SiO2/SiO2", "SiO2", 8.5e9, 0.837};
  s.on_substrate = {"SiO2/Si", "Si", 10.6e9, 0.1415};
  return s;
}

// The state after three steps, saved once.
const CheckpointState& saved() {
  static const CheckpointState state = [] {
    PinOnDisc model(setup());
    for (int k = 0; k < 3; ++k) model.step();
    CheckpointState st;
    model.save(st);
    return st;
  }();
  return state;
}

double value_of(const std::uint8_t* data, std::size_t size, std::size_t& at) {
  const std::uint8_t kind = at < size ? data[at++] : 0;
  static const double special[] = {std::nan(""), HUGE_VAL, -HUGE_VAL, -1.0, 0.0, 1e300, -1e-300, 0.5, 1e7, 2.0};
  if (kind % 2 == 0) return special[(kind / 2) % 10];
  std::uint64_t bits = 0;
  for (int b = 0; b < 8; ++b) bits = (bits << 8) | (at < size ? data[at++] : 0);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  CheckpointState state = saved();
  std::vector<std::string> names;
  for (const auto& [name, values] : state.arrays()) names.push_back(name);
  std::size_t at = 0;
  const unsigned changes = size > 0 ? 1 + data[at++] % 4 : 0;
  for (unsigned c = 0; c < changes && at < size; ++c) {
    const std::string& name = names[data[at++] % names.size()];
    std::vector<double> values = state.array(name);
    if (values.empty()) continue;
    const std::size_t index = (at < size ? data[at++] : 0) % values.size();
    values[index] = value_of(data, size, at);
    state.put(name, values);
  }
  PinOnDisc model(setup());
  try {
    model.restore(state);
  } catch (const InputError&) {
    return 0;  // refused: the outcome for a state no run reaches
  }
  if (!model.state_problem().empty()) std::abort();  // restored although outside the bounds
  try {
    model.run([](const PinOnDiscSample& x) {
      if (!sample_problem(x, setup()).empty()) std::abort();
    });
  } catch (const NumericalError&) {
  } catch (const InputError&) {
    // Refused on the way, said as one: a restored pin worn within its bounds can still carry the contact to
    // the edge of the window, which the run refuses (a larger size is needed) rather than answer.
  }
  // A sample read back: refused, or within the bounds (never a cast of NaN or 1e300 to an integer).
  PinOnDiscSample x;
  std::size_t more = at;
  x.distance = value_of(data, size, more);
  x.friction = value_of(data, size, more);
  x.pin_wear = value_of(data, size, more);
  (void)sample_problem(x, setup());
  return 0;
}
