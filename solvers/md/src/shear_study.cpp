#include "wearscale/md/shear_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "wearscale/core/cache_folder.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/core/version.hpp"
#include "wearscale/md/lammps_runner.hpp"
#include "wearscale/md/potential_file.hpp"
#include "wearscale/md/result_cache.hpp"
#include "wearscale/core/sha256.hpp"

namespace wearscale::md {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCostFile = "cost.txt";

std::string utc_date() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}

// "key value" lines (the deck's sample.txt, cost.txt).
std::map<std::string, std::string> read_key_values(const fs::path& file) {
  std::map<std::string, std::string> kv;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string k, v;
    if (ss >> k) {
      std::getline(ss >> std::ws, v);
      kv[k] = v;
    }
  }
  return kv;
}

double to_number(const std::map<std::string, std::string>& kv, const std::string& key, const fs::path& file) {
  const auto it = kv.find(key);
  char* end = nullptr;
  const double v = it == kv.end() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(it->second.c_str(), &end);
  if (it == kv.end() || end == it->second.c_str() || !std::isfinite(v))
    throw NumericalError("LAMMPS", 0, key, fmt::format("{}: missing or not a number", file.string()));
  return v;
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw InputError(fmt::format("cannot write {}", file.string()));
}

// The step number of the last complete row/line of a growing file (its
// first token), read from its tail; -1 if none yet.
long last_step(const fs::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return -1;
  const std::streamoff size = in.tellg();
  const std::streamoff from = std::max<std::streamoff>(0, size - 4096);
  in.seekg(from);
  std::string tail(static_cast<std::size_t>(size - from), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  const auto end = tail.rfind('\n');
  if (end == std::string::npos) return -1;
  std::stringstream ss(tail.substr(0, end));
  std::string line;
  long step = -1;
  while (std::getline(ss, line)) {
    char* e = nullptr;
    const long s = std::strtol(line.c_str(), &e, 10);
    if (e != line.c_str() && (*e == ' ' || *e == '\0')) step = s;
  }
  return step;
}

struct Context {
  const ShearTestSpec& spec;
  fs::path lmp;
  std::string version;
  std::string potential_name, potential_text;
  ResultCache cache;
  DeckFiles files;
};

// Makes sure the cache holds the run of `key`: looks it up (unless caching is
// off) or runs `deck` in a fresh folder (with the potential and `extra` files
// copied in), checks completion, and stores it; true if it was found. The
// entry's lock is held throughout, so of several processes (MPI ranks) asking
// for the same run at once one runs it and the others find it.
bool ensure_run(Context& ctx, const std::string& key, const std::string& deck, const std::string& label,
                const std::vector<fs::path>& extra, double expected_steps, const std::string& progress_file) {
  const EntryLock lock = ctx.cache.lock(key, [&] {
    log::info("{}: waiting for another process running the same LAMMPS run ({})", label,
              ctx.cache.entry(key).string());
  });
  if (ctx.spec.use_cache) {
    if (auto hit = ctx.cache.find(key)) {
      log::debug("{}: cached in {}", label, hit->string());
      return true;
    }
  }
  const fs::path work = ctx.cache.begin(key);
  write_text(work / "in.lammps", deck);
  write_text(work / ctx.potential_name, ctx.potential_text);
  for (const auto& f : extra) fs::copy_file(f, work / f.filename(), fs::copy_options::overwrite_existing);
  LammpsJob job{ctx.lmp, ctx.spec.ranks, work, "in.lammps", label};
  Progress progress(label, expected_steps, "steps");
  long first = -1;
  const fs::path watched = work / progress_file;
  auto poll = [&]() {
    const long s = last_step(watched);
    if (s < 0) return;
    if (first < 0) first = progress_file == "log.lammps" ? 0 : s;
    progress.update(static_cast<double>(s - first));
  };
  const LammpsRunInfo info = run_lammps(job, poll);
  progress.finish();
  const auto sample = read_key_values(work / ctx.files.sample);
  if (sample.count("completed") == 0)
    throw NumericalError("LAMMPS", last_step(work / "log.lammps"), label,
                         fmt::format("lmp ended without completing the deck (no 'completed' in {}); see {}",
                                     (work / ctx.files.sample).string(), (work / "log.lammps").string()));
  write_text(work / kCostFile, fmt::format("wall_seconds {:.3f}\nranks {}\ndate {}\nlammps_version {}\n",
                                           info.wall_seconds, info.ranks, utc_date(), ctx.version));
  ctx.cache.commit(key, work);
  return false;
}

// The record of the run of `key`, from its entry (which ensure_run made sure of).
RunRecord read_record(const Context& ctx, const std::string& key, bool cached) {
  RunRecord r;
  r.key = key;
  r.folder = ctx.cache.entry(key);
  r.cached = cached;
  const auto cost = read_key_values(r.folder / kCostFile);
  r.wall_seconds = cost.count("wall_seconds") != 0 ? std::strtod(cost.at("wall_seconds").c_str(), nullptr)
                                                   : std::numeric_limits<double>::quiet_NaN();
  r.ranks = cost.count("ranks") != 0 ? std::atoi(cost.at("ranks").c_str()) : ctx.spec.ranks;
  r.date = cost.count("date") != 0 ? cost.at("date") : std::string();
  return r;
}

// The runs as the caller's map spreads them (default: in order, here); the
// texts are "cached" or "ran".
std::optional<std::vector<std::string>> map_runs(const RunMap& map, std::size_t count,
                                                 const std::function<bool(std::size_t)>& run) {
  const auto task = [&](std::size_t k) { return std::string(run(k) ? "cached" : "ran"); };
  if (map) return map(count, task);
  std::vector<std::string> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(task(k));
  return out;
}

std::string gpa(double pa) { return fmt::format("{:g}", pa / units::GPa); }

// A study whose runs' outcomes were gathered by another process (rank 0).
ShearStudy gathered_elsewhere(ShearStudy study) {
  study.quench.reset();
  study.elastic.reset();
  study.points.clear();
  return study;
}

constexpr double kElasticStrain = 1e-3;

// The cells of the ideal lattice the reference constants are computed on:
// enough for a box of at least 12 Å a side (the cell count does not change an
// ideal lattice's constants; a larger box keeps every neighbour list ordinary).
long reference_cells(const materials::InteratomicModel& m) {
  return std::max(2L, static_cast<long>(std::ceil(12e-10 / m.lattice_constant)));
}

// The elastic check from the runs' entries (reference: crystal only).
ElasticCheck evaluate_elastic(const Context& ctx, const std::string& reference_key, const std::string& sample_key,
                              bool cached) {
  const ShearTestSpec& spec = ctx.spec;
  ElasticCheck c;
  c.isotropic = spec.model.amorphous;
  c.sample_run = read_record(ctx, sample_key, cached);
  const fs::path sample_file = c.sample_run.folder / "elastic.txt";
  const ElasticResult sample = parse_elastic(read_text_file(sample_file), kElasticStrain, sample_file.string());
  c.sample = elastic_moduli(sample.c);
  c.sample_pressure = -(sample.stress0[0] + sample.stress0[1] + sample.stress0[2]) / 3.0;
  double e_ref = 0.0, nu_ref = 0.0, e_sample = 0.0, nu_sample = 0.0;
  if (c.isotropic) {
    const auto& r = spec.model.reference;
    c.reference.young = r.young;
    c.reference.poisson = r.poisson;
    c.reference.shear = r.young / (2.0 * (1.0 + r.poisson));
    c.reference.bulk = r.young / (3.0 * (1.0 - 2.0 * r.poisson));
    c.reference.min_eigenvalue = std::min(c.reference.shear, c.reference.bulk);  // an isotropic solid: 2G and 3K
    c.reference_source = "published: " + r.source;
    e_ref = r.young;
    nu_ref = r.poisson;
    e_sample = c.sample.young;
    nu_sample = c.sample.poisson;
  } else {
    c.reference_run = read_record(ctx, reference_key, cached);
    const fs::path ref_file = c.reference_run->folder / "elastic.txt";
    const ElasticResult ref = parse_elastic(read_text_file(ref_file), kElasticStrain, ref_file.string());
    c.reference = elastic_moduli(ref.c);
    c.reference_lattice_constant = ref.lx / static_cast<double>(reference_cells(spec.model));
    c.reference_source = fmt::format("computed with LAMMPS: the ideal {} lattice of the potential relaxed to zero "
                                     "stress at 0 K (a0 = {:.4f} A), finite strains of +-{:g}",
                                     materials::to_string(spec.model.structure),
                                     c.reference_lattice_constant / units::angstrom, kElasticStrain);
    e_ref = c.reference.young_z;
    nu_ref = c.reference.poisson_zx;
    e_sample = c.sample.young_z;
    nu_sample = c.sample.poisson_zx;
  }
  c.young_error = std::abs(e_sample - e_ref) / e_ref;
  c.poisson_error = std::abs(nu_sample - nu_ref) / std::max(std::abs(nu_ref), 0.1);
  return c;
}

// Refuses a sample that is not the solid its potential describes.
void require_physical(const ElasticCheck& c, const ShearTestSpec& spec) {
  if (c.passed()) return;
  std::string why;
  if (!c.reference.stable())
    why = fmt::format("the ideal {} lattice is not mechanically stable with this potential (smallest eigenvalue of "
                      "C_ij {:.1f} GPa): the potential does not describe this structure",
                      materials::to_string(spec.model.structure), c.reference.min_eigenvalue / units::GPa);
  else if (!c.sample.stable())
    why = fmt::format("the sample is not mechanically stable at 0 K (smallest eigenvalue of C_ij {:.1f} GPa)",
                      c.sample.min_eigenvalue / units::GPa);
  else
    why = fmt::format("its elastic moduli differ from the reference by more than {:.0f} %: {}", c.tolerance * 100.0,
                      c.summary());
  std::string hint;
  if (!c.isotropic && c.reference_lattice_constant > 0.0)
    hint = fmt::format("; the potential's relaxed lattice constant is {:.4f} A against the declared {:.4f} A, the "
                       "unstrained sample's pressure {:.2f} GPa (check lattice_constant, structure and elements)",
                       c.reference_lattice_constant / units::angstrom, spec.model.lattice_constant / units::angstrom,
                       c.sample_pressure / units::GPa);
  else if (c.isotropic)
    hint = fmt::format("; the quenched sample's pressure at 0 K before relaxing is {:.2f} GPa (check the quench "
                       "schedule and the reference values: {})",
                       c.sample_pressure / units::GPa, c.reference_source);
  throw InputError(fmt::format("{}: the MD sample is refused: {}{} (runs {}{})", spec.material, why, hint,
                               c.sample_run.folder.string(),
                               c.reference_run ? ", " + c.reference_run->folder.string() : std::string()));
}

}  // namespace

