#include "wearscale/core/roots.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <memory>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale {

double find_root(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                 const std::string& solver) {
  auto call = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  gsl_function gf{call, const_cast<std::function<double(double)>*>(&f)};
  std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> s(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                   gsl_root_fsolver_free);
  gsl_error_handler_t* old = gsl_set_error_handler_off();  // report through exceptions, never abort()
  const int set = gsl_root_fsolver_set(s.get(), &gf, lo, hi);
  int status = set;
  int it = 0;
  for (; status == GSL_SUCCESS || status == GSL_CONTINUE; ++it) {
    if (it >= 200) break;
    if (gsl_root_fsolver_iterate(s.get()) != GSL_SUCCESS) break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s.get()), gsl_root_fsolver_x_upper(s.get()), tolerance,
                                    1e-13);
    if (status == GSL_SUCCESS) break;
  }
  gsl_set_error_handler(old);
  if (set != GSL_SUCCESS)
    throw NumericalError(solver, 0, "root bracket", fmt::format("f does not change sign on [{:g}, {:g}]", lo, hi));
  if (status != GSL_SUCCESS) throw NumericalError(solver, it, "root", "Brent's method did not converge");
  return gsl_root_fsolver_root(s.get());
}

}  // namespace wearscale
