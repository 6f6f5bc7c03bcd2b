// wearscale.dem: the DEM patch test (§6.2.1) and the material targets of the
// cohesive model (§6.1). The other DEM studies (sheared junction, rough shear,
// trapped particles) run through wearscale.run with their cases.
#include <pybind11/stl.h>

#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/patch_test.hpp"

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
}

}  // namespace wearscale::python
