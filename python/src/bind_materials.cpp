// wearscale.materials: the built-in records (Table 2.1), the shipped strength
// tables (Fig. 9.18) and the scale-linking junction model (§7.1.2, §9.3.2).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/io/strength_table_file.hpp"
#include "wearscale/materials/junction_model.hpp"
#include "wearscale/materials/material.hpp"
#include "wearscale/materials/strength_law.hpp"
#include "wearscale/materials/strength_table.hpp"

namespace wearscale::python {

namespace {

using namespace wearscale::materials;

py::dict to_dict(const Material& m) {
  py::dict d;
  d["name"] = m.name;
  d["young_Pa"] = m.young;
  d["poisson"] = m.poisson;
  d["density_kg_per_m3"] = m.density;
  d["surface_energy_J_per_m2"] = m.surface_energy;
  d["tensile_strength_Pa"] = m.tensile_strength;
  d["shear_strength_Pa"] = m.shear_strength;
  d["shear_modulus_Pa"] = m.shear_modulus();
  d["restitution"] = m.restitution ? py::object(py::float_(*m.restitution)) : py::object(py::none());
  d["source"] = m.source;
  return d;
}

py::dict to_dict(const StrengthTable& t) {
  py::dict d;
  d["material"] = t.material;
  d["pressure_Pa"] = owned(std::vector<double>(t.pressure));
  d["sigma_max_Pa"] = owned(std::vector<double>(t.sigma_max));
  d["sigma_dyn_Pa"] = owned(std::vector<double>(t.sigma_dyn));
  d["provenance"] = t.provenance;
  d["origin"] = t.origin;
  return d;
}

StrengthLaw law_of(const std::string& material, const std::string& set, const std::filesystem::path& file, bool clamp) {
  const auto outside = clamp ? OutsideTable::Clamp : OutsideTable::Error;
  return file.empty() ? StrengthLaw(shipped_table(set, material), outside) : StrengthLaw(read_strength_table(file), outside);
}

}  // namespace

void bind_materials(py::module_& m) {
  m.def("names", [] { return MaterialLibrary().names(); }, "Names of the built-in materials.");
  m.def("material", [](const std::string& name) { return to_dict(MaterialLibrary().get(name)); }, py::arg("name"),
        "A built-in material record (Table 2.1) as a dict, SI units in the key names. ValueError for an unknown name.");
  m.def("effective_modulus", [](const std::string& a, const std::string& b) {
          MaterialLibrary lib;
          return effective_modulus(lib.get(a), lib.get(b));
        }, py::arg("a"), py::arg("b"), "E* of two built-in materials (1.12) [Pa].");
  m.def("data_directory", [] { return data_directory().string(); },
        "The folder of shipped data: $WEARSCALE_DATA, else share/wearscale/data of the installation, else the source tree's.");
  m.def("set_data_directory", [](const std::filesystem::path& dir) { set_data_directory(dir); }, py::arg("dir"),
        "Uses `dir` for shipped data (unless $WEARSCALE_DATA is set); '' restores the search.");
  m.def("shipped_sets", &shipped_sets, "Names of the shipped strength-table sets (\"thesis\": Fig. 9.18, \"lammps\").");
  m.def("strength_table", [](const std::string& material, const std::string& set) { return to_dict(shipped_table(set, material)); },
        py::arg("material"), py::arg("set") = "thesis",
        "A shipped strength table sigma_max(p), sigma_dyn(p) [Pa] of material (\"Si\", \"SiO2\") as arrays.");
  m.def("read_strength_table", [](const std::filesystem::path& file) { return to_dict(read_strength_table(file)); }, py::arg("file"),
        "A strength table from a .csv or .h5 file (ValueError naming the file and line for a bad one).");

  py::class_<StrengthLaw>(m, "StrengthLaw", R"(Pressure-dependent shear strengths sigma_max(p), sigma_dyn(p) [Pa] interpolated from a table.

StrengthLaw(material="Si", set="thesis", file="", clamp=False): a shipped table, or a table file.
Beyond the table an ArithmeticError names the pressure and the range, unless clamp=True.)")
      .def(py::init(&law_of), py::arg("material") = "Si", py::arg("set") = "thesis", py::arg("file") = "",
           py::arg("clamp") = false)
      .def_static("constant", &StrengthLaw::constant, py::arg("material"), py::arg("value"), py::arg("p_max"),
                  py::arg("source") = "python",
                  "A pressure-independent law sigma_max = sigma_dyn = value [Pa] on [0, p_max].")
      .def("sigma_max", [](const StrengthLaw& l, const py::object& p) {
             return py::vectorize([&l](double x) { return l.sigma_max(x); })(p);
           }, py::arg("p"),
           "Peak shear strength at pressure p [Pa] (scalar or array).")
      .def("sigma_dyn", [](const StrengthLaw& l, const py::object& p) {
             return py::vectorize([&l](double x) { return l.sigma_dyn(x); })(p);
           }, py::arg("p"),
           "Sliding shear strength at pressure p [Pa] (scalar or array).")
      .def_property_readonly("pressure_range", [](const StrengthLaw& l) { return py::make_tuple(l.min_pressure(), l.max_pressure()); },
                             "(p_min, p_max) of the table [Pa].")
      .def_property_readonly("jumps", &StrengthLaw::jumps, "Pressures where the law jumps [Pa].")
      .def_property_readonly("table", [](const StrengthLaw& l) { return to_dict(l.table()); },
                             "The table interpolated: material, pressure_Pa, sigma_max_Pa, sigma_dyn_Pa arrays, provenance, origin.");

  m.def("critical_pressure", &critical_pressure, py::arg("law"),
        "p_crit solving sigma_max(p) = p (7.5), (9.10) [Pa]: the largest pressure a junction carries.");
  m.def("friction_coefficient", &friction_coefficient, py::arg("law"), py::arg("p_crit"),
        "mu0 = sigma_dyn(p_crit) / p_crit (9.13).");
  m.def("minimum_contact_ratio", &minimum_contact_ratio, py::arg("p_n"), py::arg("p_crit"), "A_min/A0 = p_N/p_crit (7.6).");
  m.def("tangential_resistance", &tangential_resistance, py::arg("law"), py::arg("p_n"), py::arg("contact_ratio"),
        py::arg("peak") = false, "p_T = (A/A0) sigma(p_N A0/A) (7.9) [Pa]; sigma_dyn, or sigma_max with peak=True.");
  m.def("wear_rate", py::overload_cast<double, double>(&wear_rate), py::arg("p_n"), py::arg("p_crit"),
        "Wear volume per apparent area and sliding distance dV/(A0 ds) = p_N/p_crit (9.21).");
  m.def("steady_slope_rms", &steady_slope_rms, py::arg("p_crit"), py::arg("e_star"),
        "Steady RMS slope h'_rms = sqrt(2 pi) p_crit / E* (9.17).");
  m.def("interface_law", [](const std::string& a, const std::string& b, const std::string& set) {
          const auto law = interface_law(a, StrengthLaw(shipped_table(set, a)), b, StrengthLaw(shipped_table(set, b)));
          py::dict d;
          d["pair"] = law.pair;
          d["governing"] = law.governing;
          d["p_crit_Pa"] = law.p_crit;
          d["mu0"] = law.mu0;
          return d;
        }, py::arg("a"), py::arg("b"), py::arg("set") = "thesis",
        "The junction law of the a/b interface from shipped tables: the material with the lower mu0 governs (§9.3.2).");
  m.def("critical_size", [](const std::string& material, double junction_strength, const std::string& geometry) {
          JunctionGeometry g = JunctionGeometry::FlatCircular;
          if (geometry == "colliding") g = JunctionGeometry::CollidingAsperities;
          else if (geometry == "dem") g = JunctionGeometry::DemCylinder;
          else if (geometry != "flat") throw InputError("materials.critical_size: geometry = '" + geometry + "'; allowed: flat | colliding | dem");
          return critical_size(MaterialLibrary().get(material), junction_strength, g);
        }, py::arg("material"), py::arg("junction_strength"), py::arg("geometry") = "flat",
        "d* = c gamma G / sigma_j^2 [m]: c = 12 pi/(2-nu) flat (4.35), 12 colliding (8.3), 32 DEM cylinder (6.65).");
}

}  // namespace wearscale::python
