#include "lammps_system.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#define LAMMPS_LIB_MPI 1
#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "fix_wearscale_history.hpp"
#include "force.h"
#include "group.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "pair_wearscale.hpp"
#include "pair_wearscale_cohesive.hpp"
#include "pair_wearscale_hooke.hpp"
#include "timer.h"
#include "wearscale/core/errors.hpp"

namespace wearscale::dem::lammps {

using LAMMPS_NS::LAMMPS;

namespace {

constexpr const char* verlet_id = "wearscale_verlet";

LAMMPS_NS::Pair* make_cohesive(LAMMPS* lmp) { return new PairWearscaleCohesive(lmp); }
LAMMPS_NS::Pair* make_hooke(LAMMPS* lmp) { return new PairWearscaleHooke(lmp); }
LAMMPS_NS::Fix* make_history(LAMMPS* lmp, int narg, char** arg) { return new FixWearscaleHistory(lmp, narg, arg); }
LAMMPS_NS::Fix* make_verlet(LAMMPS* lmp, int narg, char** arg) { return new FixWearscaleVerlet(lmp, narg, arg); }

std::string wall_group(std::size_t w) { return fmt::format("wearscale_wall{}", w); }

}  // namespace

void register_styles(LAMMPS* lmp) {
  (*lmp->force->pair_map)["wearscale/cohesive"] = &make_cohesive;
  (*lmp->force->pair_map)["wearscale/hooke"] = &make_hooke;
  (*lmp->modify->fix_map)["wearscale/history"] = &make_history;
  (*lmp->modify->fix_map)["wearscale/verlet"] = &make_verlet;
}

void LammpsSystem::open() {
  const char* args[] = {"wearscale", "-log", "none", "-screen", "none", "-nocite"};
  lmp_ = new LAMMPS(static_cast<int>(std::size(args)), const_cast<char**>(args), comm_);
  register_styles(lmp_);
}

void LammpsSystem::command(const std::string& line) { lmp_->input->one(line); }

LammpsSystem::LammpsSystem(MPI_Comm comm, SystemConfig config, const AtomTable& atoms)
    : comm_(comm), config_(std::move(config)), count_(atoms.count), wall_of_(atoms.count, no_wall) {
  MPI_Comm_rank(comm_, &rank_);
  for (int a = 0; a < 3; ++a)
    if (config_.box.periodic[static_cast<std::size_t>(a)] && !(config_.box.hi[a] > config_.box.lo[a]))
      throw InputError(fmt::format("DEM box: periodic axis {} has hi ≤ lo", "xyz"[a]));
  open();
  command("units si");
  command("atom_style sphere");
  command("atom_modify map array");
  command("dimension 3");
  command("newton on");
  const Box& box = config_.box;
  command(fmt::format("boundary {} {} {}", box.periodic[0] ? "p" : "s", box.periodic[1] ? "p" : "s",
                      box.periodic[2] ? "p" : "s"));
  command("comm_modify vel yes");
  // The box: the periodic lengths as given; the open axes around every particle.
  Vec3 lo = box.lo, hi = box.hi;
  for (std::size_t k = 0; k < atoms.count; ++k)
    for (int a = 0; a < 3; ++a) {
      if (box.periodic[static_cast<std::size_t>(a)]) continue;
      lo[a] = std::min(lo[a], atoms.x[3 * k + static_cast<std::size_t>(a)] - atoms.radius[k]);
      hi[a] = std::max(hi[a], atoms.x[3 * k + static_cast<std::size_t>(a)] + atoms.radius[k]);
    }
  command(fmt::format("region wearscale_box block {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} units box", lo.x, hi.x,
                      lo.y, hi.y, lo.z, hi.z));
  command(fmt::format("create_box {} wearscale_box", config_.law.types));
  created_lo_ = lo;
  created_hi_ = hi;
  std::vector<int> ids(atoms.count);
  for (std::size_t k = 0; k < atoms.count; ++k) ids[k] = static_cast<int>(k + 1);
  lammps_create_atoms(lmp_, static_cast<int>(atoms.count), ids.data(), atoms.type.data(), atoms.x.data(),
                      atoms.v.data(), atoms.image.data(), 1);
  LAMMPS_NS::Atom* atom = lmp_->atom;
  long long made = 0, local = atom->nlocal;
  MPI_Allreduce(&local, &made, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  if (made != static_cast<long long>(atoms.count))
    throw NumericalError("dem (lammps engine)", 0, "particles",
                         fmt::format("LAMMPS created {} of the {} particles", made, atoms.count));
  for (int i = 0; i < atom->nlocal; ++i) {
    const auto k = static_cast<std::size_t>(atom->tag[i] - 1);
    atom->radius[i] = atoms.radius[k];
    atom->rmass[i] = atoms.mass[k];
    for (int a = 0; a < 3; ++a) atom->omega[i][a] = atoms.omega[3 * k + static_cast<std::size_t>(a)];
  }
  configure(true);
}

LammpsSystem::~LammpsSystem() { delete lmp_; }

void LammpsSystem::configure(bool fresh) {
  const LawConfig& law = config_.law;
  const NeighborSettings& nb = config_.neighbors;
  if (law.kind == LawConfig::Kind::Cohesive) {
    command(fmt::format("pair_style wearscale/cohesive history {} cohesion {} tangential {}",
                        nb.history_of_touching_pairs_only ? "touching" : "kept", law.cohesion ? "yes" : "no",
                        law.tangential ? "yes" : "no"));
    for (int i = 0; i < law.types; ++i)
      for (int j = i; j < law.types; ++j) {
        const CohesiveMaterial& m = law.materials[static_cast<std::size_t>(i * law.types + j)];
        command(fmt::format("pair_coeff {} {} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}", i + 1, j + 1,
                            m.young, m.poisson, m.tensile_strength, m.shear_strength, m.surface_energy,
                            m.scaling_exponent, m.restitution));
      }
  } else {
    command(fmt::format("pair_style wearscale/hooke {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}", law.k_n, law.k_t,
                        law.gamma_n, law.gamma_t, law.friction));
    command("pair_coeff * *");
  }
  pair_ = dynamic_cast<PairWearscale*>(lmp_->force->pair);
  pair_->set_track_virial(config_.track_virial);
  command(fmt::format("neighbor {:.17g} bin", nb.skin));
  // wearscale rebuilds when a particle moved more than half the skin (and
  // every `every` steps): LAMMPS checks every step.
  if (nb.every > 0 && !nb.check_displacement)
    command(fmt::format("neigh_modify delay 0 every {} check no", nb.every));
  else
    command("neigh_modify delay 0 every 1 check yes");
  if (config_.time_step > 0.0) command(fmt::format("timestep {:.17g}", config_.time_step));
  command(fmt::format("fix {} all wearscale/verlet {:.17g}", verlet_id, nb.skin));
  verlet_ = dynamic_cast<FixWearscaleVerlet*>(lmp_->modify->fix[lmp_->modify->find_fix(verlet_id)]);
  verlet_->damping = config_.damping;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (fresh) command(fmt::format("group {} empty", wall_group(w)));
    command(fmt::format("neigh_modify exclude group {0} {0}", wall_group(w)));
    walls_[w].groupbit = lmp_->group->bitmask[lmp_->group->find(wall_group(w))];
  }
  verlet_->walls = walls_;
}

void LammpsSystem::add_wall(const std::vector<std::size_t>& members, WallSlot slot) {
  const std::size_t w = walls_.size();
  for (std::size_t i : members) wall_of_[i] = static_cast<std::int16_t>(w);
  command(fmt::format("group {} empty", wall_group(w)));
  command(fmt::format("neigh_modify exclude group {0} {0}", wall_group(w)));
  slot.groupbit = lmp_->group->bitmask[lmp_->group->find(wall_group(w))];
  LAMMPS_NS::Atom* atom = lmp_->atom;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (wall_of_[static_cast<std::size_t>(atom->tag[i] - 1)] != static_cast<std::int16_t>(w)) continue;
    atom->mask[i] |= slot.groupbit;
    for (int a = 0; a < 3; ++a) {
      atom->v[i][a] = slot.velocity[a];
      atom->omega[i][a] = 0.0;
    }
  }
  walls_.push_back(slot);
  verlet_->walls.push_back(slot);
}

