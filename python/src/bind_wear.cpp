// wearscale.wear: the analytic wear maps of one (Fig. 3.7) and two (Fig. 4.6)
// micro-contacts and the numerical rough wear map (§5.3).
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/studies/wearmap_keys.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/candidate_particles.hpp"
#include "wearscale/wear/energy_release.hpp"
#include "wearscale/wear/rough_wear_map.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"

namespace wearscale::python {

namespace {

using namespace wearscale::wear;

// The particle case of (4.48) from its number; any other number is refused
// (a cast would give C_case = 0 and so a boundary at d*/l = 0, silently).
ParticleCase particle_case_from(int c, const char* what) {
  if (c < 0 || c > 2)
    throw InputError(std::string(what) + ": case = " + std::to_string(c) +
                     "; allowed: 0 (one separated) | 1 (two separated) | 2 (combined)");
  return static_cast<ParticleCase>(c);
}

MapAxis axis(MapAxis a, double lo, double hi, std::size_t n) {
  a.min = lo;
  a.max = hi;
  a.n = n;
  return a;
}

py::dict to_dict(const WearMap& map) {
  py::dict d;
  d["kind"] = map.kind;
  d["title"] = map.title;
  d["x_name"] = map.x.name;
  d["y_name"] = map.y.name;
  d["x"] = owned(map.x.values());
  d["y"] = owned(map.y.values());
  py::array_t<int> region({map.x.n, map.y.n});
  std::copy(map.region.begin(), map.region.end(), region.mutable_data());
  d["region"] = region;
  d["region_names"] = map.region_names;
  py::dict layers;
  for (const auto& l : map.layers) {
    py::array_t<double> a({map.x.n, map.y.n});
    std::copy(l.values.begin(), l.values.end(), a.mutable_data());
    layers[py::str(l.name)] = a;
  }
  d["layers"] = layers;
  d["parameters"] = map.parameters;
  return d;
}

using BoolArray = py::array_t<bool, py::array::c_style | py::array::forcecast>;

Grid2D square_cells(const BoolArray& a, double lx, const std::string& what) {
  if (a.ndim() != 2) throw InputError(what + ": a 2D mask is needed");
  const auto nx = static_cast<std::size_t>(a.shape(0)), ny = static_cast<std::size_t>(a.shape(1));
  return Grid2D(nx, ny, lx, lx * static_cast<double>(ny) / static_cast<double>(nx));
}

Disc disc_of(const std::tuple<long, long, long>& d, const Grid2D& g) {
  Disc disc{std::get<0>(d), std::get<1>(d), std::get<2>(d)};
  if (disc.cells < 1 || disc.i < 0 || disc.j < 0 || disc.i + disc.cells > static_cast<long>(g.nx) ||
      disc.j >= static_cast<long>(g.ny))
    throw InputError("wear: disc (i, j, cells) = (" + std::to_string(disc.i) + ", " + std::to_string(disc.j) + ", " +
                     std::to_string(disc.cells) + "); allowed: cells >= 1, 0 <= i, i + cells <= nx = " +
                     std::to_string(g.nx) + ", 0 <= j < ny = " + std::to_string(g.ny));
  return disc;
}

py::array disc_mask(std::size_t nx, std::size_t ny, const std::tuple<long, long, long>& d) {
  require_memory(static_cast<double>(nx) * static_cast<double>(ny), fmt::format("a {} × {} mask", nx, ny),
                 "use a smaller grid");
  const Grid2D g(nx, ny, 1.0, static_cast<double>(ny) / static_cast<double>(nx));
  const Disc disc = disc_of(d, g);
  py::array_t<bool> out({nx, ny});
  auto* o = out.mutable_data();
  std::fill(o, o + nx * ny, false);
  disc.for_each_row(g, [&](long j, long first, long last) {
    for (long i = first; i <= last; ++i) o[static_cast<std::size_t>(i) * ny + static_cast<std::size_t>(j)] = true;
  });
  return out;
}

py::dict energy_release(const BoolArray& contact, double lx, double shear_modulus, double poisson,
                        double junction_strength, const std::tuple<long, long, long>& d) {
  const Grid2D g = square_cells(contact, lx, "wear.energy_release");
  const Disc disc = disc_of(d, g);
  std::vector<std::uint8_t> loaded(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) loaded[k] = contact.data()[k] ? 1 : 0;
  double work = 0.0, self = 0.0, energy = 0.0;
  {
    py::gil_scoped_release release;
    const TangentialCompliance f(g, shear_modulus, poisson);
    const EnergyRelease er(f, junction_strength);
    RealField p(g), u(g);
    auto w = f.workspace();
    er.traction(loaded, p);
    f.displacement(p, u, w);
    energy = f.energy(p, u);
    DiscSums sums(g);
    sums.build(loaded, &u);
    work = junction_strength * g.cell_area() * sums.sum(disc);  // W_C
    self = er.self_energy(disc, loaded);
  }
  py::dict out;
  out["release_J"] = EnergyRelease::release(work, self);
  out["work_J"] = work;
  out["self_energy_J"] = self;
  out["elastic_energy_J"] = energy;
  out["disc_diameter_m"] = disc.diameter(g);
  return out;
}

}  // namespace

void bind_wear(py::module_& m) {
  // The keyword defaults: the wear-map studies' (their keys' structs), and the map's spec.
  static const studies::WearmapAnalytic2dKeys map_2d{};
  static const studies::WearmapAnalytic3dKeys map_3d{};
  static const RoughWearMapSpec map_defaults{};
  m.def("analytic_map_2d", [](double x_max, double y_max, std::size_t nx, std::size_t ny) {
          WearMap map;
          {
            py::gil_scoped_release release;
            map = analytic_map_2d(axis(default_real_size_axis(), 0, x_max, nx), axis(default_apparent_size_axis(), 0, y_max, ny));
          }
          return to_dict(map);
        }, py::arg("x_max") = map_2d.dr_over_dstar.second, py::arg("y_max") = map_2d.da_over_dstar.second,
        py::arg("nx") = map_2d.n, py::arg("ny") = map_2d.n,
        R"(The 2D analytic wear map of Fig. 3.7 over d_r/d* in [0, x_max] and d_a/d* in [0, y_max] (cell centres).

Returns a dict: x, y (axes), region (nx, ny) int codes with region_names, layers {name: (nx, ny)}.)");
  m.def("analytic_map_3d", [](double c_inter, double x_max, double y_max, std::size_t nx, std::size_t ny) {
          WearMap map;
          {
            py::gil_scoped_release release;
            map = analytic_map_3d(axis(default_d_over_l_axis(), 0, x_max, nx), axis(default_dstar_over_l_axis(), 0, y_max, ny), c_inter);
          }
          return to_dict(map);
        }, py::arg("c_inter") = interaction_constant(map_3d.nu, map_3d.theta),
        py::arg("x_max") = map_3d.d_over_l.second, py::arg("y_max") = map_3d.dstar_over_l.second,
        py::arg("nx") = map_3d.n, py::arg("ny") = map_3d.n,
        R"(The two-micro-contact wear map of Fig. 4.6 over d/l in [0, x_max <= 1] and d*/l in [0, y_max].

c_inter in [1/3, 2/3]: the interaction constant (4.49) (interaction_constant(nu, theta)); the
regions are the most severe detachment with R >= 1 of (4.48): 0 plastic, 1 one separated
particle, 2 two separated, 3 combined. Returns the same dict as analytic_map_2d.)");
  m.def("interaction_constant", &interaction_constant, py::arg("poisson"), py::arg("angle") = 0.0,
        "C_inter = (1 - nu sin^2 theta)/(2 - nu) (4.49); -1 < nu <= 0.5, theta [rad] the angle of the contacts' line to the traction.");
  m.def("boundary_dstar_over_l", [](int particle_case, const InArray& d_over_l, double c_inter) {
          const ParticleCase pc = particle_case_from(particle_case, "wear.boundary_dstar_over_l");
          return py::vectorize([pc, c_inter](double x) {
            return boundary_dstar_over_l(pc, x, c_inter);
          })(static_cast<const InArray::Base&>(d_over_l));
        }, py::arg("case"), py::arg("d_over_l"), py::arg("c_inter"),
        "d*/l on the line R = 1 (4.48) of case 0 (one separated), 1 (two separated) or 2 (combined) at d/l.");
  m.def("energy_ratio_3d", [](int particle_case, double d_over_l, double dstar_over_l, double c_inter) {
          return energy_ratio_3d(particle_case_from(particle_case, "wear.energy_ratio_3d"), d_over_l, dstar_over_l, c_inter);
        }, py::arg("case"), py::arg("d_over_l"), py::arg("dstar_over_l"), py::arg("c_inter"),
        "R = (C_n + (3 pi/8) C_inter d/l)(d/d*) C_case (4.48).");
  m.def("disc_mask", &disc_mask, py::arg("nx"), py::arg("ny"), py::arg("disc"),
        "The cells of a disc (i, j, cells): its diameter along x runs over `cells` cells from (i, j) to "
        "(i + cells - 1, j); a cell belongs to it when its centre lies within cells/2 of the disc's centre.");
  m.def("energy_release", &energy_release, py::arg("contact"), py::arg("lx"), py::arg("shear_modulus"),
        py::arg("poisson"), py::arg("junction_strength"), py::arg("disc"),
        R"(The elastic energy released (5.3) by detaching one candidate particle: the disc (i, j, cells) cut
out of micro-contacts `contact` (a bool (nx, ny) mask on a free window lx [m] wide, square cells)
loaded by the tangential traction p_x = junction_strength [Pa] (§5.2). Returns release_J
(= work_J - self_energy_J: W_C = dA sigma_j sum_C u minus 1/2 dA p_C.(F p_C)), and the elastic energy
of the whole loading elastic_energy_J = 1/2 dA sum p u (4.2). shear_modulus [Pa], -1 < poisson <= 0.5.)");
  m.def("rough_wear_map", [](std::size_t n, double hurst, double k_l, double k_s, double poisson,
                             std::vector<std::uint64_t> seeds, std::vector<double> loads,
                             std::vector<double> critical_diameters, double tensile_strength) {
          RoughWearMapSpec spec;
          spec.surface.n = n;
          spec.surface.hurst = hurst;
          spec.surface.k_l = k_l;
          spec.surface.k_s = k_s;
          spec.surface.poisson = poisson;
          spec.seeds = std::move(seeds);
          spec.loads = std::move(loads);
          spec.critical_diameters = std::move(critical_diameters);
          spec.tensile_strength = tensile_strength;
          RoughWearMap map;
          {
            py::gil_scoped_release release;
            map = rough_wear_map(spec);
          }
          const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
          auto grid = [&](auto member) {
            py::array_t<double> a({nl, nd});
            for (std::size_t k = 0; k < map.pixels.size(); ++k) a.mutable_data()[k] = map.pixels[k].*member;
            return a;
          };
          py::dict d;
          d["loads"] = spec.loads;
          d["critical_diameters"] = spec.critical_diameters;
          d["count_mean"] = grid(&WearMapPixel::count_mean);
          d["count_sd"] = grid(&WearMapPixel::count_sd);
          d["volume_mean"] = grid(&WearMapPixel::volume_mean);
          d["volume_sd"] = grid(&WearMapPixel::volume_sd);
          d["largest_mean"] = grid(&WearMapPixel::largest_mean);
          d["contact_fraction"] = grid(&WearMapPixel::contact_fraction);
          py::array_t<bool> valid({nl, nd});
          for (std::size_t k = 0; k < map.pixels.size(); ++k) valid.mutable_data()[k] = map.pixels[k].valid;
          d["valid"] = valid;
          d["particles"] = map.particles.size();
          d["candidates"] = map.candidates;
          return d;
        }, py::arg("n") = 128, py::arg("hurst") = map_defaults.surface.hurst, py::arg("k_l") = map_defaults.surface.k_l,
        py::arg("k_s") = 16.0, py::arg("poisson") = map_defaults.surface.poisson, py::arg("seeds") = std::vector<std::uint64_t>{1}, py::kw_only(), py::arg("loads"),
        py::arg("critical_diameters"), py::arg("tensile_strength") = map_defaults.tensile_strength,
        R"(The numerical wear map of rough surfaces (§5.3): particles detached by sheared micro-contacts.

n: grid; hurst, k_l, k_s: the surface (§5.3: 512, 0.8, 8, n/8); loads (keyword): normalised p_N, increasing;
critical_diameters: d*/L; tensile_strength: sigma_m/sigma_j (4.25). Returns (loads x d*) arrays of
the particle count, wear volume / L^3 (mean, sd over seeds), largest particle / L, A/A0, validity.)");
}

}  // namespace wearscale::python
