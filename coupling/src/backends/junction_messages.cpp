#include "junction_messages.hpp"

#include <nlohmann/json.hpp>

namespace wearscale::coupling {

namespace {

using nlohmann::json;

std::string cbor(const json& j) {
  const auto bytes = json::to_cbor(j);
  return {bytes.begin(), bytes.end()};
}

json material(const dem::CohesiveMaterial& m) {
  return {m.name,           m.young,       m.poisson, m.tensile_strength, m.shear_strength,
          m.surface_energy, m.restitution, m.density, m.scaling_exponent};
}

dem::CohesiveMaterial material(const json& j) {
  dem::CohesiveMaterial m;
  m.name = j.at(0).get<std::string>();
  m.young = j.at(1), m.poisson = j.at(2), m.tensile_strength = j.at(3), m.shear_strength = j.at(4);
  m.surface_energy = j.at(5), m.restitution = j.at(6), m.density = j.at(7), m.scaling_exponent = j.at(8);
  return m;
}

}  // namespace

std::string to_message(const dem::JunctionStrengthSpec& s) {
  const auto& c = s.cell;
  return cbor({{"top", material(s.top)},
               {"bottom", material(s.bottom)},
               {"cell", {c.d0, c.length, c.height, c.depth, c.gap, c.wall_thickness}},
               {"amorphous", s.arrangement == dem::Arrangement::Amorphous},
               {"seed", s.seed},
               {"relax", {s.relax_tolerance, s.max_relax_steps}},
               {"loading", {s.contact_ratio, s.pressure, s.velocity, s.time_step, s.settle_distance,
                            s.sliding_distance, s.steady_from}},
               {"record_every", s.record_every},
               {"touching_history", s.history_of_touching_pairs_only},
               {"engine", s.engine}});
}

dem::JunctionStrengthSpec spec_from_message(const std::string& message) {
  const json j = json::from_cbor(message);
  dem::JunctionStrengthSpec s;
  s.top = material(j.at("top"));
  s.bottom = material(j.at("bottom"));
  const auto& c = j.at("cell");
  s.cell.d0 = c.at(0), s.cell.length = c.at(1), s.cell.height = c.at(2), s.cell.depth = c.at(3);
  s.cell.gap = c.at(4), s.cell.wall_thickness = c.at(5);
  s.arrangement = j.at("amorphous").get<bool>() ? dem::Arrangement::Amorphous : dem::Arrangement::Hcp;
  s.seed = j.at("seed");
  s.relax_tolerance = j.at("relax").at(0), s.max_relax_steps = j.at("relax").at(1);
  const auto& l = j.at("loading");
  s.contact_ratio = l.at(0), s.pressure = l.at(1), s.velocity = l.at(2), s.time_step = l.at(3);
  s.settle_distance = l.at(4), s.sliding_distance = l.at(5), s.steady_from = l.at(6);
  s.record_every = j.at("record_every");
  s.history_of_touching_pairs_only = j.at("touching_history");
  s.engine = j.at("engine").get<std::string>();
  return s;
}

std::string to_message(const dem::JunctionStrengthResult& r) {
  json history = json::array();
  for (const auto& h : r.history)
    history.push_back({h.time, h.sliding, h.tangential_force, h.normal_force, h.kinetic_energy});
  return cbor({{"cell", {r.length, r.depth, r.height, r.gap}},
               {"particles", {r.particles, r.junction_particles}},
               {"time_step", r.time_step},
               {"steps", r.steps},
               {"contact_ratio", {r.initial_contact_ratio, r.loaded_contact_ratio, r.final_contact_ratio}},
               {"stress", {r.peak_tangential, r.steady_tangential, r.normal}},
               {"motion", {r.rolling_rate, r.rigid_residual}},
               {"outcome", static_cast<int>(r.outcome)},
               {"history", history}});
}

dem::JunctionStrengthResult result_from_message(const std::string& message) {
  const json j = json::from_cbor(message);
  dem::JunctionStrengthResult r;
  const auto& c = j.at("cell");
  r.length = c.at(0), r.depth = c.at(1), r.height = c.at(2), r.gap = c.at(3);
  r.particles = j.at("particles").at(0), r.junction_particles = j.at("particles").at(1);
  r.time_step = j.at("time_step");
  r.steps = j.at("steps");
  const auto& a = j.at("contact_ratio");
  r.initial_contact_ratio = a.at(0), r.loaded_contact_ratio = a.at(1), r.final_contact_ratio = a.at(2);
  const auto& p = j.at("stress");
  r.peak_tangential = p.at(0), r.steady_tangential = p.at(1), r.normal = p.at(2);
  r.rolling_rate = j.at("motion").at(0), r.rigid_residual = j.at("motion").at(1);
  r.outcome = static_cast<dem::JunctionStrengthResult::Outcome>(j.at("outcome").get<int>());
  for (const auto& h : j.at("history")) {
    dem::JunctionSample x;
    x.time = h.at(0), x.sliding = h.at(1), x.tangential_force = h.at(2), x.normal_force = h.at(3);
    x.kinetic_energy = h.at(4);
    r.history.push_back(x);
  }
  return r;
}

}  // namespace wearscale::coupling