std::string ElasticCheck::summary() const {
  if (isotropic)
    return fmt::format("E = {:.1f} GPa (reference {:.1f} GPa, {:.1f} %), nu = {:.3f} (reference {:.3f}, {:.1f} %)",
                       sample.young / units::GPa, reference.young / units::GPa, 100.0 * young_error, sample.poisson,
                       reference.poisson, 100.0 * poisson_error);
  return fmt::format("E_z = {:.1f} GPa (reference {:.1f} GPa, {:.1f} %), nu_zx = {:.3f} (reference {:.3f}, {:.1f} %)",
                     sample.young_z / units::GPa, reference.young_z / units::GPa, 100.0 * young_error,
                     sample.poisson_zx, reference.poisson_zx, 100.0 * poisson_error);
}

ShearStudy run_shear_study(const ShearTestSpec& spec, const RunMap& map) {
  validate(spec);
  ShearStudy study;
  study.spec = spec;
  study.lmp = find_lmp(spec.lmp);
  const fs::path cache_dir = spec.cache_dir.empty() ? cache_folder("lammps") : spec.cache_dir;
  study.lammps_version = lammps_version(study.lmp, cache_dir);
  study.potential_source = find_potential_file(spec.model.potential);
  std::string potential_text = read_text_file(study.potential_source);
  if (spec.model.pair_style == "vashishta" && spec.model.cutoff > 0.0)
    potential_text =
        vashishta_with_cutoff(potential_text, spec.model.cutoff / units::angstrom, study.potential_source.string());
  study.potential_sha256 = sha256_hex(potential_text);

  Context ctx{spec, study.lmp, study.lammps_version, run_potential_name(spec.model), potential_text,
              ResultCache(cache_dir), {}};
  ctx.files.potential = ctx.potential_name;
  const std::string fingerprint = spec.fingerprint();
  const std::string& material = spec.material;

  // 1. An amorphous sample: one melt-quench that every later run starts from.
  std::string quench_key;
  fs::path quenched_sample;
  if (spec.model.amorphous) {
    const std::string deck = quench_deck(spec, ctx.files);
    // The deck holds every input of the quench (cell, schedule, seeds).
    quench_key = cache_key({"quench", deck, study.lammps_version, potential_text, std::to_string(spec.ranks)});
    double steps = 0.0;
    const auto& q = spec.quench;
    for (std::size_t i = 0; i < q.temperatures.size(); ++i) {
      steps += static_cast<double>(spec.steps(q.hold_time, q.timestep));
      if (i > 0) {
        const double rate = i + 1 == q.temperatures.size() ? q.final_cooling_rate : q.cooling_rate;
        steps += static_cast<double>(spec.steps((q.temperatures[i - 1] - q.temperatures[i]) / rate, q.timestep));
      }
    }
    // One run, before the pressures (which start from it): a map of one task.
    const auto ran = map_runs(map, 1, [&](std::size_t) {
      return ensure_run(ctx, quench_key, deck, material + " melt-quench", {}, steps, "log.lammps");
    });
    quenched_sample = ctx.cache.entry(quench_key) / ctx.files.quenched_sample;
    // Where the map gathers nothing the next maps still follow (collective under MPI).
    if (ran) {
      QuenchRecord qr;
      qr.run = read_record(ctx, quench_key, ran->at(0) == "cached");
      const fs::path sample_file = qr.run.folder / ctx.files.sample;
      const auto kv = read_key_values(sample_file);
      qr.atoms = std::lround(to_number(kv, "atoms", sample_file));
      qr.density = to_number(kv, "density_g_cm3", sample_file) * 1000.0;
      qr.lx = to_number(kv, "lx_A", sample_file) * units::angstrom;
      qr.lz = to_number(kv, "lz_A", sample_file) * units::angstrom;
      log::info("{} melt-quench: {} atoms, density {:.0f} kg/m^3 ({}, {:.0f} s)", material, qr.atoms, qr.density,
                qr.run.cached ? "cached" : "ran", qr.run.wall_seconds);
      study.quench = qr;
    }
  }

  // 2. The elastic check: one task (the sample's runs, then the comparison,
  // which refuses inside the task so that every rank stops together).
  std::string reference_key, sample_key;
  std::string reference_deck, sample_deck;
  {
    ElasticDeckFiles files;
    files.potential = ctx.potential_name;
    if (!spec.model.amorphous) {
      const long n = reference_cells(spec.model);
      reference_deck = elastic_deck(spec.model, {n, n, {}, true}, files, kElasticStrain,
                                    "Elastic constants of the ideal lattice (the reference)");
      reference_key = cache_key({"elastic", reference_deck, study.lammps_version, potential_text});
      sample_deck = elastic_deck(spec.model, {spec.lateral_cells(), spec.height_cells(), {}, false}, files,
                                 kElasticStrain, "Elastic constants of the shear test's sample, as built");
    } else {
      sample_deck = elastic_deck(spec.model, {1, 1, ctx.files.quenched_sample, true}, files, kElasticStrain,
                                 "Elastic constants of the melt-quenched sample, relaxed at 0 K");
    }
    sample_key = cache_key({"elastic", sample_deck, study.lammps_version, potential_text, quench_key});
  }
  const auto checked = map_runs(map, 1, [&](std::size_t) {
    bool cached = true;
    if (!reference_key.empty())
      cached = ensure_run(ctx, reference_key, reference_deck, material + " elastic constants (ideal lattice)", {}, 12,
                          "elastic.txt");
    std::vector<fs::path> extra;
    if (!quenched_sample.empty()) extra.push_back(quenched_sample);
    cached = ensure_run(ctx, sample_key, sample_deck, material + " elastic constants (sample)", extra, 12,
                        "elastic.txt") &&
             cached;
    require_physical(evaluate_elastic(ctx, reference_key, sample_key, cached), spec);
    return cached;
  });
  if (checked) {
    study.elastic = evaluate_elastic(ctx, reference_key, sample_key, checked->at(0) == "cached");
    log::info("{} elastic check: {}", material, study.elastic->summary());
  }

  // 3. The pressures: independent runs, which the caller's map may spread (over MPI ranks).
  const double expected = spec.strain_end * static_cast<double>(spec.height_cells()) * spec.model.lattice_constant /
                          (spec.shear_velocity * spec.timestep);
  auto point_key = [&](double p) {
    return cache_key({"shear", fingerprint, shear_deck(spec, p, ctx.files), study.lammps_version, potential_text,
                      quench_key});
  };
  auto point_label = [&](double p) { return fmt::format("{} shear test at {} GPa", material, gpa(p)); };
  const auto ran = map_runs(map, spec.pressures.size(), [&](std::size_t k) {
    const double p = spec.pressures[k];
    std::vector<fs::path> extra;
    if (!quenched_sample.empty()) extra.push_back(quenched_sample);
    return ensure_run(ctx, point_key(p), shear_deck(spec, p, ctx.files), point_label(p), extra, expected,
                      ctx.files.curve);
  });
  if (!ran || !checked) return gathered_elsewhere(std::move(study));
  for (std::size_t k = 0; k < spec.pressures.size(); ++k) {
    const double p = spec.pressures[k];
    ShearPoint pt;
    pt.pressure = p;
    pt.run = read_record(ctx, point_key(p), ran->at(k) == "cached");
    pt.curve = read_shear_curve(pt.run.folder / ctx.files.curve);
    pt.strength = shear_strength(pt.curve, spec.window_begin, spec.window_end);
    const fs::path sample_file = pt.run.folder / ctx.files.sample;
    const auto kv = read_key_values(sample_file);
    pt.atoms = std::lround(to_number(kv, "atoms", sample_file));
    pt.lx = to_number(kv, "lx_A", sample_file) * units::angstrom;
    pt.ly = to_number(kv, "ly_A", sample_file) * units::angstrom;
    pt.h0 = to_number(kv, "h0_A", sample_file) * units::angstrom;
    pt.h_gap = to_number(kv, "h_gap_A", sample_file) * units::angstrom;
    try {  // a run stopped before its elastic start is sampled has no modulus, and needs none
      pt.shear_modulus = initial_slope(pt.curve, std::min(spec.modulus_strain, spec.strain_end)) * pt.h_gap / pt.h0;
    } catch (const NumericalError&) {
      pt.shear_modulus = std::numeric_limits<double>::quiet_NaN();
    }
    const auto& s = pt.strength;
    log::info("{} p_N = {:>4} GPa: sigma_max = {:6.2f} GPa at strain {:.3f}, sigma_dyn = {:5.2f} ± {:.2f} GPa, "
              "G = {:.1f} GPa, T(window) = {:.0f} K ({} {:.1f} s)",
              material, gpa(p), s.sigma_max / units::GPa, s.strain_at_max, s.sigma_dyn / units::GPa,
              s.sigma_dyn_std / units::GPa, pt.shear_modulus / units::GPa, s.temperature_window,
              pt.run.cached ? "cached," : "ran", pt.run.wall_seconds);
    if (!s.failed_before_window)
      log::warn("{} at {} GPa: the peak shear stress (strain {:.3f}) is not before the dynamic-strength window "
                "[{:g}, {:g}]: sigma_dyn is not a post-failure value",
                material, gpa(p), s.strain_at_max, spec.window_begin, spec.window_end);
    if (std::abs(s.normal_stress - p) > 0.1 * p + 0.5 * units::GPa)
      log::warn("{} at {} GPa: the measured normal stress on the top wall averages {:.2f} GPa over the window",
                material, gpa(p), s.normal_stress / units::GPa);
    study.points.push_back(std::move(pt));
  }
  return study;
}