void LammpsSystem::set_time_step(double dt) {
  config_.time_step = dt;
  command(fmt::format("timestep {:.17g}", dt));
}

void LammpsSystem::set_damping(double c) {
  config_.damping = c;
  verlet_->damping = c;
}

void LammpsSystem::set_track_virial(bool on) {
  config_.track_virial = on;
  pair_->set_track_virial(on);
}

void LammpsSystem::set_wall_velocity(int wall, int axis, double velocity) {
  verlet_->walls[static_cast<std::size_t>(wall)].velocity[axis] = velocity;
}

RunFailure LammpsSystem::run(long steps, const std::function<void()>& each_step) {
  verlet_->each_step = each_step;
  verlet_->continue_forces = true;
  command(fmt::format("run {}", steps));
  verlet_->each_step = {};
  lmp_->timer->reset_timeout();  // a failure forced one
  return verlet_->agree_on_failure();
}

void LammpsSystem::compute_forces() {
  verlet_->continue_forces = false;  // afresh, at the current velocities (Simulation::compute_forces)
  command("run 0 post no");
}

const std::vector<WallSlot>& LammpsSystem::walls() const { return verlet_->walls; }
long LammpsSystem::steps() const { return verlet_->steps; }
double LammpsSystem::time() const { return verlet_->time; }

