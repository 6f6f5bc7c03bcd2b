// wearscale.dem: the DEM patch test (§6.2.1), the sheared junction (§6.3), the
// sheared rough surfaces (§7.2), the trapped particles (§7.3) and the
// material targets of the cohesive model (§6.1).
#include <pybind11/stl.h>

#include <deque>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/sheared_junction.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::python {

namespace {

using namespace wearscale::dem;

CohesiveMaterial material_of(const std::string& name, std::optional<double> poisson, double scaling_exponent) {
  CohesiveMaterial m;
  if (name == "table-6.4") {
    m = patch_test_targets();
  } else {
    m = cohesive_material(materials::MaterialLibrary().get(name), scaling_exponent);
  }
  m.scaling_exponent = scaling_exponent;
  if (poisson) m.poisson = *poisson;
  require_modelled(m);
  return m;
}

// A docstring with each `{study|key}` replaced by that key's default as the
// study's key table words it ("1.5 D"), kept for the module's lifetime.
const char* docstring(std::string text) {
  static std::deque<std::string> kept;
  for (std::size_t at; (at = text.find("{dem/")) != std::string::npos;) {
    const auto bar = text.find('|', at), end = text.find('}', at);
    text.replace(at, end + 1 - at, study_default(text.substr(at + 1, bar - at - 1), text.substr(bar + 1, end - bar - 1)));
  }
  return kept.emplace_back(std::move(text)).c_str();
}

py::dict targets(const CohesiveMaterial& m) {
  py::dict d;
  d["name"] = m.name;
  d["young"] = m.young;
  d["poisson"] = m.poisson;
  d["tensile_strength"] = m.tensile_strength;
  d["shear_strength"] = m.shear_strength;
  d["surface_energy"] = m.surface_energy;
  d["restitution"] = m.restitution;
  d["density"] = m.density;
  d["scaling_exponent"] = m.scaling_exponent;
  d["d_c"] = critical_diameter(m);
  d["d_min"] = minimum_diameter(m);
  d["d_star"] = critical_junction_size(m);
  return d;
}

// An (n, 3) array of a Vec3 vector (copied: the simulation is gone after the run).
py::array vectors(const std::vector<Vec3>& v) {
  py::array_t<double> a({v.size(), std::size_t{3}});
  auto* o = a.mutable_data();
  for (std::size_t i = 0; i < v.size(); ++i) o[3 * i] = v[i].x, o[3 * i + 1] = v[i].y, o[3 * i + 2] = v[i].z;
  return a;
}

// The final state of a run, taken at the observer's last call.
struct FinalState {
  std::vector<Vec3> position, velocity;
  std::vector<double> radius;
  std::vector<std::int16_t> wall;
  void take(const Engine& sim) {
    const auto& p = sim.particles();
    position = p.position;
    velocity = p.velocity;
    radius = p.radius;
    wall = p.wall;
  }
  /// An observer of a sliding cell that keeps its last state.
  auto observer() {
    return [this](const SlidingCell& c, const SlidingSample&, long, long) { take(c.engine()); };
  }
  void put(py::dict& d) const {
    d["position"] = vectors(position);
    d["velocity"] = vectors(velocity);
    d["radius"] = owned(std::vector<double>(radius));
    py::array_t<std::int16_t> w(wall.size());
    std::copy(wall.begin(), wall.end(), w.mutable_data());
    d["wall"] = w;
  }
};

py::dict sheared_junction(const std::string& material, double diameter, double d0, double largest,
                          std::vector<double> box, double velocity, double pressure, double sliding_distance,
                          double time_step, long record_every, unsigned seed, double scaling_exponent) {
  ShearedJunctionSpec spec;
  spec.material = material_of(material, std::nullopt, scaling_exponent);
  spec.diameter = diameter;
  spec.d0 = d0;
  spec.largest = largest;
  if (box.size() != 3) throw InputError("dem.sheared_junction: box = [x, y, z] in m, three lengths");
  spec.box = Vec3{box[0], box[1], box[2]};
  spec.velocity = velocity;
  spec.pressure = pressure;
  spec.sliding_distance = sliding_distance;
  spec.time_step = time_step;
  spec.record_every = record_every;
  spec.seed = seed;
  FinalState final_state;
  ShearedJunctionResult r;
  {
    py::gil_scoped_release release;
    r = run_sheared_junction(spec, [&](const Engine& sim, const JunctionSample&, long, long) { final_state.take(sim); });
  }
  py::dict d;
  d["particles"] = r.particles;
  d["junction_particles"] = r.junction_particles;
  d["d_star_m"] = r.d_star;
  d["time_step_s"] = r.time_step;
  d["steps"] = r.steps;
  d["peak_tangential_force_N"] = r.peak_tangential_force;
  d["detached"] = r.detached;
  d["verdict"] = r.verdict();
  d["detached_diameter_m"] = r.detached_diameter;
  d["rigid_residual"] = r.rigid_residual;
  d["rolling_rate"] = r.rolling_rate;
  auto series = [&](auto member) {
    std::vector<double> v;
    v.reserve(r.history.size());
    for (const auto& sample : r.history) v.push_back(sample.*member);
    return owned(std::move(v));
  };
  py::dict history;
  history["time_s"] = series(&JunctionSample::time);
  history["sliding_m"] = series(&JunctionSample::sliding);
  history["tangential_force_N"] = series(&JunctionSample::tangential_force);
  history["normal_force_N"] = series(&JunctionSample::normal_force);
  history["kinetic_energy_J"] = series(&JunctionSample::kinetic_energy);
  d["history"] = history;
  py::dict state;
  final_state.put(state);
  d["final"] = state;
  return d;
}

// The sliding cell of §7.2-7.3 (sliding_cell.hpp) from keyword arguments in SI units.
struct CellArgs {
  std::string material, law;
  double d0, largest;
  std::vector<double> box;
  double velocity, pressure, sliding_distance, settle_distance, time_step, friction, scaling_exponent;
  long record_every;
  unsigned seed;
  SlidingCellSpec spec(const char* study) const {
    SlidingCellSpec c;
    c.material = material_of(material, std::nullopt, scaling_exponent);
    c.law = law;
    c.friction = friction;
    c.d0 = d0;
    c.largest = largest;
    if (box.size() != 3) throw InputError(std::string(study) + ": box = [L, W, H] in m, three lengths");
    c.box = Vec3{box[0], box[1], box[2]};
    c.velocity = velocity;
    c.pressure = pressure;
    c.sliding_distance = sliding_distance;
    c.settle_distance = settle_distance;
    c.time_step = time_step;
    c.record_every = record_every;
    c.seed = seed;
    check(c, study);
    return c;
  }
};

// A sliding cell's history as named arrays (SI units in the names).
py::dict sliding_history(const std::vector<SlidingSample>& history) {
  auto series = [&](double SlidingSample::*member) {
    std::vector<double> v;
    v.reserve(history.size());
    for (const auto& sample : history) v.push_back(sample.*member);
    return owned(std::move(v));
  };
  py::dict h;
  h["time_s"] = series(&SlidingSample::time);
  h["sliding_m"] = series(&SlidingSample::sliding);
  h["tangential_force_N"] = series(&SlidingSample::tangential_force);
  h["normal_force_N"] = series(&SlidingSample::normal_force);
  h["kinetic_energy_J"] = series(&SlidingSample::kinetic_energy);
  h["worn"] = series(&SlidingSample::worn);
  h["roughness_bottom_m"] = series(&SlidingSample::roughness_bottom);
  h["roughness_top_m"] = series(&SlidingSample::roughness_top);
  return h;
}

// What every sliding-cell study reports (the members RoughShearResult and
// TrappedParticlesResult share), its history and its final particles.
template <class Result>
py::dict sliding_result(const Result& r, const FinalState& final_state) {
  py::dict d;
  d["particles"] = r.particles;
  d["d_star_m"] = r.d_star;
  d["time_step_s"] = r.time_step;
  d["steps"] = r.steps;
  d["area_m2"] = r.area;
  d["mean_pressure_Pa"] = r.mean_pressure;
  d["mean_tangential_force_N"] = r.mean_tangential_force;
  d["peak_tangential_force_N"] = r.peak_tangential_force;
  d["friction"] = r.friction;
  d["history"] = sliding_history(r.history);
  py::dict state;
  final_state.put(state);
  d["final"] = state;
  return d;
}

py::dict rough_shear(const CellArgs& cell, double roughness, double hurst, double shortest_wavelength) {
  RoughShearSpec spec;
  spec.cell = cell.spec("dem.rough_shear");
  spec.roughness = roughness;
  spec.hurst = hurst;
  spec.shortest_wavelength = shortest_wavelength;
  FinalState final_state;
  RoughShearResult r;
  {
    py::gil_scoped_release release;
    r = run_rough_shear(spec, final_state.observer());
  }
  py::dict d = sliding_result(r, final_state);
  d["imposed_roughness_m"] = r.imposed_roughness;
  d["worn"] = r.worn;
  d["worn_fraction"] = r.worn_fraction;
  d["wear_particle"] = r.wear_particle;
  d["wear_particle_residual"] = r.wear_particle_residual;
  d["regime"] = r.regime;
  return d;
}

py::dict trapped_particles(const CellArgs& cell, int count, double diameter, double clearance, double fit_from) {
  TrappedParticlesSpec spec;
  spec.cell = cell.spec("dem.trapped_particles");
  spec.count = count;
  spec.diameter = diameter;
  spec.clearance = clearance;
  spec.fit_from = fit_from;
  FinalState final_state;
  TrappedParticlesResult r;
  {
    py::gil_scoped_release release;
    r = run_trapped_particles(spec, final_state.observer());
  }
  py::dict d = sliding_result(r, final_state);
  d["loose_particles"] = r.loose_particles;
  d["worn_first_body"] = r.worn_first_body;
  d["band_thickness_m"] = r.band_thickness;
  d["loose_residual"] = r.loose_residual;
  d["mean_residual"] = r.mean_residual;
  d["rolling"] = r.rolling;
  d["regime"] = r.regime();
  return d;
}

}  // namespace

