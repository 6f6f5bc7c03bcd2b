// wearscale.contact: normal (§2.3.2) and frictional (App. A) BEM contact of a
// rigid surface on an elastic half-space, the stresses below it and Hertz.
// Every solve releases the GIL; result fields are read-only views on the
// solver's storage (valid until its next solve: copy() to keep one).
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/hertz.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"

namespace wearscale::python {

namespace {

using namespace wearscale::bem;

// A stop for a solve running with the GIL released in the interpreter's main
// thread: Ctrl-C (or a Python signal handler that raises) ends it within an
// iteration, as KeyboardInterrupt (the solver throws Interrupted; module.cpp
// translates it). The GIL is taken to ask Python at most ten times a second;
// other threads never see signals, so their solves are not asked.
std::function<bool()> python_signal_stop() {  // called with the GIL held
  const auto main_thread = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  if (PyThread_get_thread_ident() != main_thread) return nullptr;
  return [last = std::chrono::steady_clock::now()]() mutable {
    const auto now = std::chrono::steady_clock::now();
    if (now - last < std::chrono::milliseconds(100)) return false;
    last = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return false;
    PyErr_Clear();
    return true;
  };
}

Boundary boundary_from(const std::string& name) {
  if (name == "periodic") return Boundary::Periodic;
  if (name == "free") return Boundary::Free;
  throw InputError("contact: boundary = '" + name + "'; allowed: periodic | free");
}

ContactMethod method_from(const std::string& name) {
  if (name == "preconditioned") return ContactMethod::PreconditionedCG;
  if (name == "polonsky-keer") return ContactMethod::PolonskyKeer;
  if (name == "two-level") return ContactMethod::TwoLevelCG;
  throw InputError("contact: method = '" + name + "'; allowed: preconditioned | two-level | polonsky-keer");
}

const char* method_name(ContactMethod method) {
  switch (method) {
    case ContactMethod::PreconditionedCG: return "preconditioned";
    case ContactMethod::PolonskyKeer: return "polonsky-keer";
    case ContactMethod::TwoLevelCG: return "two-level";
  }
  return "two-level";
}

// A normal load [N] as the mean pressure on the window (the CLI's normal_load, --load).
double normal_pressure_of(double load, const Grid2D& g, const char* where) {
  if (!(load >= 0.0) || !std::isfinite(load))
    throw InputError(fmt::format("{}: load = {} N; allowed: a finite force >= 0", where, load));
  return load / g.area();
}

py::dict to_dict(const ContactResult& r) {
  py::dict d;
  d["iterations"] = r.iterations;
  d["error"] = r.error;
  d["mean_pressure_Pa"] = r.mean_pressure;
  d["contact_fraction"] = r.contact_fraction;
  d["interference_m"] = r.interference;
  d["elastic_energy_J"] = r.elastic_energy;
  return d;
}

py::dict to_dict(const FrictionalResult& r) {
  py::dict d;
  d["iterations"] = r.iterations;
  d["bound_updates"] = r.bound_updates;
  d["unsettled_points"] = r.unsettled_points;
  d["error"] = r.error;
  d["normal_error"] = r.normal_error;
  d["tangential_error"] = r.tangential_error;
  d["mean_pressure_Pa"] = r.mean_traction.normal;
  d["mean_traction_x_Pa"] = r.mean_traction.x;
  d["mean_traction_y_Pa"] = r.mean_traction.y;
  d["contact_fraction"] = r.contact_fraction;
  d["stick_fraction"] = r.stick_fraction;
  d["slip_fraction"] = r.slip_fraction;
  d["full_sliding"] = r.full_sliding;
  d["interference_m"] = r.interference;
  d["tangential_displacement_x_m"] = r.tangential_displacement_x;
  d["tangential_displacement_y_m"] = r.tangential_displacement_y;
  d["elastic_energy_J"] = r.elastic_energy;
  d["frictional_force_ratio"] = r.frictional_force_ratio;
  return d;
}

FrictionLaw law_from(const std::string& law, std::optional<double> mu, std::optional<double> shear_strength) {
  if (law == "coulomb") {
    if (!mu) throw InputError("contact.FrictionalContact: law = 'coulomb' needs mu (>= 0)");
    return FrictionLaw::coulomb(*mu);
  }
  if (law == "tresca") {
    if (!shear_strength) throw InputError("contact.FrictionalContact: law = 'tresca' needs shear_strength [Pa] (>= 0)");
    return FrictionLaw::tresca(*shear_strength);
  }
  throw InputError("contact.FrictionalContact: law = '" + law + "'; allowed: coulomb | tresca");
}

// A solver object serves one thread at a time: its warm start, fields and FFT
// workspace are one state, which two solves at once would both write (and then
// fail with a NumericalError that blames the numerics). A second thread that
// reaches an object in use is refused at once, naming the cause, as a
// RuntimeError; separate objects solve in parallel (the GIL is released).
class OneThreadAtATime {
 public:
  OneThreadAtATime(std::atomic<bool>& busy, const char* what) : busy_(busy) {
    if (busy_.exchange(true))
      throw std::runtime_error(fmt::format("{} is not thread-safe: another thread is using this object (a solve, "
                                           "set_surface, reset or warm_start); give each thread its own {}",
                                           what, what));
  }
  ~OneThreadAtATime() { busy_ = false; }
  OneThreadAtATime(const OneThreadAtATime&) = delete;
  OneThreadAtATime& operator=(const OneThreadAtATime&) = delete;