void LammpsSystem::set_clock(long steps, double time, const std::vector<WallSlot>& walls) {
  verlet_->steps = steps;
  verlet_->time = time;
  for (std::size_t w = 0; w < walls.size() && w < verlet_->walls.size(); ++w) {
    const int bit = verlet_->walls[w].groupbit;
    verlet_->walls[w] = walls[w];
    verlet_->walls[w].groupbit = bit;
  }
}

int LammpsSystem::lammps_version() const { return lmp_->num_ver; }

std::string library_version() {
  const char* args[] = {"wearscale", "-log", "none", "-screen", "none", "-nocite"};
  LAMMPS lmp(static_cast<int>(std::size(args)), const_cast<char**>(args), MPI_COMM_SELF);
  return lmp.version;
}

void LammpsSystem::gather(int root, GatheredState& out) const {
  LAMMPS_NS::Atom* atom = lmp_->atom;
  const bool virial = config_.track_virial;
  const int per = 1 + 15 + 3 + (virial ? 6 : 0);
  const int nlocal = atom->nlocal;
  std::vector<double> mine(static_cast<std::size_t>(nlocal) * static_cast<std::size_t>(per));
  const auto& vir = pair_->virial();
  for (int i = 0; i < nlocal; ++i) {
    double* row = &mine[static_cast<std::size_t>(i) * static_cast<std::size_t>(per)];
    row[0] = static_cast<double>(atom->tag[i]);
    for (int a = 0; a < 3; ++a) {
      row[1 + a] = atom->x[i][a];
      row[4 + a] = atom->v[i][a];
      row[7 + a] = atom->omega[i][a];
      row[10 + a] = atom->f[i][a];
      row[13 + a] = atom->torque[i][a];
    }
    const LAMMPS_NS::imageint image = atom->image[i];
    row[16] = static_cast<double>((image & IMGMASK) - IMGMAX);
    row[17] = static_cast<double>((image >> IMGBITS & IMGMASK) - IMGMAX);
    row[18] = static_cast<double>((image >> IMG2BITS) - IMGMAX);
    if (virial)
      for (int c = 0; c < 6; ++c)
        row[19 + c] = vir.size() >= 6 * static_cast<std::size_t>(nlocal) ? vir[6 * static_cast<std::size_t>(i) + static_cast<std::size_t>(c)] : 0.0;
  }
  int size = 1;
  MPI_Comm_size(comm_, &size);
  const int sent = static_cast<int>(mine.size());
  std::vector<int> counts(rank_ == root ? static_cast<std::size_t>(size) : 0), starts;
  MPI_Gather(&sent, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_);
  std::vector<double> all;
  if (rank_ == root) {
    starts.resize(static_cast<std::size_t>(size));
    long long total = 0;
    for (int r = 0; r < size; ++r) {
      starts[static_cast<std::size_t>(r)] = static_cast<int>(total);
      total += counts[static_cast<std::size_t>(r)];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), sent, MPI_DOUBLE, all.data(), counts.data(), starts.data(), MPI_DOUBLE, root, comm_);
  if (rank_ != root) return;
  const std::size_t n = count_;
  for (auto* a : {&out.x, &out.v, &out.omega, &out.force, &out.torque}) a->resize(3 * n);
  out.image.resize(3 * n);
  out.virial.resize(virial ? 6 * n : 0);
  for (std::size_t at = 0; at < all.size(); at += static_cast<std::size_t>(per)) {
    const double* row = &all[at];
    const auto k = static_cast<std::size_t>(row[0]) - 1;
    for (std::size_t a = 0; a < 3; ++a) {
      out.x[3 * k + a] = row[1 + a];
      out.v[3 * k + a] = row[4 + a];
      out.omega[3 * k + a] = row[7 + a];
      out.force[3 * k + a] = row[10 + a];
      out.torque[3 * k + a] = row[13 + a];
      out.image[3 * k + a] = static_cast<std::int32_t>(row[16 + a]);
    }
    if (virial) std::copy(row + 19, row + 25, &out.virial[6 * k]);
  }
}