void bind_dem(py::module_& m) {
  // The defaults of the keyword arguments: the spec structs' own (one place for each).
  static const PatchTestSpec patch_defaults{};
  static const ShearedJunctionSpec junction_defaults{};
  static const RoughShearSpec rough_defaults{};
  static const SlidingCellSpec cell_defaults{};
  static const TrappedParticlesSpec trapped_defaults{};
  const double s_default = CohesiveMaterial{}.scaling_exponent;  // [dem] scaling_exponent's default
  m.def("material", [](const std::string& name, std::optional<double> poisson, double s) {
          return targets(material_of(name, poisson, s));
        }, py::arg("name") = study_default("dem/patch_test", "dem.material"), py::arg("poisson") = py::none(),
        py::arg("scaling_exponent") = s_default,
        R"(The targets of the cohesive DEM for a material: "table-6.4" (no units: E = 1, nu = 0.15,
sigma_mN = 0.2, sigma_mT = 0.1, gamma = 1.5) or a built-in record (SI units), with d_c = 4 gamma E/sigma_mN^2
(6.35), d_min = 4 gamma/sigma_mN (6.62), d* = 32 gamma G/sigma_mT^2 (6.65). nu <= 1/4 (6.52).)");
  m.def("patch_test",
        [](const std::string& material, std::optional<double> poisson, std::optional<double> d0, const std::string& lattice,
           bool load_along_c_axis, double length, double width, double load, double time_step, bool strengths,
           long max_elastic_steps, unsigned seed, double scaling_exponent) {
          PatchTestSpec spec;
          spec.material = material_of(material, poisson, scaling_exponent);
          if (lattice != "hcp" && lattice != "amorphous")
            throw InputError("dem.patch_test: lattice = '" + lattice + "'; allowed: hcp | amorphous");
          spec.amorphous = lattice == "amorphous";
          spec.d0 = d0.value_or(patch_test_d0(spec.material));
          spec.load_along_c_axis = load_along_c_axis;
          spec.length = length;
          spec.width = width;
          spec.load = load;
          spec.time_step = time_step;
          spec.strengths = strengths;
          spec.max_elastic_steps = max_elastic_steps;
          spec.seed = seed;
          PatchTestResult r;
          {
            py::gil_scoped_release release;
            r = run_patch_test(spec);
          }
          py::dict d;
          d["particles"] = r.particles;
          d["d0"] = spec.d0;
          d["d_min"] = r.d_min;
          d["d_c"] = r.d_c;
          d["c11"] = r.c11;
          d["c12"] = r.c12;
          d["young"] = r.young;
          d["poisson"] = r.poisson;
          d["young_target"] = spec.material.young;
          d["poisson_target"] = spec.material.poisson;
          d["elastic_steps"] = r.elastic_steps;
          d["elastic_converged"] = r.elastic_converged;
          d["tensile_strength"] = r.tensile_strength ? py::object(py::float_(*r.tensile_strength)) : py::object(py::none());
          d["shear_strength"] = r.shear_strength ? py::object(py::float_(*r.shear_strength)) : py::object(py::none());
          d["tensile_strength_target"] = r.target_tensile;
          d["shear_strength_target"] = r.target_shear;
          d["strength_steps"] = r.strength_steps;
          return d;
        },
        py::arg("material") = study_default("dem/patch_test", "dem.material"), py::arg("poisson") = py::none(),
        py::arg("d0") = py::none(),
        py::arg("lattice") = patch_defaults.amorphous ? "amorphous" : "hcp",
        py::arg("load_along_c_axis") = patch_defaults.load_along_c_axis, py::arg("length") = patch_defaults.length,
        py::arg("width") = patch_defaults.width, py::arg("load") = patch_defaults.load,
        py::arg("time_step") = patch_defaults.time_step, py::arg("strengths") = patch_defaults.strengths,
        py::arg("max_elastic_steps") = patch_defaults.max_elastic_steps, py::arg("seed") = patch_defaults.seed,
        py::arg("scaling_exponent") = s_default,
        docstring(R"(The DEM patch test of §6.2.1: a sample between two walls in confined compression gives
C11, C12 and so E and nu; with strengths=True the walls are also pulled apart and sheared
(sigma_mN, sigma_mT; minutes; strengths=False for E and nu alone). d0: particle size (default {dem/patch_test|dem.patch_test.d0}, in the material's units);
length, width in d0; load in units of E; time_step in the critical step. Releases the GIL.)"));
  const Vec3& junction_box = junction_defaults.box;
  m.def("sheared_junction", &sheared_junction, py::arg("material") = "SiO2", py::arg("diameter") = 20e-9,
        py::arg("d0") = 3e-9, py::arg("largest") = junction_defaults.largest,
        py::arg("box") = std::vector<double>{junction_box.x, junction_box.y, junction_box.z},
        py::arg("velocity") = junction_defaults.velocity, py::arg("pressure") = junction_defaults.pressure,
        py::arg("sliding_distance") = junction_defaults.sliding_distance, py::arg("time_step") = junction_defaults.time_step,
        py::arg("record_every") = junction_defaults.record_every, py::arg("seed") = junction_defaults.seed,
        py::arg("scaling_exponent") = s_default,
        docstring(R"(The sheared junction of §6.3 (Figs. 6.18-6.20): two amorphous surfaces linked by a cylindrical
junction of diameter D [m] (height D/2), the top wall slid at `velocity` [m/s] under `pressure` [Pa]
over sliding_distance [m] (0: {dem/junction|dem.junction.sliding_distance}). d0, largest: mode and largest particle diameter [m]
(largest 0: {dem/junction|dem.junction.largest}; the thesis fixes 7.5 nm); box [m].
Returns the verdict (detached into a rolling particle when D >= d* = 32 gamma G/sigma_mT^2 (6.65),
else plastic), the force history arrays (time_s, sliding_m, tangential_force_N, normal_force_N,
kinetic_energy_J) and the final particles (position, velocity (n, 3), radius, wall). Minutes for
the thesis' D = 20 nm.)"));
  auto cell_args = [](const std::string& material, double d0, double largest, std::vector<double> box,
                      double velocity, double pressure, double sliding_distance, double settle_distance,
                      double time_step, long record_every, unsigned seed, double scaling_exponent,
                      const std::string& law, double friction) {
    return CellArgs{material, law,           d0,        largest,         std::move(box), velocity, pressure,
                    sliding_distance, settle_distance, time_step, friction, scaling_exponent, record_every, seed};
  };
  m.def("rough_shear",
        [cell_args](double roughness, double hurst, double shortest_wavelength, const std::string& material, double d0,
                    double largest, std::vector<double> box, double velocity, double pressure, double sliding_distance,
                    double settle_distance, double time_step, long record_every, unsigned seed,
                    double scaling_exponent, const std::string& law, double friction) {
          return rough_shear(cell_args(material, d0, largest, std::move(box), velocity, pressure, sliding_distance,
                                       settle_distance, time_step, record_every, seed, scaling_exponent, law, friction),
                             roughness, hurst, shortest_wavelength);
        },
        py::arg("roughness") = rough_defaults.roughness, py::arg("hurst") = rough_defaults.hurst,
        py::arg("shortest_wavelength") = rough_defaults.shortest_wavelength,
        py::arg("material") = "SiO2", py::arg("d0") = 3e-9, py::arg("largest") = cell_defaults.largest,
        py::arg("box") = std::vector<double>{150e-9, 10.5e-9, 60e-9}, py::arg("velocity") = cell_defaults.velocity,
        py::arg("pressure") = cell_defaults.pressure,
        py::arg("sliding_distance") = 150e-9, py::arg("settle_distance") = 3e-9,
        py::arg("time_step") = cell_defaults.time_step, py::arg("record_every") = cell_defaults.record_every,
        py::arg("seed") = cell_defaults.seed, py::arg("scaling_exponent") = s_default,
        py::arg("law") = cell_defaults.law, py::arg("friction") = cell_defaults.friction,
        docstring(R"(The sheared rough surfaces of §7.2 (Figs. 7.4-7.7): two amorphous surfaces of self-affine
roughness Sa = roughness * L (Hurst exponent hurst, shortest wavelength in d0) carved from one
relaxed box, the bottom wall fixed, the top wall pressed at `pressure` [Pa] and slid at `velocity`
[m/s] over sliding_distance [m] after settle_distance [m] at rest. box = [L, W, H] [m] (L sliding and
W periodic); d0 and largest (0: {dem/rough_shear|dem.rough_shear.largest}) [m]; time_step in the critical step; law "cohesive" (the
thesis) or "hooke" with Coulomb `friction`. Returns the friction (mean F_T / F_N over the second
half), worn particles, the regime ("rolling wear particles", "shear band", "no wear particle"), the
history arrays (time_s, sliding_m, tangential_force_N, normal_force_N, kinetic_energy_J, worn,
roughness_bottom_m, roughness_top_m) and the final particles. Releases the GIL; minutes at the
defaults (the thesis' 50 d0 cell).)"));
  m.def("trapped_particles",
        [cell_args](int count, double diameter, double clearance, double fit_from, const std::string& material,
                    double d0, double largest, std::vector<double> box, double velocity, double pressure,
                    double sliding_distance, double settle_distance, double time_step, long record_every,
                    unsigned seed, double scaling_exponent, const std::string& law, double friction) {
          return trapped_particles(cell_args(material, d0, largest, std::move(box), velocity, pressure,
                                             sliding_distance, settle_distance, time_step, record_every, seed,
                                             scaling_exponent, law, friction),
                                   count, diameter, clearance, fit_from);
        },
        py::arg("count") = trapped_defaults.count, py::arg("diameter") = 30e-9,
        py::arg("clearance") = trapped_defaults.clearance, py::arg("fit_from") = trapped_defaults.fit_from,
        py::arg("material") = "SiO2", py::arg("d0") = 3e-9, py::arg("largest") = cell_defaults.largest,
        py::arg("box") = std::vector<double>{300e-9, 10.5e-9, 54e-9}, py::arg("velocity") = cell_defaults.velocity,
        py::arg("pressure") = cell_defaults.pressure,
        py::arg("sliding_distance") = 300e-9, py::arg("settle_distance") = 3e-9,
        py::arg("time_step") = cell_defaults.time_step, py::arg("record_every") = cell_defaults.record_every,
        py::arg("seed") = cell_defaults.seed, py::arg("scaling_exponent") = s_default,
        py::arg("law") = cell_defaults.law, py::arg("friction") = cell_defaults.friction,
        docstring(R"(Loose particles trapped between flat surfaces, §7.3 (Figs. 7.8-7.9): `count` discs of
diameter D [m] in a gap of height D (clearance in d0 from the surfaces), the top wall pressed at
`pressure` [Pa] and slid at `velocity` [m/s]. The regime from the loose particles' rigid-body misfit
over the slide from fit_from on: "rolling" (misfit < 1/3) or "shear band". Cell keys as
rough_shear (largest 0: {dem/trapped_particles|dem.trapped_particles.largest}). Returns the friction, the worn first body and its band thickness [m], the misfits,
the history arrays and the final particles. Releases the GIL; minutes at the defaults.)"));
}

}  // namespace wearscale::python
