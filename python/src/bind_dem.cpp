// wearscale.dem: the DEM patch test (§6.2.1), the sheared junction (§6.3) and
// the material targets of the cohesive model (§6.1). The rough-shear and
// trapped-particle studies are not bound yet (the CLI's `wearscale dem` runs them).
#include <pybind11/stl.h>

#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/sheared_junction.hpp"
#include "wearscale/dem/simulation.hpp"

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
  void take(const Simulation& sim) {
    const auto& p = sim.particles();
    position = p.position;
    velocity = p.velocity;
    radius = p.radius;
    wall = p.wall;
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
    r = run_sheared_junction(spec, [&](const Simulation& sim, const JunctionSample&, long, long) { final_state.take(sim); });
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

}  // namespace

void bind_dem(py::module_& m) {
  m.def("material", [](const std::string& name, std::optional<double> poisson, double s) {
          return targets(material_of(name, poisson, s));
        }, py::arg("name") = "table-6.4", py::arg("poisson") = py::none(), py::arg("scaling_exponent") = 0.5,
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
          spec.d0 = d0.value_or(0.6 * critical_diameter(spec.material));
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
        py::arg("material") = "table-6.4", py::arg("poisson") = py::none(), py::arg("d0") = py::none(),
        py::arg("lattice") = "hcp", py::arg("load_along_c_axis") = false, py::arg("length") = 25.0,
        py::arg("width") = 3.0, py::arg("load") = 0.01, py::arg("time_step") = 0.1, py::arg("strengths") = false,
        py::arg("max_elastic_steps") = 40000, py::arg("seed") = 1, py::arg("scaling_exponent") = 0.5,
        R"(The DEM patch test of §6.2.1: a sample between two walls in confined compression gives
C11, C12 and so E and nu; with strengths=True the walls are also pulled apart and sheared
(sigma_mN, sigma_mT; minutes). d0: particle size (default 0.6 d_c, in the material's units);
length, width in d0; load in units of E; time_step in the critical step. Releases the GIL.)");
  m.def("sheared_junction", &sheared_junction, py::arg("material") = "SiO2", py::arg("diameter") = 20e-9,
        py::arg("d0") = 3e-9, py::arg("largest") = 7.5e-9, py::arg("box") = std::vector<double>{60e-9, 40e-9, 40e-9},
        py::arg("velocity") = 10.0, py::arg("pressure") = 100e6, py::arg("sliding_distance") = 0.0,
        py::arg("time_step") = 0.1, py::arg("record_every") = 100, py::arg("seed") = 1,
        py::arg("scaling_exponent") = 0.5,
        R"(The sheared junction of §6.3 (Figs. 6.18-6.20): two amorphous surfaces linked by a cylindrical
junction of diameter D [m] (height D/2), the top wall slid at `velocity` [m/s] under `pressure` [Pa]
over sliding_distance [m] (0: 1.5 D). d0, largest: mode and largest particle diameter [m]; box [m].
Returns the verdict (detached into a rolling particle when D >= d* = 32 gamma G/sigma_mT^2 (6.65),
else plastic), the force history arrays (time_s, sliding_m, tangential_force_N, normal_force_N,
kinetic_energy_J) and the final particles (position, velocity (n, 3), radius, wall). Minutes for
the thesis' D = 20 nm.)");
}

}  // namespace wearscale::python