std::string LammpsSystem::temporary_file(int root) const {
  static std::atomic<long> counter{0};
  std::string path;
  if (rank_ == root) {
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path dir = tmp != nullptr && *tmp != '\0' ? tmp : "/tmp";
    path = (dir / fmt::format("wearscale-lammps-{}-{}.restart", ::getpid(), counter++)).string();
  }
  int length = static_cast<int>(path.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm_);
  path.resize(static_cast<std::size_t>(length));
  MPI_Bcast(path.data(), length, MPI_CHAR, root, comm_);
  return path;
}

std::string LammpsSystem::write_restart(int root) const {
  const std::string path = temporary_file(root);
  lmp_->input->one("write_restart " + path);
  std::string bytes;
  if (rank_ == root) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (!ec) {
      bytes.resize(static_cast<std::size_t>(size));
      in.read(bytes.data(), static_cast<std::streamsize>(size));
    }
    const bool read = !ec && in.good();
    std::filesystem::remove(path, ec);
    if (!read) throw OutputError(fmt::format("the LAMMPS engine could not read back its restart file {}", path));
  }
  return bytes;
}

void LammpsSystem::restore(int root, const std::string& bytes) {
  const std::string path = temporary_file(root);
  int written = 1;
  if (rank_ == root) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    written = out.good() ? 1 : 0;
  }
  MPI_Bcast(&written, 1, MPI_INT, root, comm_);
  if (written == 0) {
    if (rank_ == root) throw OutputError(fmt::format("the LAMMPS engine could not write its restart file {}", path));
    return;
  }
  // The ranks' grid of the system as set up (LAMMPS chose it from the box
  // then, as in the run that saved the state): chosen again from the box of
  // the restart file, it could split another axis.
  const int grid[3] = {lmp_->comm->procgrid[0], lmp_->comm->procgrid[1], lmp_->comm->procgrid[2]};
  delete lmp_;
  lmp_ = nullptr;
  open();
  command(fmt::format("processors {} {} {}", grid[0], grid[1], grid[2]));
  command("newton on");  // read_restart keeps the script's newton_pair
  command("atom_modify map array");
  command("read_restart " + path);
  keep_created_margins();
  if (rank_ == root) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
  command("comm_modify vel yes");
  configure(false);
}

// read_restart sizes the margin of the shrink-wrapped bounds (Domain::small,
// 1e-4 of the box) from the saved box, where the run that saved it had the
// box it was created with: its bounds, bins, atom sort and neighbour order
// would drift from that run's in the last bits. The margin is set again from
// the created box (Domain::set_initial_box(0) sets only it), the saved box kept.
void LammpsSystem::keep_created_margins() {
  LAMMPS_NS::Domain* domain = lmp_->domain;
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = domain->boxlo[a];
    hi[a] = domain->boxhi[a];
    domain->boxlo[a] = created_lo_[a];
    domain->boxhi[a] = created_hi_[a];
  }
  domain->set_initial_box(0);
  for (int a = 0; a < 3; ++a) {
    domain->boxlo[a] = lo[a];
    domain->boxhi[a] = hi[a];
  }
  domain->set_global_box();
  domain->set_local_box();
}

}  // namespace wearscale::dem::lammps
