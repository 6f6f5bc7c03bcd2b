#include "wearscale/tribometer/adaptive_wear.hpp"

#include <arkode/arkode_arkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kSolver = "tribometer/adaptive (ARKODE TR-BDF2)";

// What ARKODE's callbacks need: the model, the materials frozen over the
// step (per cell, 1: the oxide), the error weights' reference state, and an
// exception thrown inside a callback (ARKODE is C: it cannot carry one).
struct Data {
  PinOnDisc* model = nullptr;
  std::vector<double> y0;  // the unworn state: tolerances are relative to what has worn
  std::vector<double> atol;
  double rtol = 0.0;
  std::vector<char> frozen;
  bool freeze = false;     // materials per column, switched at the roots (unless the tilt enters the layer test)
  std::vector<double> a, z, rate;
  PinOnDiscSample sample;
  std::string error;   // from a callback
  std::string arkode;  // ARKODE's last error message
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

// Error weights 1/(rtol |y − y0| + atol): relative to the worn depth, not to
// the pin's height above its summit (up to R − √(R² − L²/2) at the corners).
int weights(N_Vector y, N_Vector w, void* user) {
  auto* d = static_cast<Data*>(user);
  const double* Y = N_VGetArrayPointer(y);
  double* W = N_VGetArrayPointer(w);
  for (std::size_t k = 0; k < d->y0.size(); ++k) W[k] = 1.0 / (d->rtol * std::abs(Y[k] - d->y0[k]) + d->atol[k]);
  return 0;
}

// Root k: column k's worn depth reaches h_layer.
int layer_roots(sunrealtype, N_Vector y, sunrealtype* g, void* user) {
  auto* d = static_cast<Data*>(user);
  d->model->depth_below_layer(N_VGetArrayPointer(y), g);
  return 0;
}

// The nonlinear solver of the implicit stages: ARKODE's stage equation is
// z = z_pred + z_cor with z_cor − γ f(z) − sdata = 0, i.e. z = a + γ f(z)
// with a = z_pred + sdata; PinOnDisc::solve_stage solves it exactly.
SUNNonlinearSolver_Type nls_type(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_ROOTFIND; }

int nls_solve(SUNNonlinearSolver nls, N_Vector, N_Vector correction, N_Vector, sunrealtype, sunbooleantype,
              void* arkode_mem) {
  auto* d = static_cast<Data*>(nls->content);
  sunrealtype s = 0.0, gamma = 0.0;
  N_Vector zpred = nullptr, z = nullptr, fi = nullptr, sdata = nullptr;
  void* user = nullptr;
  if (ARKStepGetNonlinearSystemData(arkode_mem, &s, &zpred, &z, &fi, &gamma, &sdata, &user) != ARK_SUCCESS) return -1;
  const double* zp = N_VGetArrayPointer(zpred);
  const double* sd = N_VGetArrayPointer(sdata);
  double* zc = N_VGetArrayPointer(correction);
  for (std::size_t k = 0; k < d->a.size(); ++k) d->a[k] = zp[k] + sd[k];
  try {
    d->model->solve_stage(s, d->a.data(), gamma, d->z.data(), d->rate.data(), d->sample,
                          d->freeze ? &d->frozen : nullptr);
  } catch (const StageNotSolved& e) {
    d->error = e.what();
    return SUN_NLS_CONV_RECVR;  // ARKODE retries with a shorter step
  } catch (const std::exception& e) {
    d->error = e.what();
    return -1;  // unrecoverable
  }
  d->error.clear();
  for (std::size_t k = 0; k < d->a.size(); ++k) zc[k] = d->z[k] - zp[k];
  return SUN_NLS_SUCCESS;
}

int nls_set_sys(SUNNonlinearSolver, SUNNonlinSolSysFn) { return SUN_NLS_SUCCESS; }
int nls_set_test(SUNNonlinearSolver, SUNNonlinSolConvTestFn, void*) { return SUN_NLS_SUCCESS; }
int nls_set_iters(SUNNonlinearSolver, int) { return SUN_NLS_SUCCESS; }
int nls_iters(SUNNonlinearSolver, long* n) {
  *n = 1;
  return SUN_NLS_SUCCESS;
}
int nls_current(SUNNonlinearSolver, int* n) {
  *n = 0;
  return SUN_NLS_SUCCESS;
}
int nls_fails(SUNNonlinearSolver, long* n) {
  *n = 0;
  return SUN_NLS_SUCCESS;
}

// ARKODE's own messages go into the error we raise, not to stderr.
void arkode_message(int code, const char*, const char* function, char* message, void* user) {
  if (code < 0) {
    auto* d = static_cast<Data*>(user);
    d->arkode = fmt::format("{}: {}", function, message);
  }
}

void check(int flag, const char* call, double s, const Data& d) {
  if (flag < 0)
    throw NumericalError(kSolver, 0, call,
                         fmt::format("ARKODE flag {} at s = {:g} m{}", flag, s, d.error.empty() ? "" : ": " + d.error));
}
}  // namespace

