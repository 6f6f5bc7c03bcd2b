#pragma once
// The keys of the DEM studies (`wearscale dem ...`), each declared once in a
// key table (io/key_table.hpp) against the member it fills: the [dem] table
// (the particles' material, their contact law, the engine) as DemKeys, and
// the keys several studies' tables name alike (d0, time_step, seed, the
// sliding cell of §7.2-7.3, ...), each added to a study's table by one
// function here. A study's own table, in its file, declares the rest.
// Private to the studies.
#include <cstdint>
#include <optional>
#include <string>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/sliding_cell.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/key_table.hpp"

namespace wearscale::studies {

// ---- [dem] ------------------------------------------------------------------

/// What [dem] holds: the material by name, its overrides, the contact law
/// and the engine.
struct DemKeys {
  std::string material = "table-6.4";  ///< "table-6.4" (Table 6.4, unitless), a library record or a [materials.define] name
  double scaling_exponent = dem::CohesiveMaterial{}.scaling_exponent;  ///< s of (6.57)
  std::optional<double> restitution;  ///< η; none: the material's
  std::optional<double> poisson;      ///< ν ≤ 1/4 (6.52); none: the material's
  std::string law = "cohesive";       ///< contact_law.hpp
  double friction = dem::SlidingCellSpec{}.friction;  ///< Coulomb μ of the hooke law
  std::string engine = "wearscale";   ///< engine.hpp
  bool history_of_touching_pairs_only = false;  ///< sliding cells only ([dem] history)
};

/// How a study's [dem] table differs from another's.
struct DemTableOptions {
  std::string materials;                   ///< dem.material's meaning: the names the study takes
  const char* default_material = nullptr;  ///< dem.material's default; none: DemKeys'
  std::string poisson_flag = {};           ///< dem.poisson's alias
  std::string scaling_exponent_flag = {};  ///< dem.scaling_exponent's alias
  bool history = false;                    ///< dem.history: the sliding cell's
  /// The study that measures the cohesive law's strengths (refuses another law), or none.
  const char* cohesive_study = nullptr;
};

/// The [dem] table of a study.
KeyTable<DemKeys> dem_table(const DemTableOptions& options);
/// [dem] as read, and the material it names.
struct DemInputs {
  DemKeys keys;
  dem::CohesiveMaterial material;
};
/// The material [dem] names (its overrides applied), checked modelled: ν ≤ 1/4 (6.52).
dem::CohesiveMaterial dem_material(const Config& root, const DemKeys& keys);
/// Registers the LAMMPS engine for `engine` = "lammps"; refuses it in a build without one.
void require_engine(const Config& dem, const std::string& engine);

/// The sliding cell's material, contact law, tangential histories and engine, from [dem].
void with_dem(const DemInputs& dem, dem::SlidingCellSpec& cell);

// ---- Keys several studies' tables name alike ---------------------------------
// `at` gives the member filled (io/key_table.hpp).

/// d0: the mode of the particle diameters [m]; required unless `required` is false.
template <class K, class At>
void add_d0(KeyTable<K>& t, At at, std::string doc = "mode of the particle diameters", bool required = true) {
  t.number("d0", at, Range::positive(), units::length, std::move(doc)).flag("--d0");
  if (required) t.required();
}
/// largest: the largest diameter d_l ≥ d0 [m]; 1.25 d0 (§6.2.3).
template <class K, class At, class D0>
void add_largest(KeyTable<K>& t, At at, D0 d0, std::string doc = "largest particle diameter") {
  t.number("largest", at, Range::positive(), units::length, std::move(doc))
      .range_from([d0](const K& k) { return Range::at_least(d0(k)); }, "≥ d0")
      .computed_default([d0](const K& k) { return 1.25 * d0(k); }, "1.25 d0");
}
/// time_step: in the critical time step Δt_c (6.6), in (0, 1).
template <class K, class At>
void add_time_step(KeyTable<K>& t, At at) {
  t.number("time_step", at, Range::open(0.0, 1.0), "time step in Δt_c");
}
/// seed: of the random amorphous sample, in [0, 2^32).
template <class K, class At>
void add_seed(KeyTable<K>& t, At at, std::string doc = "seed of the amorphous sample") {
  t.integer("seed", at, Range::closed(0, 4294967295.0), std::move(doc)).allowed("[0, 4294967295]").flag("--seed");
}
/// velocity: of the moving wall [m/s], in (0, 1000).
template <class K, class At>
void add_sliding_velocity(KeyTable<K>& t, At at, std::string doc = "sliding velocity of the top wall") {
  t.number("velocity", at, Range::open(0.0, 1000.0), units::velocity, std::move(doc)).flag("--velocity");
}
/// pressure: p_N on the pressed wall [Pa], in [0, σ_m,N] of the material
/// (beyond the normal strength the cohesive model holds no solid).
template <class K, class At, class M>
void add_pressure(KeyTable<K>& t, At at, M material, std::string doc = "normal pressure on the top wall") {
  t.number("pressure", at, Range::non_negative(), units::pressure, std::move(doc))
      .range_from([material](const K& k) { return Range::closed(0.0, material(k).tensile_strength); }, "[0, σ_m,N]")
      .flag("--pressure");
}
/// sliding_distance: how far the moving wall slides [m], > 0; `fallback` of the keys read before.
template <class K, class At, class F>
void add_sliding_distance(KeyTable<K>& t, At at, F fallback, std::string text) {
  t.number("sliding_distance", at, Range::positive(), units::length, "sliding distance")
      .computed_default(std::move(fallback), std::move(text))
      .flag("--slide");
}
/// box: the cell size [x, y, z] [m], three lengths > 0.
template <class K, class At>
void add_box(KeyTable<K>& t, At at, const dem::Vec3& initial, std::string doc) {
  t.custom("box", "list", "three lengths > 0", "m", std::move(doc), [at](const Config& c, const std::string& key, K& k) {
     if (!c.has(key)) return;
     const auto b = c.numbers(key, Range::positive(), units::length);
     if (b.size() != 3) throw c.error(key, std::to_string(b.size()) + " values", "three lengths [x, y, z]");
     std::invoke(at, k) = dem::Vec3{b[0], b[1], b[2]};
   }).fallback("[" + key_table_detail::default_text(initial.x) + ", " + key_table_detail::default_text(initial.y) +
               ", " + key_table_detail::default_text(initial.z) + "]");
}
/// wall_thickness: a wall's thickness in d0, in [1, 10] (§6.3).
template <class K, class At>
void add_wall_thickness(KeyTable<K>& t, At at, std::string doc = "wall thickness in d0") {
  t.number("wall_thickness", at, Range::closed(1.0, 10.0), std::move(doc));
}
/// clearance: the gap left around a loose body, in d0, in [0, 1).
template <class K, class At>
void add_clearance(KeyTable<K>& t, At at, std::string doc) {
  t.number("clearance", at, Range::closed_open(0.0, 1.0), std::move(doc));
}
/// record_every: steps per history sample, ≥ 1.
template <class K, class At>
void add_record_every(KeyTable<K>& t, At at) {
  t.integer("record_every", at, Range::at_least(1), "steps per history sample");
}
/// relax_tolerance and max_relax_steps: the relaxation of the amorphous sample (§6.2.2).
template <class K, class Tolerance, class Steps>
void add_relaxation(KeyTable<K>& t, Tolerance tolerance, Steps steps) {
  t.number("relax_tolerance", tolerance, Range::open(0.0, 1e-2), "stress tolerance of the relaxation, in E")
      .integer("max_relax_steps", steps, Range::at_least(0), "relaxation step limit");
}
/// dump_every: steps between OVITO snapshot frames, ≥ 0 (0: none).
template <class K, class At>
void add_dump_every(KeyTable<K>& t, At at) {
  t.integer("dump_every", at, Range::at_least(0), "steps between OVITO dump frames (0: none)");
}

// ---- The sliding cell of the wear studies (§7.2, §7.3) ---------------------

/// The keys of the sliding cell (sliding_cell.hpp) the wear studies share,
/// `cell` giving the study's cell (`[](auto& k) -> auto& { return k.spec.cell; }`);
/// its size is each study's (add_cell_depth).
template <class K, class Cell>
void add_sliding_cell(KeyTable<K>& t, Cell cell) {
  using S = dem::SlidingCellSpec;
  const auto at = [cell](auto member) { return [cell, member](K& k) -> auto& { return cell(k).*member; }; };
  const auto d0 = [cell](const K& k) { return cell(k).d0; };
  add_d0(t, at(&S::d0));
  add_largest(t, at(&S::largest), d0);
  add_sliding_velocity(t, at(&S::velocity));
  add_pressure(t, at(&S::pressure), [cell](const K& k) -> const dem::CohesiveMaterial& { return cell(k).material; });
  add_time_step(t, at(&S::time_step));
  t.number("settle_distance", at(&S::settle_distance), Range::non_negative(), units::length,
           "loading at rest before sliding, for the time the wall takes to slide this far")
      .computed_default(d0, "d0");
  t.number("wall_damping", at(&S::wall_damping), Range::closed(0.0, 1.0),
           "damping of the pressed wall's normal motion, in the critical damping");
  add_wall_thickness(t, at(&S::wall_thickness));
  add_record_every(t, at(&S::record_every));
  add_seed(t, at(&S::seed));
  add_relaxation(t, at(&S::relax_tolerance), at(&S::max_relax_steps));
}

/// depth: the cell depth W, periodic down to the largest particle (a pair
/// meets several images of a neighbour across a thinner-than-cutoff depth,
/// neighbor_list.hpp); 3.5 d0.
template <class K, class Cell>
void add_cell_depth(KeyTable<K>& t, Cell cell) {
  t.number("depth", [cell](K& k) -> double& { return cell(k).box.y; }, Range::positive(), units::length,
           "cell depth W (periodic)")
      .range_from([cell](const K& k) { return Range::at_least(cell(k).largest); }, "≥ largest")
      .computed_default([cell](const K& k) { return 3.5 * cell(k).d0; }, "3.5 d0");
}

}  // namespace wearscale::studies