 private:
  std::atomic<bool>& busy_;
};

// The solvers keep a reference to nothing of Python's: the heights are copied in.
struct PyNormalContact {
  NormalContact solver;
  std::atomic<bool> busy{false};
  PyNormalContact(const InArray& h, double lx, double ly, double e_star, const std::string& boundary)
      : solver(field_from(h, grid_of(h, lx, ly, "contact.NormalContact")), e_star, boundary_from(boundary)) {}
};

struct PyFrictionalContact {
  FrictionalContact solver;
  std::atomic<bool> busy{false};
  PyFrictionalContact(const InArray& h, double lx, double ly, double young, double poisson, const std::string& law,
                      std::optional<double> mu, std::optional<double> shear_strength)
      : solver(field_from(h, grid_of(h, lx, ly, "contact.FrictionalContact")), young, poisson,
               law_from(law, mu, shear_strength)) {}
};

RealField optional_field(const std::optional<InArray>& a, const Grid2D& g, const std::string& what) {
  if (!a) return RealField(g);
  require_shape(*a, g, what);
  return field_from(*a, g);
}

py::dict stresses(const InArray& pressure, double lx, double ly, double poisson, const std::vector<double>& depths,
                  const std::optional<InArray>& traction_x, const std::optional<InArray>& traction_y, bool tensor) {
  const Grid2D g = grid_of(pressure, lx, ly, "contact.stresses");
  VectorField p(g);
  p.z = field_from(pressure, g);
  p.x = optional_field(traction_x, g, "traction_x");
  p.y = optional_field(traction_y, g, "traction_y");
  py::dict out;
  SubsurfaceStress stress(g, poisson);
  stress.set_traction(p);
  for (double z : depths) {
    StressField s(g);
    PrincipalStresses principal(g);
    {
      py::gil_scoped_release release;
      stress.stress(z, s);
      principal_stresses(s, principal);
    }
    py::dict d;
    d["sigma_I_Pa"] = owned(std::move(principal.first));
    d["sigma_II_Pa"] = owned(std::move(principal.second));
    d["sigma_III_Pa"] = owned(std::move(principal.third));
    d["tau_max_Pa"] = owned(std::move(principal.max_shear));
    if (tensor) {
      d["xx_Pa"] = owned(std::move(s.xx));
      d["yy_Pa"] = owned(std::move(s.yy));
      d["zz_Pa"] = owned(std::move(s.zz));
      d["xy_Pa"] = owned(std::move(s.xy));
      d["xz_Pa"] = owned(std::move(s.xz));
      d["yz_Pa"] = owned(std::move(s.yz));
    }
    out[py::float_(z)] = d;
  }
  return out;
}

// One field of a contact file: its dataset in contact.h5, the field, its unit, its name in ParaView.
struct FieldOut {
  std::string dataset;
  const RealField* field;
  const char* unit;
  std::string name;
};

// A solved contact's fields as the CLI's contact study writes them: an HDF5
// file of the same datasets and an XDMF sidecar beside it (ParaView). Returns the sidecar.
std::string write_fields(const std::string& file, const Grid2D& g, const std::vector<FieldOut>& fields) {
  std::filesystem::path h5_path(file);
  if (h5_path.extension() != ".h5")
    throw InputError(fmt::format("contact write: file = '{}'; allowed: a name ending in .h5 (its XDMF sidecar goes "
                                 "beside it, .xdmf)",
                                 file));
  auto sidecar = h5_path;
  sidecar.replace_extension(".xdmf");
  {
    py::gil_scoped_release release;
    XdmfSidecar xdmf(g);
    std::vector<XdmfField> shown;
    {
      H5Writer h5(h5_path, Commit::Now);
      for (const auto& f : fields) {
        h5.write_field(f.dataset, *f.field, f.unit);
        shown.push_back({f.dataset, f.name});
      }
      h5.set_attribute("/", "written_by", "wearscale Python: contact write()");
      xdmf.add(h5, shown);
      std::error_code ec;
      std::filesystem::remove(sidecar, ec);  // an old sidecar never describes a new file
      h5.commit();
    }
    xdmf.write(sidecar, h5_path);
  }
  return sidecar.string();
}

RealField in_contact(const RealField& p) {
  RealField c(p.grid());
  for (std::size_t k = 0; k < p.size(); ++k) c[k] = p[k] > 0.0 ? 1.0 : 0.0;
  return c;
}

// A sphere pressed on a free (non-periodic) window against Hertz's solution.
py::dict hertz_check(std::size_t n, double radius, double load, double e_star) {
  const HertzContact hertz{radius, load, e_star};
  const double a = hertz.contact_radius();
  const double size = 4.0 * a;  // the window holds the contact with a margin of one radius
  const Grid2D g = Grid2D::square(n, size);
  ContactResult r;
  double peak = 0.0;
  {
    py::gil_scoped_release release;
    NormalContact contact(sphere(g, radius, size / 2, size / 2), e_star, Boundary::Free);
    r = contact.solve_mean_pressure(load / g.area());
    for (double p : contact.pressure()) peak = std::max(peak, p);
  }
  const double area = r.contact_fraction * g.area();
  py::dict d;
  d["grid"] = n;
  d["contact_radius_m"] = std::sqrt(area / M_PI);
  d["contact_radius_hertz_m"] = a;
  d["peak_pressure_Pa"] = peak;
  d["peak_pressure_hertz_Pa"] = hertz.peak_pressure();
  d["approach_m"] = r.interference;
  d["approach_hertz_m"] = hertz.approach();
  d["approach_relative_error"] = std::abs(r.interference / hertz.approach() - 1.0);
  d["contact_radius_relative_error"] = std::abs(std::sqrt(area / M_PI) / a - 1.0);
  d["peak_pressure_relative_error"] = std::abs(peak / hertz.peak_pressure() - 1.0);
  d["iterations"] = r.iterations;
  return d;
}

}  // namespace

void bind_contact(py::module_& m) {
  // The defaults of the solves' keyword arguments: the options structs' own.
  const ContactOptions contact_defaults{};
  const FrictionalOptions frictional_defaults{};
  // The window's boundary defaults as the contact study's does (its key table: one place).
  const std::string boundary = study_default("contact", "contact.boundary");
  static const std::string normal_doc = R"(Frictionless normal contact (§2.3.2, (2.43)) of a rigid surface on an elastic half-space.

NormalContact(heights, lx, ly=-1, e_star, boundary=")" + boundary + R"(")
heights [m]: (nx, ny) array, positive towards the elastic body (copied once); lx, ly [m]: the
window (ly < 0: square cells); e_star [Pa] > 0: the contact modulus E/(1-nu^2) (1.12).
boundary: "periodic" (one cell of a periodic surface) or "free" (a window on an isolated body;
a contact that reaches the window's border is refused).
The solver is Polonsky-Keer's constrained conjugate gradient, FFT-preconditioned by default.
Each solve starts from the last pressure (a warm start for load ramps); reset() forgets it.
pressure, gap, displacement: read-only (nx, ny) views on the solver's storage [Pa], [m], [m].)";
  py::class_<PyNormalContact>(m, "NormalContact", normal_doc.c_str())
      .def(py::init<const InArray&, double, double, double, const std::string&>(), py::arg("heights"),
           py::arg("lx"), py::arg("ly") = -1.0, py::arg("e_star"), py::arg("boundary") = boundary)
      .def("solve",
           [](PyNormalContact& self, std::optional<double> mean_pressure, std::optional<double> interference,
              double tolerance, int max_iterations, const std::string& method, bool predict_load,
              std::optional<double> load) {
             if (int(mean_pressure.has_value()) + int(interference.has_value()) + int(load.has_value()) != 1)
               throw InputError("contact.NormalContact.solve: give exactly one of mean_pressure [Pa] >= 0, "
                                "load [N] >= 0, interference [m]");
             if (load) mean_pressure = normal_pressure_of(*load, self.solver.grid(), "contact.NormalContact.solve");
             ContactOptions options;
             options.tolerance = tolerance;
             options.max_iterations = max_iterations;
             options.method = method_from(method);
             options.predict_load = predict_load;
             options.stop = python_signal_stop();
             ContactResult r;
             const auto start = std::chrono::steady_clock::now();
             {
               const OneThreadAtATime mine(self.busy, "contact.NormalContact");
               py::gil_scoped_release release;
               r = mean_pressure ? self.solver.solve_mean_pressure(*mean_pressure, options)
                                 : self.solver.solve_interference(*interference, options);
             }
             auto d = to_dict(r);
             d["normal_load_N"] = r.mean_pressure * self.solver.grid().area();
             d["solve_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
             return d;
           },
           py::arg("mean_pressure") = py::none(), py::arg("interference") = py::none(),
           py::arg("tolerance") = contact_defaults.tolerance, py::arg("max_iterations") = contact_defaults.max_iterations,
           py::arg("method") = method_name(contact_defaults.method), py::arg("predict_load") = contact_defaults.predict_load,
           py::arg("load") = py::none(),
           R"(Solves for the imposed mean pressure p0 [Pa] >= 0, normal load F = p0 lx ly [N] >= 0 (force
control, as the CLI's --load) or interference delta = max h - d [m]: exactly one of them.

tolerance: on the relative orthogonality error sum p|g| / (sum p * h_rms), in (0, 1e-3]; method:
"two-level" (default: the preconditioner S on a 2x coarser grid, the same iterations at a quarter of
its transforms, 15-20 % less time a solve from 1024^2; a free window or an odd grid uses the full one),
"preconditioned" (S by a full FFT pair) or "polonsky-keer". predict_load: for a load ramp on one surface, start
from the secant through the last two solutions (kept_solutions) instead of the last pressure
rescaled (about 13 iterations per +0.1 % step against 18 at 512^2). Releases the GIL; Ctrl-C ends the solve within an
iteration (KeyboardInterrupt). Returns a dict: iterations,
error, mean_pressure_Pa, contact_fraction (A/A0), interference_m, elastic_energy_J (per cell),
normal_load_N (p0 lx ly), solve_seconds (wall time of the C++ solve, GIL released).
ValueError for p0 < 0; ArithmeticError for no convergence or NaN.)")
      .def("set_surface", [](PyNormalContact& self, const InArray& h) {
             const OneThreadAtATime mine(self.busy, "contact.NormalContact");
             self.solver.set_surface(field_from(h, self.solver.grid()));
           }, py::arg("heights"), "Replaces the rigid surface (same grid), keeping the last pressure as a warm start.")
      .def("write", [](PyNormalContact& self, const std::string& file) {
             const OneThreadAtATime mine(self.busy, "contact.NormalContact");
             const auto& c = self.solver;
             const RealField contact = in_contact(c.pressure());
             return write_fields(file, c.grid(),
                                 {{"/surface/height", &c.surface(), "m", "height"},
                                  {"/fields/pressure", &c.pressure(), "Pa", "pressure"},
                                  {"/fields/gap", &c.gap(), "m", "gap"},
                                  {"/fields/displacement", &c.displacement(), "m", "displacement"},
                                  {"/fields/contact", &contact, "1", "contact"}});
           }, py::arg("file"),
           R"(Writes the last solve's fields for ParaView as `wearscale contact` writes contact.h5: the HDF5 file
`file` (*.h5: /surface/height [m], /fields/pressure [Pa], /fields/gap [m], /fields/displacement [m],
/fields/contact [1]) and its XDMF sidecar beside it (same name, .xdmf; open that one in ParaView).
Returns the sidecar's path.)")
      .def("reset", [](PyNormalContact& self) {
             const OneThreadAtATime mine(self.busy, "contact.NormalContact");
             self.solver.reset();
           }, "Forgets the warm start.")
      .def_property_readonly("kept_solutions", [](PyNormalContact& self) { return self.solver.kept_solutions(); },
                             "Solutions kept for predict_load on this surface (0, 1 or 2).")
      .def_property_readonly("pressure", [](py::object self) { return view(self.cast<PyNormalContact&>().solver.pressure(), self); },
                             "Contact pressure p >= 0 [Pa], (nx, ny), read-only view.")
      .def_property_readonly("gap", [](py::object self) { return view(self.cast<PyNormalContact&>().solver.gap(), self); },
                             "Gap g = u - h + d [m]: 0 in contact, >= 0 outside, read-only view.")
      .def_property_readonly("displacement", [](py::object self) { return view(self.cast<PyNormalContact&>().solver.displacement(), self); },
                             "Surface displacement u [m] (zero mean; positive into the solid), read-only view.")
      .def_property_readonly("surface", [](py::object self) { return view(self.cast<PyNormalContact&>().solver.surface(), self); },
                             "The rigid surface's heights [m], read-only view.")
      .def_property_readonly("contact", [](PyNormalContact& self) {
             py::array_t<bool> out({self.solver.grid().nx, self.solver.grid().ny});
             auto* o = out.mutable_data();
             const auto& p = self.solver.pressure();
             for (std::size_t k = 0; k < p.size(); ++k) o[k] = p[k] > 0.0;
             return out;
           }, "Points in contact (p > 0), a bool array (a copy).")
      .def_property_readonly("e_star", [](PyNormalContact& self) { return self.solver.e_star(); }, "E* [Pa].")
      .def_property_readonly("shape", [](PyNormalContact& self) { return py::make_tuple(self.solver.grid().nx, self.solver.grid().ny); },
                             "(nx, ny): the grid, the shape of every field.")
      .def_property_readonly("size", [](PyNormalContact& self) { return py::make_tuple(self.solver.grid().lx, self.solver.grid().ly); },
                             "(lx, ly) [m].")
      .def_property_readonly("history", [](PyNormalContact& self) { return self.solver.history(); },
                             "The errors of the last solve's final iterations (at most the last 12; the last is its error).")
      .def_property("warm_start",
           [](py::object self) {
             auto& s = self.cast<PyNormalContact&>().solver;
             return py::make_tuple(view(s.pressure(), self), s.warm_gap_shift());
           },
           [](PyNormalContact& self, const py::tuple& state) {
             const OneThreadAtATime mine(self.busy, "contact.NormalContact");
             const auto p = state[0].cast<InArray>();
             require_shape(p, self.solver.grid(), "warm_start pressure");
             self.solver.set_warm_start({p.data(), static_cast<std::size_t>(p.size())}, state[1].cast<double>());
           },
           "(pressure [Pa], mean gap shift [m]): restoring both makes the next solve bit-identical to an uninterrupted one.");

  py::class_<PyFrictionalContact>(m, "FrictionalContact", R"(Frictional contact (Appendix A): a rigid surface pressed and sheared on an elastic flat.

FrictionalContact(heights, lx, ly=-1, young, poisson, law="coulomb", mu=None, shear_strength=None)
young [Pa] > 0, poisson in (-1, 0.5] of the flat (the rigid surface's compliance folded in, (A.1));
law: "coulomb" (p_T,max = mu p_N, (A.2)) or "tresca" (p_T,max = shear_strength [Pa], (A.3)).
Normal and tangential are coupled for nu < 0.5 (Boussinesq-Cerruti tensor). Periodic cell.
Each solve starts from the last solution (warm start); reset() forgets it.)")
      .def(py::init<const InArray&, double, double, double, double, const std::string&, std::optional<double>,
                    std::optional<double>>(),
           py::arg("heights"), py::arg("lx"), py::arg("ly") = -1.0, py::arg("young"), py::arg("poisson"),
           py::arg("law") = "coulomb", py::arg("mu") = py::none(), py::arg("shear_strength") = py::none())
      .def("solve",
           [](PyFrictionalContact& self, std::optional<double> mean_pressure, double traction_x, double traction_y,
              double tolerance, int max_iterations, std::optional<double> load) {
             if (mean_pressure.has_value() == load.has_value())
               throw InputError("contact.FrictionalContact.solve: give exactly one of mean_pressure [Pa] >= 0, load [N] >= 0");
             if (load) mean_pressure = normal_pressure_of(*load, self.solver.grid(), "contact.FrictionalContact.solve");
             FrictionalOptions options;
             options.tolerance = tolerance;
             options.max_iterations = max_iterations;
             options.stop = python_signal_stop();
             FrictionalResult r;
             const auto start = std::chrono::steady_clock::now();
             {
               const OneThreadAtATime mine(self.busy, "contact.FrictionalContact");
               py::gil_scoped_release release;
               r = self.solver.solve(MeanTraction{*mean_pressure, traction_x, traction_y}, options);
             }
             auto d = to_dict(r);
             d["normal_load_N"] = r.mean_traction.normal * self.solver.grid().area();
             d["solve_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
             return d;
           },
           py::arg("mean_pressure") = py::none(), py::arg("traction_x") = 0.0, py::arg("traction_y") = 0.0,
           py::arg("tolerance") = frictional_defaults.tolerance, py::arg("max_iterations") = frictional_defaults.max_iterations,
           py::arg("load") = py::none(),
           R"(Solves for imposed mean tractions <p_N> = mean_pressure >= 0 (or the normal load [N], load =
<p_N> lx ly: force control) and <p_T> = (traction_x, traction_y) [Pa].

tolerance on the relative cost (A.14). Releases the GIL; Ctrl-C ends the solve within an iteration
(KeyboardInterrupt). A tangential load above what friction
carries (gross sliding) is a ValueError, never clamped. Returns a dict of scalars (units in the
names): contact_fraction, stick_fraction, slip_fraction, tangential_displacement_x_m, ...)")
      .def("write", [](PyFrictionalContact& self, const std::string& file) {
             const OneThreadAtATime mine(self.busy, "contact.FrictionalContact");
             const auto& c = self.solver;
             const RealField contact = in_contact(c.traction().z);
             return write_fields(file, c.grid(),
                                 {{"/surface/height", &c.surface(), "m", "height"},
                                  {"/fields/pressure", &c.traction().z, "Pa", "p_N"},
                                  {"/fields/traction_x", &c.traction().x, "Pa", "p_x"},
                                  {"/fields/traction_y", &c.traction().y, "Pa", "p_y"},
                                  {"/fields/stick_slip", &c.stick_slip_map(), "1", "stick_slip"},
                                  {"/fields/gap", &c.normal_gap(), "m", "gap"},
                                  {"/fields/slip_x", &c.slip().x, "m", "slip_x"},
                                  {"/fields/slip_y", &c.slip().y, "m", "slip_y"},
                                  {"/fields/displacement", &c.displacement().z, "m", "u_z"},
                                  {"/fields/displacement_x", &c.displacement().x, "m", "u_x"},
                                  {"/fields/displacement_y", &c.displacement().y, "m", "u_y"},
                                  {"/fields/contact", &contact, "1", "contact"}});
           }, py::arg("file"),
           R"(Writes the last solve's fields for ParaView as `wearscale contact --friction ...` writes contact.h5
(the same datasets and names: /surface/height, /fields/pressure, traction_x, traction_y [Pa], stick_slip
(0 open, 1 stick, 2 slip), gap, slip_x, slip_y, displacement, displacement_x, displacement_y [m], contact [1];
the subsurface stresses are contact.stresses()'s) into `file` (*.h5) and its XDMF sidecar beside it (.xdmf).
Returns the sidecar's path.)")
      .def("reset", [](PyFrictionalContact& self) {
             const OneThreadAtATime mine(self.busy, "contact.FrictionalContact");
             self.solver.reset();
           }, "Forgets the warm start.")
      .def_property_readonly("pressure", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.traction().z, self); },
                             "p_N [Pa], read-only view.")
      .def_property_readonly("traction_x", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.traction().x, self); },
                             "p_x [Pa], read-only view.")
      .def_property_readonly("traction_y", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.traction().y, self); },
                             "p_y [Pa], read-only view.")
      .def_property_readonly("displacement", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.displacement().z, self); },
                             "u_z [m] (zero mean), read-only view.")
      .def_property_readonly("displacement_x", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.displacement().x, self); },
                             "u_x [m], read-only view.")
      .def_property_readonly("displacement_y", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.displacement().y, self); },
                             "u_y [m], read-only view.")
      .def_property_readonly("gap", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.normal_gap(), self); },
                             "Normal gap g_N [m], read-only view.")
      .def_property_readonly("slip_x", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.slip().x, self); },
                             "Slip g_T,x [m]: 0 where sticking, read-only view.")
      .def_property_readonly("slip_y", [](py::object self) { return view(self.cast<PyFrictionalContact&>().solver.slip().y, self); },
                             "Slip g_T,y [m], read-only view.")
      .def_property_readonly("stick_slip", [](PyFrictionalContact& self) { return codes(self.solver.stick_slip_map()); },
                             "uint8 (nx, ny): 0 open, 1 stick, 2 slip (a copy).")
      .def_property_readonly("shape", [](PyFrictionalContact& self) { return py::make_tuple(self.solver.grid().nx, self.solver.grid().ny); },
                             "(nx, ny): the grid, the shape of every field.")
      .def_property_readonly("size", [](PyFrictionalContact& self) { return py::make_tuple(self.solver.grid().lx, self.solver.grid().ly); },
                             "(lx, ly) [m].")
      .def_property_readonly("poisson", [](PyFrictionalContact& self) { return self.solver.poisson(); },
                             "Poisson's ratio nu of the flat, in (-1, 0.5].")
      .def_property_readonly("young", [](PyFrictionalContact& self) { return self.solver.young(); },
                             "Young's modulus E of the flat [Pa].");

  m.def("stresses", &stresses, py::arg("pressure"), py::arg("lx"), py::arg("ly") = -1.0, py::arg("poisson"),
        py::arg("depths"), py::arg("traction_x") = py::none(), py::arg("traction_y") = py::none(),
        py::arg("tensor") = false,
        R"(Stresses in a periodic half-space below surface tractions [Pa] (Boussinesq-Cerruti; App. A.3).

pressure (p_z), traction_x, traction_y: (nx, ny) arrays over lx x ly metres; poisson in (-1, 0.5];
depths: z >= 0 [m] (0: the surface). Returns {z: {sigma_I_Pa, sigma_II_Pa, sigma_III_Pa, tau_max_Pa,
and with tensor=True xx_Pa ... yz_Pa}}: sigma_I is the largest principal stress of (4.24),
tau_max = (sigma_I - sigma_III)/2.)");
  m.def("effective_modulus", &effective_modulus, py::arg("e1"), py::arg("nu1"), py::arg("e2"), py::arg("nu2"),
        "E* of two bodies: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (1.12) [Pa].");
  m.def("hertz", [](double radius, double load, double e_star) {
          const HertzContact h{radius, load, e_star};
          py::dict d;
          d["contact_radius_m"] = h.contact_radius();
          d["peak_pressure_Pa"] = h.peak_pressure();
          d["mean_pressure_Pa"] = h.mean_pressure();
          d["approach_m"] = h.approach();
          return d;
        }, py::arg("radius"), py::arg("load"), py::arg("e_star"),
        "Hertz's sphere on a flat: a = (3FR/4E*)^(1/3), p0 = 3F/(2 pi a^2), delta = a^2/R (SI units).");
  m.def("hertz_check", &hertz_check, py::arg("n") = 128, py::arg("radius") = 3e-3, py::arg("load") = 1.0,
        py::arg("e_star") = 73e9 / (1 - 0.17 * 0.17),
        R"(Solves a sphere (radius [m], load [N], e_star [Pa]) on a free n x n window of 4 a and compares
it with Hertz: returns the computed and analytic contact radius, peak pressure and approach and
their relative errors (a few percent at n = 128, shrinking as 1/n).)");
}

}  // namespace wearscale::python