double adaptive_step_cap(const PinOnDiscSetup& setup, const AdaptiveOptions& opt) {
  double cap = opt.max_step;
  if (setup.nonplanar_slope > 0.0) cap = std::min(cap, setup.tilt_period() / opt.steps_per_period);
  if (setup.track == Track::Resolved) cap = std::min(cap, setup.size / static_cast<double>(setup.grid));  // one cell
  return cap;
}

void run_adaptive(PinOnDisc& model, const AdaptiveOptions& opt,
                  const std::function<void(const PinOnDiscSample&)>& observe,
                  const std::function<void(const AdaptiveStatus&)>& after_step) {
  const auto& setup = model.setup();
  if (!(opt.relative_tolerance > 0.0 && opt.relative_tolerance < 1.0) || !(opt.absolute_tolerance > 0.0) ||
      !(opt.max_step > 0.0) || opt.steps_per_period < 1)
    throw InputError(fmt::format("pin-on-disc: adaptive options rtol = {:g}, atol = {:g}, max_step = {:g} are not "
                                 "allowed; allowed: 0 < rtol < 1, atol > 0, max_step > 0",
                                 opt.relative_tolerance, opt.absolute_tolerance, opt.max_step));
  const double s0 = model.distance(), s_end = setup.distance;
  const std::size_t size = model.state_size(), np = model.pin_surface().size(), nd = model.disc_profile().size();
  const auto n = static_cast<sunindextype>(size);
  const double h = setup.layer_thickness;
  // Roots: the averaged track's columns reaching the substrate (on a resolved
  // track the window's cells change material as the strip slides under them:
  // their materials are frozen over each step, at most one cell long).
  const bool roots = setup.track == Track::Averaged && !setup.tilt_in_layer_test() && h > 0.0 && std::isfinite(h);

  Data data;
  data.model = &model;
  data.y0 = model.initial_state();
  data.rtol = opt.relative_tolerance;
  data.atol.assign(size, opt.absolute_tolerance);
  data.atol[np + nd] = data.atol[np + nd + 1] = opt.absolute_tolerance * model.grid().cell_area();
  data.freeze = !setup.tilt_in_layer_test();
  data.a.resize(size);
  data.z.resize(size);
  data.rate.resize(size);

  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create", s0, data);
  std::unique_ptr<_SUNContext, void (*)(SUNContext)> ctx_guard(ctx, [](SUNContext c) { SUNContext_Free(&c); });
  N_Vector y = N_VNew_Serial(n, ctx);
  std::unique_ptr<_generic_N_Vector, void (*)(N_Vector)> y_guard(y, N_VDestroy);
  const auto start = model.state();
  std::copy(start.begin(), start.end(), N_VGetArrayPointer(y));
  SUNNonlinearSolver nls = SUNNonlinSolNewEmpty(ctx);
  if (nls == nullptr) throw NumericalError(kSolver, 0, "SUNNonlinSolNewEmpty", "out of memory");
  std::unique_ptr<_generic_SUNNonlinearSolver, void (*)(SUNNonlinearSolver)> nls_guard(nls, SUNNonlinSolFreeEmpty);
  nls->ops->gettype = nls_type;
  nls->ops->solve = nls_solve;
  nls->ops->setsysfn = nls_set_sys;
  nls->ops->setctestfn = nls_set_test;
  nls->ops->setmaxiters = nls_set_iters;
  nls->ops->getnumiters = nls_iters;
  nls->ops->getcuriter = nls_current;
  nls->ops->getnumconvfails = nls_fails;
  nls->content = &data;
  const double cap = adaptive_step_cap(setup, opt);

  // One integrator per segment of `restart_every` steps, started from the
  // state, distance and proposed step where the last one ended: a run resumed
  // from a checkpoint taken at a segment's end continues exactly as the
  // uninterrupted run does (the rate at that state is in the model's checkpoint).
  using Memory = std::unique_ptr<void, void (*)(void*)>;
  auto configure = [&](void* mem, double s_from, double h0) {
    check(ARKStepSetErrHandlerFn(mem, arkode_message, &data), "ARKStepSetErrHandlerFn", s_from, data);
    check(ARKStepWFtolerances(mem, weights), "ARKStepWFtolerances", s_from, data);
    check(ARKStepSetTableNum(mem, ARKODE_TRBDF2_3_3_2, ARKODE_ERK_NONE), "ARKStepSetTableNum", s_from, data);
    check(ARKStepSetNonlinearSolver(mem, nls), "ARKStepSetNonlinearSolver", s_from, data);
    check(ARKStepSetDeduceImplicitRhs(mem, SUNTRUE), "ARKStepSetDeduceImplicitRhs", s_from, data);
    check(ARKStepSetUserData(mem, &data), "ARKStepSetUserData", s_from, data);
    check(ARKStepSetMaxStep(mem, cap), "ARKStepSetMaxStep", s_from, data);
    check(ARKStepSetInitStep(mem, std::min(h0, cap)), "ARKStepSetInitStep", s_from, data);
    check(ARKStepSetStopTime(mem, s_end), "ARKStepSetStopTime", s_from, data);
    check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps", s_from, data);
    // The step follows the error estimate from step to step: an I controller
    // (h ∝ err^(−1/3)) with no band of "keep the step" ratios. ARKODE's default
    // PID controller keeps h while the proposed ratio is within [1, 1.5], and
    // the wear's error, 5-20 times below the tolerance, stayed there: twice the
    // steps on the main job (2 441 solves against 1 290, the same figures
    // within 0.01 %, docs/pin_on_disc.md).
    check(ARKStepSetAdaptivityMethod(mem, 2, SUNTRUE, SUNFALSE, nullptr), "ARKStepSetAdaptivityMethod", s_from, data);
    check(ARKStepSetFixedStepBounds(mem, 1.0, 1.0), "ARKStepSetFixedStepBounds", s_from, data);
    if (roots) check(ARKStepRootInit(mem, static_cast<int>(nd), layer_roots), "ARKStepRootInit", s_from, data);
  };
  auto start_segment = [&](double s_from, double h0) {
    void* mem = ARKStepCreate(nullptr, rhs, s_from, y, ctx);
    if (mem == nullptr) throw NumericalError(kSolver, 0, "ARKStepCreate", data.error.empty() ? "out of memory" : data.error);
    Memory guard(mem, [](void* m) { ARKStepFree(&m); });
    configure(mem, s_from, h0);
    return guard;
  };
  auto freeze = [&](double s) {
    if (data.freeze) data.frozen = model.layer_cells(s, N_VGetArrayPointer(y));
  };

  PinOnDiscSample sample;
  std::vector<double> dyds(size);
  if (opt.observe_start) {
    model.derivative(s0, N_VGetArrayPointer(y), dyds.data(), sample);
    observe(sample);
  }
  double s = s0;
  AdaptiveStatus status;
  status.steps = opt.steps_done;
  status.next_step = opt.initial_step > 0.0 ? opt.initial_step : setup.velocity * setup.time_step;
  const long every = std::max(1L, opt.restart_every);
  std::vector<int> found(nd);
  while (s < s_end * (1.0 - 1e-12)) {
    Memory mem = start_segment(s, status.next_step);
    do {
      freeze(s);
      const int flag = ARKStepEvolve(mem.get(), s_end, y, &s, ARK_ONE_STEP);
      if (flag < 0)
        throw NumericalError(kSolver, status.steps, "ARKStepEvolve",
                             fmt::format("ARKODE flag {} at s = {:g} m{}{}", flag, s,
                                         data.arkode.empty() ? "" : " (" + data.arkode + ")",
                                         data.error.empty() ? "" : ": " + data.error));
      double* Y = N_VGetArrayPointer(y);
      for (std::size_t k = 0; k < size; ++k)
        if (!std::isfinite(Y[k]))
          throw NumericalError(kSolver, status.steps, "state", fmt::format("component {} is {} at s = {:g} m", k, Y[k], s));
      if (flag == ARK_ROOT_RETURN) {
        // A column reached the substrate inside the step: restart there (the
        // part of the step beyond it wore that column as oxide). The
        // interpolated depth is h_layer to rounding; set it so, on the substrate.
        check(ARKStepGetRootInfo(mem.get(), found.data()), "ARKStepGetRootInfo", s, data);
        for (std::size_t i = 0; i < nd; ++i)
          if (found[i] > 0 && std::abs(-Y[np + i] - h) <= 1e-9 * h) Y[np + i] = -h;
        double last = 0.0;
        check(ARKStepGetLastStep(mem.get(), &last), "ARKStepGetLastStep", s, data);
        check(ARKStepSetInitStep(mem.get(), std::min(last, cap)), "ARKStepSetInitStep", s, data);
        check(ARKStepReset(mem.get(), s, y), "ARKStepReset", s, data);
        check(ARKStepSetStopTime(mem.get(), s_end), "ARKStepSetStopTime", s, data);  // a reset clears it
        model.set_state(Y, s);
        model.derivative(s, Y, dyds.data(), sample);
        observe(sample);
        continue;
      }
      ++status.steps;
      model.set_state(Y, s);
      model.derivative(s, Y, dyds.data(), sample);  // the last stage's solution: no solve
      observe(sample);
      check(ARKStepGetCurrentStep(mem.get(), &status.next_step), "ARKStepGetCurrentStep", s, data);
      status.segment_end = status.steps % every == 0;
      if (after_step) after_step(status);
    } while (!status.segment_end && s < s_end * (1.0 - 1e-12));
  }
  model.set_state(N_VGetArrayPointer(y), s);
}

}  // namespace wearscale::tribometer
