#include "wearscale/tribometer/adaptive_wear.hpp"

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kSolver = "tribometer/adaptive (ARKODE ERK)";
constexpr double kGrowth = 20.0;  // largest step growth from one step to the next (ARKODE's default)

struct Data {
  PinOnDisc* model;
  PinOnDiscSample sample;
  std::string error;  // an exception thrown inside the right-hand side
};

int rhs(sunrealtype s, N_Vector y, N_Vector dyds, void* user) {
  auto* d = static_cast<Data*>(user);
  try {
    d->model->derivative(s, N_VGetArrayPointer(y), N_VGetArrayPointer(dyds), d->sample);
  } catch (const std::exception& e) {
    d->error = e.what();
    return -1;  // unrecoverable: ARKODE stops and returns ARK_RHSFUNC_FAIL
  }
  return 0;
}

void check(int flag, const char* call, double s) {
  if (flag < 0) throw NumericalError(kSolver, 0, call, fmt::format("ARKODE flag {} at s = {:g} m", flag, s));
}
}  // namespace

void run_adaptive(PinOnDisc& model, const AdaptiveOptions& opt,
                  const std::function<void(const PinOnDiscSample&)>& observe,
                  const std::function<void(const AdaptiveStatus&)>& after_step) {
  const auto& setup = model.setup();
  const double s0 = model.distance(), s_end = setup.distance;
  const auto n = static_cast<sunindextype>(model.state_size());

  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create", s0);
  std::unique_ptr<_SUNContext, void (*)(SUNContext)> ctx_guard(ctx, [](SUNContext c) { SUNContext_Free(&c); });
  N_Vector y = N_VNew_Serial(n, ctx);
  std::unique_ptr<_generic_N_Vector, void (*)(N_Vector)> y_guard(y, N_VDestroy);
  N_Vector weights = N_VNew_Serial(n, ctx);
  std::unique_ptr<_generic_N_Vector, void (*)(N_Vector)> w_guard(weights, N_VDestroy);
  const auto start = model.state();
  std::copy(start.begin(), start.end(), N_VGetArrayPointer(y));

  Data data{&model, {}, {}};
  // Absolute tolerances per component: heights in m; volumes in m³ scaled by the cell area.
  double* w = N_VGetArrayPointer(weights);
  const double cell = model.grid().cell_area();
  for (sunindextype k = 0; k < n; ++k) w[k] = opt.absolute_tolerance;
  w[n - 2] = w[n - 1] = opt.absolute_tolerance * cell;

  // One integrator per segment of `restart_every` steps, started from the
  // state, distance and proposed step where the last one ended: a run resumed
  // from a checkpoint taken at a segment's end continues exactly as the
  // uninterrupted run does.
  using Memory = std::unique_ptr<void, void (*)(void*)>;
  auto start_segment = [&](double s0_segment, double h0) {
    void* mem = ERKStepCreate(rhs, s0_segment, y, ctx);
    if (mem == nullptr) throw NumericalError(kSolver, 0, "ERKStepCreate", "out of memory");
    Memory guard(mem, [](void* m) { ERKStepFree(&m); });
    check(ERKStepSVtolerances(mem, opt.relative_tolerance, weights), "ERKStepSVtolerances", s0_segment);
    check(ERKStepSetTableNum(mem, ARKODE_HEUN_EULER_2_1_2), "ERKStepSetTableNum", s0_segment);
    check(ERKStepSetUserData(mem, &data), "ERKStepSetUserData", s0_segment);
    check(ERKStepSetMaxStep(mem, opt.max_step), "ERKStepSetMaxStep", s0_segment);
    check(ERKStepSetInitStep(mem, h0), "ERKStepSetInitStep", s0_segment);
    check(ERKStepSetMaxFirstGrowth(mem, kGrowth), "ERKStepSetMaxFirstGrowth", s0_segment);  // as on any later step
    check(ERKStepSetMaxGrowth(mem, kGrowth), "ERKStepSetMaxGrowth", s0_segment);
    check(ERKStepSetStopTime(mem, s_end), "ERKStepSetStopTime", s0_segment);
    check(ERKStepSetMaxNumSteps(mem, 1000000), "ERKStepSetMaxNumSteps", s0_segment);
    return guard;
  };

  PinOnDiscSample sample;
  std::vector<double> dyds(static_cast<std::size_t>(n));
  if (opt.observe_start) {
    model.derivative(s0, N_VGetArrayPointer(y), dyds.data(), sample);
    observe(sample);
  }
  double s = s0;
  AdaptiveStatus status;
  status.steps = opt.steps_done;
  status.next_step = opt.initial_step > 0.0 ? opt.initial_step : setup.velocity * setup.time_step;
  const long every = std::max(1L, opt.restart_every);
  while (s < s_end * (1.0 - 1e-12)) {
    Memory mem = start_segment(s, status.next_step);
    do {
      const int flag = ERKStepEvolve(mem.get(), s_end, y, &s, ARK_ONE_STEP);
      if (flag < 0)
        throw NumericalError(kSolver, status.steps, "ERKStepEvolve",
                             fmt::format("ARKODE flag {} at s = {:g} m{}", flag, s, data.error.empty() ? "" : ": " + data.error));
      ++status.steps;
      model.derivative(s, N_VGetArrayPointer(y), dyds.data(), sample);  // the state after the step
      for (sunindextype k = 0; k < n; ++k)
        if (!std::isfinite(N_VGetArrayPointer(y)[k]))
          throw NumericalError(kSolver, status.steps, "state", fmt::format("component {} is {} at s = {:g} m", k,
                                                                           N_VGetArrayPointer(y)[k], s));
      observe(sample);
      check(ERKStepGetCurrentStep(mem.get(), &status.next_step), "ERKStepGetCurrentStep", s);
      status.segment_end = status.steps % every == 0;
      if (after_step) after_step(status);
    } while (!status.segment_end && s < s_end * (1.0 - 1e-12));
  }
  model.set_state(N_VGetArrayPointer(y), s);
}

}  // namespace wearscale::tribometer