materials::StrengthTable strength_table(const ShearStudy& st) {
  const ShearTestSpec& s = st.spec;
  materials::StrengthTable t;
  t.material = s.material;
  for (const auto& p : st.points) {
    t.pressure.push_back(p.pressure);
    t.sigma_max.push_back(p.strength.sigma_max);
    t.sigma_dyn.push_back(p.strength.sigma_dyn);
  }
  const auto& m = s.model;
  const std::string structure = materials::to_string(m.structure);
  std::string elements;
  for (std::size_t i = 0; i < m.elements.size(); ++i)
    elements += fmt::format("{}{} ({:g} g/mol)", i ? ", " : "", m.elements[i], m.masses[i]);
  auto& pv = t.provenance;
  auto add = [&pv](std::string k, std::string v) { pv.emplace_back(std::move(k), std::move(v)); };
  add("source", fmt::format("wearscale {} strength-table --backend lammps: MD shear test of thesis Sec. 9.3.1, "
                            "preset {}, computed by this project (not thesis data)",
                            version(), s.preset));
  add("material", t.material);
  add("columns", "pressure = imposed normal pressure p_N; sigma_max = peak shear stress; sigma_dyn = mean shear "
                 "stress over the strain window");
  add("lammps_version", st.lammps_version);
  add("lammps_command", fmt::format("{} ({} MPI rank{})", st.lmp.string(), s.ranks, s.ranks > 1 ? "s" : ""));
  add("potential", fmt::format("pair_style {}, {}{}; elements {}{}", m.pair_style, st.potential_source.string(),
                               m.pair_style == "vashishta" && m.cutoff > 0.0
                                   ? fmt::format(" with rc set to {:g} A in every entry (file {})",
                                                 m.cutoff / units::angstrom, run_potential_name(m))
                                   : std::string(),
                               elements, m.source.empty() ? std::string() : "; " + m.source));
  add("potential_sha256", st.potential_sha256);
  if (!st.points.empty()) {
    const auto& p0 = st.points.front();
    add("system_size", fmt::format("{:.2f} x {:.2f} nm laterally (periodic), box height {:.2f} nm, sheared height "
                                   "(wall centroids) {:.2f} nm at p_N = {} GPa",
                                   p0.lx / units::nm, p0.ly / units::nm,
                                   (st.quench ? st.quench->lz
                                              : static_cast<double>(s.height_cells()) * m.lattice_constant) /
                                       units::nm,
                                   p0.h0 / units::nm, gpa(p0.pressure)));
    add("atoms", std::to_string(p0.atoms));
  }
  add("sample", !m.amorphous
                    ? fmt::format("{} crystal, a = {:g} A, {} x {} x {} cells, x=[100] y=[010] z=[001] ((001) faces on "
                                  "the walls)",
                                  structure, m.lattice_constant / units::angstrom, s.lateral_cells(), s.lateral_cells(),
                                  s.height_cells())
                    : fmt::format("amorphous, melt-quenched from the {} crystal (a = {:g} A, {} x {} x {} cells), one "
                                  "quench reused at every pressure",
                                  structure, m.lattice_constant / units::angstrom, s.lateral_cells(), s.lateral_cells(),
                                  s.height_cells()));
  if (st.elastic) {
    const auto& e = *st.elastic;
    add("elastic_check", fmt::format("passed within {:.0f} %: {}; sample at 0 K: E = {:.1f} GPa, nu = {:.3f}, "
                                     "G_xz = {:.1f} GPa, pressure {:.2f} GPa before straining",
                                     e.tolerance * 100.0, e.summary(), e.sample.young / units::GPa, e.sample.poisson,
                                     e.sample.shear_xz / units::GPa, e.sample_pressure / units::GPa));
    add("elastic_reference", e.reference_source);
  }
  if (!st.points.empty()) {
    std::string moduli;
    for (const auto& p : st.points)
      moduli += fmt::format("{}{} GPa: {}", moduli.empty() ? "" : "; ", gpa(p.pressure),
                            std::isfinite(p.shear_modulus) ? fmt::format("{:.1f} GPa", p.shear_modulus / units::GPa)
                                                           : std::string("too few rows"));
    add("shear_modulus", fmt::format("slope of the shear stress over strains up to {:g}, times (gap between the walls' "
                                     "inner faces)/(distance between their centroids), at {:g} K: {}",
                                     s.modulus_strain, s.temperature, moduli));
  }
  add("walls", fmt::format("rigid, {:g} A thick; bottom fixed, top loaded by p_N (aveforce) and moved along x",
                           s.wall_thickness / units::angstrom));
  add("temperature", fmt::format("{:g} K", s.temperature));
  add("thermostat", fmt::format("Langevin layers {:g} A thick next to the walls, damp {:g} ps, y and z only "
                                "(temp/partial 0 1 1 bias: no drag along the sliding direction)",
                                s.thermostat_thickness / units::angstrom, s.langevin_damp * 1e12));
  add("timestep", fmt::format("{:g} fs", s.timestep * 1e15));
  add("compression", fmt::format("{:g} ps under load before shearing", s.compression_time * 1e12));
  add("shear_velocity", fmt::format("{:g} m/s", s.shear_velocity));
  if (!st.points.empty())
    add("shear_rate", fmt::format("{:.3g} 1/s (velocity / sheared height at p_N = {} GPa)",
                                  s.shear_velocity / st.points.front().h0, gpa(st.points.front().pressure)));
  add("strain", fmt::format("top-wall displacement / distance between the wall centroids (from atom positions), "
                            "sheared up to {:g}",
                            s.strain_end));
  add("strain_window", fmt::format("sigma_dyn = mean shear stress for strain in [{:g}, {:g}]; small boxes stick-slip "
                                   "after failure, so sigma_dyn depends on this window",
                                   s.window_begin, s.window_end));
  std::string heating;
  for (const auto& p : st.points)
    heating += fmt::format("{}{} GPa: {:.0f} K", heating.empty() ? "" : "; ", gpa(p.pressure), p.strength.temperature_window);
  add("heating", "mean temperature of the mobile atoms (without the x streaming component) in the window: " + heating);
  add("seeds", !m.amorphous
                   ? fmt::format("velocity {}, langevin {}", s.seed, s.seed + 1)
                   : fmt::format("quench velocity {}, quench langevin {}..{}, shear langevin {}", s.seed + 2, s.seed + 3,
                                 s.seed + 1 + 2 * s.quench.temperatures.size(), s.seed + 1));
  if (st.quench) {
    const auto& q = s.quench;
    std::string temps;
    for (double T : q.temperatures) temps += fmt::format("{}{:g}", temps.empty() ? "" : ",", T);
    add("quench", fmt::format("holds of {:g} ps at {} K, cooling {:g} K/ps, last {:g} K/ps, dt {:g} fs, {}, Langevin "
                              "damp {:g} ps; density after: {:.0f} kg/m^3; {} atoms",
                              q.hold_time * 1e12, temps, q.cooling_rate * 1e-12, q.final_cooling_rate * 1e-12,
                              q.timestep * 1e15,
                              q.constant_volume ? std::string("constant volume (the crystal's)")
                                                : fmt::format("Berendsen barostat {:g} GPa (damp {:g} ps)",
                                                              q.pressure / units::GPa, q.barostat_damp * 1e12),
                              q.thermostat_damp * 1e12, st.quench->density, st.quench->atoms));
    add("quench_cost", fmt::format("{:.0f} s wall on {} rank(s)", st.quench->run.wall_seconds, st.quench->run.ranks));
  }
  std::string dates;
  double cost = 0.0;
  int costed = 0;
  for (const auto& p : st.points) {
    if (std::isfinite(p.run.wall_seconds)) {
      cost += p.run.wall_seconds;
      ++costed;
    }
    if (!p.run.date.empty() && dates.find(p.run.date) == std::string::npos)
      dates += (dates.empty() ? "" : ", ") + p.run.date;
  }
  add("date", dates.empty() ? utc_date() : dates);
  if (costed > 0)
    add("cost_per_point", fmt::format("{:.1f} s wall on {} rank(s) (mean of {} pressures)", cost / costed,
                                      st.points.front().run.ranks, costed));
  for (const auto& p : st.points) {
    const auto& r = p.strength;
    add(fmt::format("point_{}GPa", gpa(p.pressure)),
        fmt::format("peak at strain {:.3f}; window: {} rows, std {:.2f} GPa, measured p_N {:.2f} GPa; T max {:.0f} K; "
                    "sheared height {:.2f} nm; run {}",
                    r.strain_at_max, r.window_samples, r.sigma_dyn_std / units::GPa, r.normal_stress / units::GPa,
                    r.temperature_max, p.h0 / units::nm, p.run.key.substr(0, 12)));
  }
  return t;
}

}  // namespace wearscale::md
