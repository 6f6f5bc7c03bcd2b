// Checkpoints of a DEM system: its dynamic state as named arrays of doubles
// (integers and flags are stored exactly: all are far below 2^53).
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

namespace {

// Format 2 adds the reach of the periodic images the neighbour list's shift
// indices refer to (lists of thin periodic cells meet several images);
// format 1 is read as its 27 nearest images. Format 3 (a renumbered system)
// adds the numbering of the neighbour list: the particles are stored in the
// user's order, the list in the system's own ("dem.order": the user's
// particle in each slot); a system never renumbered still writes format 2.
constexpr const char* kFormat3 = "wearscale-dem-state-3";
constexpr const char* kFormat = "wearscale-dem-state-2";
constexpr const char* kFormat1 = "wearscale-dem-state-1";

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

template <class T>
std::vector<double> as_doubles(const std::vector<T>& v) {
  return {v.begin(), v.end()};
}

// The entry `name`, which must hold `count` values.
const std::vector<double>& sized(const CheckpointState& in, const std::string& name, std::size_t count) {
  const auto& a = in.array(name);
  if (a.size() != count)
    throw InputError(fmt::format("{}: DEM state entry '{}' holds {} values, expected {}: not the state of this system",
                                 in.origin, name, a.size(), count));
  return a;
}

// A checksum proves a checkpoint's bytes, not that they are a state a run reaches: every restored value is
// held to what a computed state is (finite positions, velocities, forces; counts whole and within their type),
// before it is converted.
[[noreturn]] void refuse(const CheckpointState& in, const std::string& name, const std::string& problem) {
  throw InputError(fmt::format("{}: DEM state entry '{}' {}: no state a run reaches; the checkpoint was changed or "
                               "written by another program: delete it to start afresh",
                               in.origin, name, problem));
}

const std::vector<double>& finite(const CheckpointState& in, const std::string& name, const std::vector<double>& a) {
  for (const double v : a)
    if (!std::isfinite(v)) refuse(in, name, fmt::format("holds {}", v));
  return a;
}

void unflatten(const CheckpointState& in, const std::string& name, std::vector<Vec3>& out) {
  const auto& a = finite(in, name, sized(in, name, 3 * out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {a[3 * i], a[3 * i + 1], a[3 * i + 2]};
}

// Integers stored as doubles: whole numbers within the type's range, checked before the conversion.
template <class T>
T whole(const CheckpointState& in, const std::string& name, double v) {
  if (!(v == std::floor(v) && v >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
        v <= static_cast<double>(std::numeric_limits<T>::max())))
    refuse(in, name, fmt::format("holds {:g} where a whole number is stored", v));
  return static_cast<T>(v);
}

template <class T>
void from_doubles(const CheckpointState& in, const std::string& name, std::vector<T>& out) {
  const auto& a = sized(in, name, out.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = whole<T>(in, name, a[i]);
}

Vec3 vec(const CheckpointState& in, const std::string& name) {
  const auto& a = finite(in, name, sized(in, name, 3));
  return {a[0], a[1], a[2]};
}

void put(CheckpointState& out, const std::string& name, const Vec3& v) {
  const double a[3] = {v.x, v.y, v.z};
  out.put(name, a);
}

}  // namespace

void NeighborList::save(CheckpointState& out, const std::string& prefix) const {
  out.put(prefix + "offsets", as_doubles(offset_));
  out.put(prefix + "neighbors", as_doubles(neighbor_));
  out.put(prefix + "shifts", as_doubles(shift_));
  out.put(prefix + "images", std::vector<double>{double(images_.reach[0]), double(images_.reach[1]),
                                                 double(images_.reach[2])});
  out.put(prefix + "history", history_);
  out.put(prefix + "built_at", flatten(built_at_));
  out.put(prefix + "half_skin", half_skin_);
  out.put(prefix + "builds", static_cast<double>(builds_));
}

void NeighborList::restore(const CheckpointState& in, const std::string& prefix, const Particles& p,
                           int history_size) {
  history_size_ = history_size;
  const std::size_t particles = p.size();
  images_ = PeriodicImages{};  // format 1: the 27 nearest images
  if (in.has(prefix + "images")) {
    const auto& reach = sized(in, prefix + "images", 3);
    for (std::size_t a = 0; a < 3; ++a) {
      if (!(reach[a] >= 0.0 && reach[a] <= 127.0) || reach[a] != std::floor(reach[a]))
        throw InputError(fmt::format("{}: DEM state entry '{}images' holds {}: not a reach of periodic images",
                                     in.origin, prefix, reach[a]));
      images_.reach[a] = static_cast<int>(reach[a]);
    }
    if (images_.count() > PeriodicImages::max_count)
      throw InputError(fmt::format("{}: DEM state entry '{}images' names {} periodic images, more than {}", in.origin,
                                   prefix, images_.count(), PeriodicImages::max_count));
  }
  const std::size_t pairs = in.array(prefix + "neighbors").size();
  const bool built = !in.array(prefix + "offsets").empty();
  offset_.resize(built ? particles + 1 : 0);
  neighbor_.resize(pairs);
  shift_.resize(pairs);
  history_ = finite(in, prefix + "history", sized(in, prefix + "history", static_cast<std::size_t>(history_size) * pairs));
  built_at_.resize(in.array(prefix + "built_at").size() / 3);
  from_doubles(in, prefix + "offsets", offset_);
  from_doubles(in, prefix + "neighbors", neighbor_);
  from_doubles(in, prefix + "shifts", shift_);
  unflatten(in, prefix + "built_at", built_at_);
  // A list built without keeping its positions (check_displacement off) saves none.
  for (std::size_t i = 1; i < offset_.size(); ++i)  // each particle's pairs a run of the list, in order
    if (offset_[i] < offset_[i - 1] || offset_[i] > pairs)
      refuse(in, prefix + "offsets", fmt::format("does not grow from 0 to the {} pairs", pairs));
  if (!offset_.empty() && offset_.front() != 0) refuse(in, prefix + "offsets", "does not start at 0");
  if (built && (offset_.back() != pairs || (!built_at_.empty() && built_at_.size() != particles)))
    throw InputError(fmt::format("{}: the DEM neighbour list in '{}' does not fit {} particles", in.origin, prefix,
                                 particles));
  for (std::uint32_t j : neighbor_)
    if (j >= particles)
      throw InputError(fmt::format("{}: the DEM neighbour list in '{}' names particle {} of {}", in.origin, prefix, j,
                                   particles));
  for (std::uint8_t s : shift_)
    if (s >= images_.count())
      throw InputError(fmt::format("{}: the DEM neighbour list in '{}' names periodic image {} of {}", in.origin,
                                   prefix, s, images_.count()));
  built_image_.resize(particles);  // images change only at builds
  for (std::size_t i = 0; i < particles; ++i) built_image_[i] = image_low_bytes(p.image[i]);
  half_skin_ = in.scalar(prefix + "half_skin");
  if (!(std::isfinite(half_skin_) && half_skin_ >= 0.0)) refuse(in, prefix + "half_skin", fmt::format("holds {}", half_skin_));
  builds_ = in.count(prefix + "builds", 0.0, 9e15);
  old_offset_.clear();
  old_neighbor_.clear();
  old_shift_.clear();
  several_images_ = true;  // not known: the next carry-over checks its order
}

void Simulation::save_state(CheckpointState& out) const {
  in_user_order();
  const Particles& p = particles_;
  out.put_text("dem.format", user_of_.empty() ? kFormat : kFormat3);
  if (!user_of_.empty()) out.put("dem.order", as_doubles(user_of_));
  out.put("dem.position", flatten(p.position));
  out.put("dem.velocity", flatten(p.velocity));
  out.put("dem.omega", flatten(p.omega));
  out.put("dem.force", flatten(p.force));
  out.put("dem.torque", flatten(p.torque));
  out.put("dem.radius", p.radius);
  out.put("dem.mass", p.mass);
  out.put("dem.inv_mass", p.inv_mass);
  out.put("dem.inv_inertia", p.inv_inertia);
  out.put("dem.id", as_doubles(p.id));
  out.put("dem.material", as_doubles(p.material));
  out.put("dem.body", as_doubles(p.body));
  out.put("dem.wall", as_doubles(p.wall));
  std::vector<double> image;
  image.reserve(3 * p.size());
  for (const auto& im : p.image) image.insert(image.end(), im.begin(), im.end());
  out.put("dem.image", image);

  put(out, "dem.box.lo", box_.lo);
  put(out, "dem.box.hi", box_.hi);
  out.put("dem.box.periodic", std::vector<double>{double(box_.periodic[0]), double(box_.periodic[1]),
                                                  double(box_.periodic[2])});

  out.put("dem.walls", static_cast<double>(walls_.size()));
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& wall = walls_[w];
    const WallMotion& m = wall.motion;
    const std::string k = fmt::format("dem.wall{}.", w);
    out.put(k + "members", as_doubles(wall.members));
    out.put(k + "motion", std::vector<double>{double(static_cast<int>(m.kind)), m.velocity.x, m.velocity.y,
                                              m.velocity.z, double(m.axis), m.pressure, m.area, double(m.outward),
                                              m.mass, m.damping});
    out.put(k + "mass", wall.mass);
    put(out, k + "velocity", wall.velocity);
    put(out, k + "force", wall.force);
    put(out, k + "displacement", wall.displacement);
  }

  neighbors_.save(out, "dem.list.");
  out.put("dem.clock", std::vector<double>{double(step_), double(since_build_), time_, dt_, double(forces_valid_),
                                           global_damping_});
  if (track_virial_) {
    std::vector<double> v;
    v.reserve(6 * virial_.size());
    for (const auto& t : virial_) v.insert(v.end(), t.begin(), t.end());
    out.put("dem.virial", v);
  }
}

void Simulation::restore_state(const CheckpointState& in) {
  if (!in.has("dem.format") ||
      (in.text("dem.format") != kFormat3 && in.text("dem.format") != kFormat && in.text("dem.format") != kFormat1))
    throw InputError(fmt::format("{}: not a DEM state of this version (expected format '{}', '{}' or '{}')", in.origin,
                                 kFormat3, kFormat, kFormat1));
  in_user_order();
  const std::size_t n = in.array("dem.radius").size();
  Particles& p = particles_;
  // A state of as many particles as this set-up must be of the same
  // particles in the same order (the study's own indices, walls and subsets,
  // are the set-up's): a checkpoint written by a version that numbered the
  // particles otherwise, or made them otherwise, is refused, not mixed in.
  if (n == p.size() && in.array("dem.radius") != p.radius)
    throw InputError(fmt::format("{}: the checkpoint's particles are not this run's (another numbering or another "
                                 "sample: written by another version of wearscale, or for another case); start the "
                                 "run again without --resume",
                                 in.origin));
  p.for_each_array([n](auto& v) { v.resize(n); });
  unflatten(in, "dem.position", p.position);
  unflatten(in, "dem.velocity", p.velocity);
  unflatten(in, "dem.omega", p.omega);
  unflatten(in, "dem.force", p.force);
  unflatten(in, "dem.torque", p.torque);
  p.radius = finite(in, "dem.radius", in.array("dem.radius"));
  for (const double r : p.radius)
    if (!(r > 0.0)) refuse(in, "dem.radius", fmt::format("holds a radius {:g}", r));
  p.mass = sized(in, "dem.mass", n);
  p.inv_mass = finite(in, "dem.inv_mass", sized(in, "dem.inv_mass", n));
  p.inv_inertia = finite(in, "dem.inv_inertia", sized(in, "dem.inv_inertia", n));
  from_doubles(in, "dem.id", p.id);
  from_doubles(in, "dem.material", p.material);
  from_doubles(in, "dem.body", p.body);
  from_doubles(in, "dem.wall", p.wall);
  const auto& image = sized(in, "dem.image", 3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < 3; ++a) p.image[i][a] = whole<std::int32_t>(in, "dem.image", image[3 * i + a]);

  box_.lo = vec(in, "dem.box.lo");
  box_.hi = vec(in, "dem.box.hi");
  if (!(box_.hi.x > box_.lo.x && box_.hi.y > box_.lo.y && box_.hi.z > box_.lo.z))
    refuse(in, "dem.box.hi", "is not above dem.box.lo");
  const auto& periodic = sized(in, "dem.box.periodic", 3);
  for (std::size_t a = 0; a < 3; ++a) box_.periodic[a] = periodic[a] != 0.0;

  const auto walls = static_cast<std::size_t>(in.count("dem.walls", 0.0, 1024.0));
  walls_.assign(walls, Wall{});
  for (std::size_t w = 0; w < walls; ++w) {
    Wall& wall = walls_[w];
    const std::string k = fmt::format("dem.wall{}.", w);
    const auto& members = in.array(k + "members");
    wall.members.clear();
    for (const double i : members) wall.members.push_back(whole<std::size_t>(in, k + "members", i));
    for (std::size_t i : wall.members)
      if (i >= n) throw InputError(fmt::format("{}: DEM wall {} names particle {} of {}", in.origin, w, i, n));
    const auto& m = finite(in, k + "motion", sized(in, k + "motion", 10));
    const int kind = whole<int>(in, k + "motion", m[0]), axis = whole<int>(in, k + "motion", m[4]),
              outward = whole<int>(in, k + "motion", m[7]);
    if (kind < 0 || kind > 2 || axis < 0 || axis > 2 || (outward != 1 && outward != -1))
      refuse(in, k + "motion", fmt::format("holds a wall motion of kind {}, axis {}, side {}", kind, axis, outward));
    wall.motion.kind = static_cast<WallMotion::Kind>(kind);
    wall.motion.velocity = {m[1], m[2], m[3]};
    wall.motion.axis = axis;
    wall.motion.pressure = m[5];
    wall.motion.area = m[6];
    wall.motion.outward = outward;
    wall.motion.mass = m[8];
    wall.motion.damping = m[9];
    wall.mass = in.scalar(k + "mass");
    wall.velocity = vec(in, k + "velocity");
    wall.force = vec(in, k + "force");
    wall.displacement = vec(in, k + "displacement");
  }

  // The list's numbering: the user's particle in each slot, a permutation.
  user_of_.clear();
  slot_of_.clear();
  if (in.text("dem.format") == kFormat3) {
    const auto& order = sized(in, "dem.order", n);
    slot_of_.assign(n, static_cast<std::uint32_t>(n));
    user_of_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double u = order[k];
      if (!(u >= 0.0 && u < static_cast<double>(n)) || u != std::floor(u) || slot_of_[static_cast<std::size_t>(u)] != n)
        throw InputError(fmt::format("{}: DEM state entry 'dem.order' is not a numbering of its {} particles", in.origin,
                                     n));
      user_of_[k] = static_cast<std::uint32_t>(u);
      slot_of_[static_cast<std::size_t>(u)] = static_cast<std::uint32_t>(k);
    }
  }
  map_walls();
  if (track_virial_) {
    virial_.assign(n, SymTensor{});
    if (in.has("dem.virial")) {
      const auto& v = sized(in, "dem.virial", 6 * n);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < 6; ++c) virial_[i][c] = v[6 * i + c];
    }
  }
  const SlotOrder slots(*this);  // the list, its images and per-pair parameters in the list's numbering
  neighbors_.restore(in, "dem.list.", p, law_->history_size());
  const auto& clock = finite(in, "dem.clock", sized(in, "dem.clock", 6));
  step_ = whole<long>(in, "dem.clock", clock[0]);
  since_build_ = whole<long>(in, "dem.clock", clock[1]);  // −1: the list is rebuilt at the next step
  if (step_ < 0 || since_build_ < -1 || since_build_ > step_ || clock[2] < 0.0 || !(clock[3] > 0.0))
    refuse(in, "dem.clock", fmt::format("holds step {}, {} steps since the last build, time {:g}, step {:g}", step_,
                                        since_build_, clock[2], clock[3]));
  time_ = clock[2];
  dt_ = clock[3];
  global_damping_ = clock[5];
  neighbors_.shift_vectors(box_, shift_table_.data());
  if (neighbors_.offsets().empty()) {
    forces_valid_ = false;  // saved before the first step: the list is built then
  } else {
    prepare_pairs();  // per-pair parameters and thread buffers for the restored list
    forces_valid_ = clock[4] != 0.0;
  }
}

}  // namespace wearscale::dem
