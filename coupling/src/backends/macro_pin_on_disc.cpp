// macro/bem-pin-on-disc: the pin-on-disc wear model of §9.3.2 on the BEM,
// driven by the interface laws of the nanoscale (one per interface the pin
// meets: the oxide layer and the substrate beneath it).
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "wearscale/coupling/scale.hpp"
#include "backends/case_materials.hpp"
#include "backends/pin_on_disc_surfaces.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/io/xdmf.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/friction_average.hpp"
#include "wearscale/tribometer/specific_wear_rate.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"
#include "wearscale/tribometer/state_bounds.hpp"

namespace wearscale::coupling {

namespace {

// The keys of [scale.macro] with backend = "bem-pin-on-disc", and what they
// fill: the model's setup (its defaults, the thesis setup of §9.3.2 "Setup",
// are PinOnDiscSetup's initializers) and the backend's own choices.
struct PinOnDiscKeys {
  tribometer::PinOnDiscSetup setup;
  std::string elastic = "pin";
  std::string integrator = "explicit";
  tribometer::AdaptiveOptions adaptive;
  std::size_t fields_every = 0;
  double moving_average = 0.0;
  std::vector<std::pair<std::string, std::string>> surfaces;  ///< key, what the initial surface is
  // Not keys: the contact moduli `elastic` picks from (of the case's materials).
  double e_star_pin = 0.0, e_star_pair = 0.0;
};

// The adaptive integrator by default where it is verified against the
// converged explicit stepping (within 0.1 %: planar and tilted discs under
// the physical reading, docs/pin_on_disc.md); the thesis' explicit step is
// one key away, and the default where the adaptive one is not verified.
std::string default_integrator(const PinOnDiscKeys& k) {
  const bool verified = k.setup.track == tribometer::Track::Averaged && !k.setup.tilt_in_layer_test();
  return verified ? "adaptive" : "explicit";
}

// The checks between the keys of the cell, the track and the time step, before
// the initial surfaces are read on that grid.
void warn_unverified_integrator(const Config& c, PinOnDiscKeys& k) {
  if (k.integrator == "adaptive" && k.setup.tilt_in_layer_test())
    log::warn("{}: the adaptive integrator with layer_test = \"tilted\" and a slope is not verified: the material "
              "changes cell by cell as the tilt turns, and its μ_mean and wear were 2-7 % off the converged "
              "explicit stepping (docs/pin_on_disc.md); integrator = \"explicit\" is the default there",
              c.full_key("integrator"));
}

void check_setup(const Config& c, PinOnDiscKeys& k) {
  auto& s = k.setup;
  s.validate();
  // Every step keeps a sample (the series, its copy in each checkpoint and in run.h5): a time step
  // many orders below the distance's would exhaust memory long before the run ended.
  const double steps = std::ceil(s.distance / s.explicit_step());
  require_memory(steps * 3.0 * 9.0 * sizeof(double),
                 fmt::format("{}: key '{}': {:.3g} steps of {:g} s over {:g} m", c.where("time_step"),
                             c.full_key("time_step"), steps, s.time_step, s.distance),
                 "a longer time_step or a shorter distance");
  if (s.track == tribometer::Track::Resolved) {
    const double revolution = s.tilt_period();
    const double cell = s.size / static_cast<double>(s.grid);
    if (c.has("nonplanarity.period") &&
        std::lround(s.nonplanar_period / cell) != static_cast<long>(s.track_cells()))  // not the same whole track
      throw c.error("nonplanarity.period",
                    fmt::format("a resolved track's tilt turns with the disc, once per revolution ({:g} m: "
                                "path_length on the {}-cell track)",
                                revolution, s.track_cells()),
                    fmt::format("absent, or {:g} m", revolution));
    if (s.step_bounded() && k.integrator == "explicit")
      log::info("{}: on a resolved track the pin moves at most one cell a step: the explicit step is {:.4g} s "
                "(one {:.4g} m cell at {:g} m/s), not time_step = {:g} s",
                c.full_key("track"), s.explicit_step() / s.velocity, s.size / static_cast<double>(s.grid),
                s.velocity, s.time_step);
  }
}

// The initial roughness of the pin (over its window) and of the disc (over the
// resolved track's strip): a measured file or a generated surface (docs/pin_on_disc.md).
void read_pin_surface(const Config& c, PinOnDiscKeys& k) {
  auto& s = k.setup;
  if (!c.has("pin_surface")) return;
  auto surface = read_initial_surface(c, "pin_surface", Grid2D::square(s.grid, s.size), s.size);
  s.pin_roughness = std::move(surface.heights);
  k.surfaces.emplace_back("pin_surface", std::move(surface.description));
}

void read_disc_surface(const Config& c, PinOnDiscKeys& k) {
  auto& s = k.setup;
  if (!c.has("disc_surface")) return;
  if (s.track != tribometer::Track::Resolved)
    throw c.error("disc_surface",
                  "the averaged track's disc is one height per x column, invariant along the sliding "
                  "direction: it holds no roughness along it (a rough surface's mean along y is all but flat, "
                  "so the rough disc would be a smooth one)",
                  "track = \"resolved\" (the disc stored over the whole circumference), or no disc_surface");
  const std::size_t cells = s.track_cells();
  const double cell = s.size / static_cast<double>(s.grid);
  auto surface = read_initial_surface(c, "disc_surface",
                                      Grid2D(s.grid, cells, s.size, static_cast<double>(cells) * cell), s.size);
  s.disc_roughness = std::move(surface.heights);
  k.surfaces.emplace_back("disc_surface", std::move(surface.description));
}

const KeyTable<PinOnDiscKeys>& pin_on_disc_keys() {
  using K = PinOnDiscKeys;
  using tribometer::LayerTest;
  using tribometer::Track;
  using namespace units;
  const auto setup = [](auto member) { return [member](K& k) -> auto& { return k.setup.*member; }; };
  const auto adaptive = [](auto member) { return [member](K& k) -> auto& { return k.adaptive.*member; }; };
  using PS = tribometer::PinOnDiscSetup;
  using AO = tribometer::AdaptiveOptions;
  static const auto table =
      KeyTable<K>()
          .integer("grid", setup(&PS::grid), Range::closed(8, 4096), "BEM cells n per side of the pin's window")
          .number("size", setup(&PS::size), Range::positive(), length, "side L of the pin's window")
          .number("pin_radius", setup(&PS::pin_radius), Range::positive(), length, "pin radius R (> size/√2: the sphere covers the window)")
          .number("normal_load", setup(&PS::normal_load), Range::positive(), force, "normal load F_N")
          .number("velocity", setup(&PS::velocity), Range::positive(), units::velocity, "sliding velocity v")
          .number("path_length", setup(&PS::path_length), Range::positive(), length,
                  "circumference L_path of the wear track (≥ size)")
          .number("distance", setup(&PS::distance), Range::positive(), length, "sliding distance to cover")
          // At least one step: a longer one would overshoot the distance (the last step is cut to land on it).
          .number("time_step", setup(&PS::time_step), Range::positive(), time,
                  "explicit time step (the adaptive integrator's first step)")
          .range_from([](const K& k) { return Range::open_closed(0.0, k.setup.distance / k.setup.velocity); },
                      "(0, distance/velocity]")
          .number("nonplanarity.slope", setup(&PS::nonplanar_slope), Range::closed_open(0.0, 0.2),
                  "slope of the disc's rotating tilt (§9.3.2, Figs. 9.23-9.25)")
          .number("nonplanarity.period", setup(&PS::nonplanar_period), Range::positive(), length,
                  "the tilt's rotation period in sliding distance (resolved track: path_length)")
          // Which material the pin meets: the worn disc's depth ("disc", physical),
          // or with the tilt added ("tilted", the reading that reproduces Figs. 9.23-9.25).
          .choice("nonplanarity.layer_test", setup(&PS::layer_test),
                  std::vector<std::pair<std::string, LayerTest>>{{"disc", LayerTest::Disc},
                                                                 {"tilted", LayerTest::Tilted}},
                  "depth the material is tested at: the worn disc's, or with the tilt added")
          // The disc track: averaged along the sliding direction (§9.3.2) or the
          // whole circumference resolved (the wear where the pin is, the tilt turning
          // with the disc, once per revolution).
          .choice("track", setup(&PS::track),
                  std::vector<std::pair<std::string, Track>>{{"averaged", Track::Averaged},
                                                             {"resolved", Track::Resolved}},
                  "disc track averaged along the sliding direction, or the whole circumference resolved")
          .number("tolerance", setup(&PS::tolerance), Range::open(0.0, 1e-3), "BEM orthogonality error of a solve")
          .choice("boundary", setup(&PS::boundary),
                  std::vector<std::pair<std::string, bem::Boundary>>{{"periodic", bem::Boundary::Periodic},
                                                                     {"free", bem::Boundary::Free}},
                  "BEM cell: periodic images, or an isolated pin")
          // Elastic properties of the contact solve: the pin's for both bodies (the
          // thesis, which could not model layered bodies), the pair's, or a value.
          .choice("elastic", &K::elastic, std::vector<std::string>{"pin", "pair"},
                  "elastic constants of the contact solve: the pin's for both bodies (the thesis), or the pair's")
          .number("e_star", setup(&PS::e_star), Range::positive(), pressure, "contact modulus E* of the BEM solve")
          .computed_default([](const K& k) { return k.elastic == "pin" ? k.e_star_pin : k.e_star_pair; },
                            "E* of the pin on itself (elastic = \"pin\") or of the pair")
          .choice("integrator", &K::integrator, std::vector<std::string>{"explicit", "adaptive"},
                  "time integrator of the wear")
          .computed_text(default_integrator,
                           "adaptive on an averaged track without the tilt in the layer test, else explicit")
          .then(warn_unverified_integrator)
          .number("adaptive.contact_tolerance", setup(&PS::stage_tolerance), Range::open(0.0, 1e-3),
                  "BEM orthogonality error of an implicit stage's solve")
          .number("adaptive.rtol", adaptive(&AO::relative_tolerance), Range::open(0.0, 1.0),
                  "relative tolerance of the adaptive step")
          .number("adaptive.atol", adaptive(&AO::absolute_tolerance), Range::positive(), length,
                  "absolute tolerance of the adaptive step (worn heights)")
          .number("adaptive.max_step", adaptive(&AO::max_step), Range::positive(), length,
                  "longest adaptive step in sliding distance")
          .integer("adaptive.steps_per_period", adaptive(&AO::steps_per_period), Range::closed(4, 10000),
                   "adaptive steps at least per tilt period")
          .integer("fields_every", &K::fields_every, Range::non_negative(),
                   "field snapshots every this many samples (0: first and last only)")
          .then(check_setup)
          .table("pin_surface", "initial roughness of the pin over its window", read_pin_surface,
                 "a topography file, or a table: {file, dataset, missing_points, level} or a generated surface "
                 "(docs/pin_on_disc.md)")
          .table("disc_surface", "initial roughness of the disc over the resolved track", read_disc_surface,
                 "as pin_surface; track = \"resolved\" only")
          .then([](const Config&, K& k) {
            k.setup.measure_roughness = !k.surfaces.empty();
            k.setup.validate();
          })
          // The moving average of friction.csv and friction.png (Fig. 9.23): one
          // tilt period when there is a tilt, else a twentieth of the distance.
          .number("moving_average", &K::moving_average, Range::positive(), length,
                  "window of friction's centred moving average")
          .computed_default(
              [](const K& k) {
                const double tilt = k.setup.nonplanar_slope > 0.0 ? k.setup.tilt_period() : 0.0;
                return tilt > 0.0 ? tilt : k.setup.distance / 20.0;
              },
              "one tilt period with a tilt, else distance/20");
  return table;
}

class MacroPinOnDisc final : public Scale {
 public:
  static inline const Ports ports{{{Quantity::InterfaceLaw, "pin/disc"}, {Quantity::InterfaceLaw, "pin/layer"}},
                                  {{Quantity::MacroResult, "pin/disc"}}};

  explicit MacroPinOnDisc(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const Config& c = setup.section;
    const Config& root = setup.root;
    const auto library = material_library(root);
    case_materials(root, library);
    CaseMaterialKeys names;
    case_material_keys().read(root.section("materials"), names);
    pin_ = names.pin;
    disc_ = names.disc;
    layer_ = names.layer_material;
    PinOnDiscKeys k;
    k.setup.layer_thickness = names.layer_thickness;
    k.e_star_pin = materials::effective_modulus(library.get(pin_), library.get(pin_));
    k.e_star_pair = materials::effective_modulus(library.get(pin_), library.get(disc_));
    pin_on_disc_keys().read(c, k);
    s_ = std::move(k.setup);
    integrator_ = k.integrator;
    adaptive_ = k.adaptive;
    fields_every_ = k.fields_every;
    moving_window_ = k.moving_average;
    surfaces_ = std::move(k.surfaces);
  }

  std::vector<Key> consumes() const override {
    std::vector<Key> out{{ports.consumes[0].what, pin_ + "/" + disc_}};
    if (layer_ != disc_) out.push_back({ports.consumes[1].what, pin_ + "/" + layer_});
    return out;
  }
  std::vector<Key> provides() const override { return ports.provides; }

  // In BEM solves on 128² cells: a solve costs about n² log n²; the explicit
  // stepping makes one a step; the adaptive one's count is not known ahead,
  // but on a layer of finite thickness it does about twice the work of a run on
  // one material (measured on the main job: 1 860-2 170 BEM iterations against
  // 800-880 for bare Si and bulk SiO2, of 0.5 m each).
  double estimated_cost() const override {
    const double n2 = static_cast<double>(s_.grid * s_.grid), per_solve = n2 * std::log2(n2) / (16384.0 * 14.0);
    if (integrator_ == "explicit") return per_solve * std::ceil(s_.distance / s_.explicit_step());
    const double h = s_.layer_thickness;
    return per_solve * 250.0 * (s_.distance / 0.5) * (h > 0.0 && std::isfinite(h) ? 2.0 : 1.0);
  }

  void run(Exchange& exchange, RunContext& ctx) override {
    s_.on_substrate = exchange.get<Quantity::InterfaceLaw>(pin_ + "/" + disc_);
    s_.on_layer = exchange.get<Quantity::InterfaceLaw>(pin_ + "/" + layer_);
    tribometer::PinOnDisc model(s_);

    // Resuming: the model, the samples so far and the field snapshots written
    // before the checkpoint come back; the run then goes on from there.
    std::vector<tribometer::PinOnDiscSample> samples;
    std::vector<Snapshot> snapshots;
    XdmfSidecar series(model.grid(), origin(model.grid()));  // the snapshots in ParaView, the sliding distance as time
    std::size_t n = 0;
    long adaptive_steps = 0;
    double next_step = 0.0;
    Checkpointer& checkpoints = ctx.checkpoints();
    const CheckpointState* saved = checkpoints.restored(kOwner);
    if (saved != nullptr) {
      if (saved->text("integrator") != integrator_)
        throw InputError(fmt::format("{}: saved by the {} integrator, the case asks for {}", saved->origin,
                                     saved->text("integrator"), integrator_));
      model.restore(*saved);  // refused unless a state a run reaches (tribometer/state_bounds.hpp)
      samples = load_samples(*saved, s_, model.distance());
      if (s_.measure_roughness) {
        if (!saved->has("samples/roughness") || saved->array("samples/roughness").size() != 8 * samples.size())
          throw InputError(fmt::format("{}: the samples hold no roughness of a rough run; delete the checkpoint to "
                                       "start afresh",
                                       saved->origin));
        for (std::size_t r = 0; r < samples.size(); ++r)
          tribometer::set_roughness_values(samples[r], saved->array("samples/roughness").data() + 8 * r);
      }
      snapshots = load_snapshots(*saved);
      // The counters as the samples are: whole, within what the run can reach, checked before they are integers.
      for (const std::string& problem :
           {tribometer::count_problem("snapshot_counter", saved->scalar("snapshot_counter"), 0.0,
                                      static_cast<double>(samples.size())),
            tribometer::count_problem("adaptive_steps", saved->scalar("adaptive_steps"), 0.0, 1e12)})
        if (!problem.empty())
          throw InputError(fmt::format("{}: no state a run reaches ({}); delete it to start afresh", saved->origin,
                                       problem));
      if (const double h = saved->scalar("next_step"); !(std::isfinite(h) && h >= 0.0 && h <= s_.distance))
        throw InputError(fmt::format("{}: no state a run reaches (next_step = {:g} m; allowed: within [0, {:g}] m); "
                                     "delete it to start afresh",
                                     saved->origin, h, s_.distance));
      for (const auto& snap : snapshots) write_fields(ctx, model.grid(), snap, &series);
      n = static_cast<std::size_t>(saved->scalar("snapshot_counter"));
      adaptive_steps = static_cast<long>(saved->scalar("adaptive_steps"));
      next_step = saved->scalar("next_step");
      log::info("resuming {} at s = {:g} m ({} samples, step {})", kOwner, model.distance(), samples.size(),
                saved->step);
    }
    auto state = [&] {
      CheckpointState st;
      model.save(st);
      st.put_text("integrator", integrator_);
      save_samples(st, samples);
      if (s_.measure_roughness) {
        std::vector<double> values;
        for (const auto& e : samples) {
          const auto v = tribometer::roughness_values(e);
          values.insert(values.end(), v.begin(), v.end());
        }
        st.put("samples/roughness", values);
      }
      save_snapshots(st, snapshots);
      st.put("snapshot_counter", static_cast<double>(n));
      st.put("adaptive_steps", static_cast<double>(adaptive_steps));
      st.put("next_step", next_step);
      return st;
    };

    Progress progress = ctx.show_progress() ? Progress("pin-on-disc", s_.distance * 1e3, "mm")
                                            : Progress::silent(s_.distance * 1e3);
    auto observe = [&](const tribometer::PinOnDiscSample& x) {
      // Held to the bounds a restored sample is held to (load_samples).
      if (const std::string problem = tribometer::sample_problem(x, s_); !problem.empty())
        throw NumericalError("pin-on-disc", static_cast<long>(samples.size()), "sample", problem);
      samples.push_back(x);
      progress.update(x.distance * 1e3);
      if (fields_every_ > 0 && n++ % fields_every_ == 0) {
        // Numbered, not named by distance: two snapshots closer than any printed
        // precision would otherwise share a group. The distance is an attribute.
        snapshots.push_back(snapshot(model, fmt::format("/macro/fields/{:06d}", snapshots.size())));
        write_fields(ctx, model.grid(), snapshots.back(), &series);
      }
    };
    if (integrator_ == "explicit") {
      model.run([&](const tribometer::PinOnDiscSample& x) {
        observe(x);
        if (model.steps() < model.total_steps()) checkpoints.at_step(kOwner, model.steps(), state);
      });
    } else {
      // Measured on a reduced run (n = 32, 1 µm, Sa = 0.5 µm, 0.06 m, docs/pin_on_disc.md).
      if (s_.track == tribometer::Track::Resolved && !s_.disc_roughness.empty() && s_.layer_thickness > 0.0 &&
          std::isfinite(s_.layer_thickness))
        log::warn("{}: the adaptive integrator on a rough disc over an oxide layer is not verified: with steps of "
                  "up to one cell the materials under the window lag the sliding strip, and μ_mean and the pin's "
                  "wear were 3-4 % below the explicit stepping converged at a quarter of a cell a step (the "
                  "substrate met 1.6 mm early); integrator = \"explicit\" with time_step at most a quarter of a "
                  "cell's sliding ({:.4g} s) is converged there",
                  kOwner, s_.size / static_cast<double>(s_.grid) / 4.0 / s_.velocity);
      tribometer::AdaptiveOptions options = adaptive_;
      options.initial_step = next_step;
      options.observe_start = saved == nullptr;
      options.steps_done = adaptive_steps;
      const double end = s_.distance * (1.0 - 1e-12);
      // Checkpoints (and a stop on SIGINT) only where the integrator restarts,
      // so that a resumed run continues exactly as an uninterrupted one.
      tribometer::run_adaptive(model, options, observe, [&](const tribometer::AdaptiveStatus& status) {
        next_step = status.next_step;
        adaptive_steps = status.steps;
        if (status.segment_end && model.distance() < end) checkpoints.at_step(kOwner, adaptive_steps, state);
      });
    }
    progress.finish();
    report(ctx, model, samples);
    write_fields(ctx, model.grid(), snapshot(model, "/macro/final"));
    write_disc(ctx, model);
    XdmfSidecar(model.grid(), origin(model.grid()))
        .add(ctx.h5(), snapshot_fields("/macro/final"))
        .write(ctx.output_dir() / "final_surfaces.xdmf", ctx.h5().final_path());
    ctx.add_file(ctx.output_dir() / "final_surfaces.xdmf");
    if (series.steps() > 0) {
      series.write(ctx.output_dir() / "fields.xdmf", ctx.h5().final_path(), "s", "m");
      ctx.add_file(ctx.output_dir() / "fields.xdmf");
    }
    exchange.put<Quantity::MacroResult>(provides().front().subject, ctx.results(), provenance_);
  }

 private:
  static constexpr const char* kOwner = "macro/bem-pin-on-disc";

  // An oxide of finite thickness on a substrate: grooves (bands worn through it) can form.
  bool layered() const { return std::isfinite(s_.layer_thickness) && s_.layer_thickness > 0.0; }

  // Surfaces and pressure at one distance (fields_every, and the final state).
  struct Snapshot {
    std::string group;
    std::vector<double> pin, disc, pressure;  // n×n each: the disc as the pin's window sees it
    double distance = 0.0;                    // sliding distance [m]
  };

  static Snapshot snapshot(const tribometer::PinOnDisc& model, std::string group) {
    const RealField disc = model.disc_under_pin();
    return {std::move(group), {model.pin_surface().begin(), model.pin_surface().end()}, {disc.begin(), disc.end()},
            {model.contact().pressure().begin(), model.contact().pressure().end()}, model.distance()};
  }

  static std::vector<XdmfField> snapshot_fields(const std::string& group) {
    return {{group + "/pin", "pin"}, {group + "/disc", "disc"}, {group + "/pressure", "pressure"}};
  }

  // Every output's x and y (fields, sidecars, disc_profile.csv, the figures):
  // 0 on the pin's axis, the window spanning [-lx/2, lx/2) × [-ly/2, ly/2).
  static std::array<double, 2> origin(const Grid2D& g) { return {-0.5 * g.lx, -0.5 * g.ly}; }

  // The snapshot's fields and its distance attribute; a step of `series` if given.
  // What a disc height is: from the unworn plane on a smooth disc; on a rough
  // one, from the initial surface's mean plane, so its roughness shows.
  std::string disc_height_meaning() const {
    return s_.disc_roughness.empty() ? "0 unworn, negative where worn"
                                     : "the initial rough surface (its mean plane at 0) lowered where worn";
  }

  void write_fields(RunContext& ctx, const Grid2D& g, const Snapshot& snap, XdmfSidecar* series = nullptr) const {
    RealField pin(g), disc(g), pressure(g);
    std::copy(snap.pin.begin(), snap.pin.end(), pin.begin());
    std::copy(snap.pressure.begin(), snap.pressure.end(), pressure.begin());
    std::copy(snap.disc.begin(), snap.disc.end(), disc.begin());  // the disc under the pin's window
    ctx.h5().write_field(snap.group + "/pin", pin, "m",
                         "pin surface profile, measured from the plane of its unworn summit (at x = y = 0); x "
                         "across the track, y along the sliding",
                         origin(g));
    ctx.h5().write_field(snap.group + "/disc", disc, "m",
                         fmt::format("disc surface height under the pin's window ({}); x across the track, y "
                                     "along the sliding",
                                     disc_height_meaning()),
                         origin(g));
    ctx.h5().write_field(snap.group + "/pressure", pressure, "Pa",
                         "contact pressure between pin and disc; x across the track, y along the sliding", origin(g));
    ctx.h5().set_attribute(snap.group, "distance", snap.distance);
    ctx.h5().set_attribute(snap.group, "distance_unit", "m");
    if (series != nullptr) series->add_step(ctx.h5(), snap.distance, snapshot_fields(snap.group));
  }

  // The final disc: its mean profile across the track (one value per x, the
  // grooves) and, for a resolved track, the whole circumference.
  void write_disc(RunContext& ctx, const tribometer::PinOnDisc& model) const {
    const Grid2D& g = model.grid();
    const auto profile = model.disc_column_means();
    const auto initial = model.disc_initial_column_means();  // zeros for a smooth disc
    std::vector<double> x(g.nx), depth(g.nx), through(g.nx);
    for (std::size_t i = 0; i < g.nx; ++i) {
      x[i] = g.x(i) - 0.5 * g.lx;
      depth[i] = initial[i] - profile[i];  // an unworn cell 0, not -0
      through[i] = !layered() ? std::nan("") : depth[i] > s_.layer_thickness ? 1.0 : 0.0;
    }
    ctx.h5().write_table("/macro/final/disc_profile", {"x", "worn_depth", "through_layer"}, {x, depth, through},
                         {"m", "m", "1"});
    const auto csv = ctx.output_dir() / "disc_profile.csv";
    write_csv(csv, {"x", "worn_depth", "through_layer"}, {x, depth, through}, {"m", "m", "1"},
              {"macro/bem-pin-on-disc: final worn depth of the disc across the track (mean along it), x = 0 on the "
               "pin's axis; through_layer = 1 where the oxide is worn through (a groove), nan without an oxide on "
               "a substrate (h = 0 or bulk)"});
    ctx.add_file(csv);
    if (s_.track == tribometer::Track::Resolved) {
      const std::size_t cells = s_.track_cells();
      const Grid2D strip(g.nx, cells, g.lx, static_cast<double>(cells) * g.dx());
      RealField disc(strip);
      std::copy(model.disc_profile().begin(), model.disc_profile().end(), disc.begin());
      ctx.h5().write_field("/macro/final/disc_track", disc, "m",
                           fmt::format("disc surface height along the whole track (resolved), {}; x across the "
                                       "track, y along it from where the pin started",
                                       disc_height_meaning()),
                           {-0.5 * g.lx, 0.0});
    }
  }

  // The samples so far as columns of the checkpoint, and back.
  static constexpr int kColumns = 11;
  static void save_samples(CheckpointState& st, const std::vector<tribometer::PinOnDiscSample>& x) {
    std::vector<double> c[kColumns];
    for (const auto& e : x) {
      const double row[kColumns] = {e.distance,         e.friction,      e.friction_integral,
                                    e.pin_wear,         e.disc_wear,     e.contact_fraction,
                                    e.layer_contact,    e.substrate_contact, e.max_pressure,
                                    static_cast<double>(e.iterations), static_cast<double>(e.grooves)};
      for (int k = 0; k < kColumns; ++k) c[k].push_back(row[k]);
    }
    for (int k = 0; k < kColumns; ++k) st.put(std::string("samples/") + kSampleColumns[k], c[k]);
  }

  // The samples of a checkpoint, each within the bounds of a computed one (sample_problem), in order of
  // distance up to the restored state's.
  static std::vector<tribometer::PinOnDiscSample> load_samples(const CheckpointState& st,
                                                                const tribometer::PinOnDiscSetup& setup,
                                                                double restored_distance) {
    const std::vector<double>* c[kColumns];
    for (int k = 0; k < kColumns; ++k) c[k] = &st.array(std::string("samples/") + kSampleColumns[k]);
    std::vector<tribometer::PinOnDiscSample> x(c[0]->size());
    for (int k = 1; k < kColumns; ++k)
      if (c[k]->size() != x.size()) throw InputError(fmt::format("{}: sample columns of different lengths", st.origin));
    const auto refuse = [&](std::size_t r, const std::string& problem) {
      return InputError(fmt::format("{}: no state a run reaches (sample {}: {}); delete the checkpoint to start "
                                    "afresh",
                                    st.origin, r, problem));
    };
    for (std::size_t r = 0; r < x.size(); ++r) {
      for (const std::string& problem : {tribometer::count_problem("BEM iterations", (*c[9])[r], 0.0, 1e9),
                                         tribometer::count_problem("grooves", (*c[10])[r], 0.0, 1e9)})
        if (!problem.empty()) throw refuse(r, problem);
      x[r] = {(*c[0])[r], (*c[1])[r], (*c[2])[r], (*c[3])[r],  (*c[4])[r],
              (*c[5])[r], (*c[6])[r], (*c[7])[r], (*c[8])[r], static_cast<int>((*c[9])[r]),
              static_cast<int>((*c[10])[r])};
      if (const std::string problem = tribometer::sample_problem(x[r], setup); !problem.empty()) throw refuse(r, problem);
      if (r > 0 && x[r].distance < x[r - 1].distance)
        throw refuse(r, fmt::format("distance {:g} m after {:g} m", x[r].distance, x[r - 1].distance));
      if (x[r].distance > restored_distance * (1.0 + 1e-12))
        throw refuse(r, fmt::format("distance {:g} m beyond the state's {:g} m", x[r].distance, restored_distance));
    }
    return x;
  }

  static void save_snapshots(CheckpointState& st, const std::vector<Snapshot>& snaps) {
    std::string groups;
    for (std::size_t k = 0; k < snaps.size(); ++k) {
      groups += (k ? "\n" : "") + snaps[k].group;
      st.put(fmt::format("snapshot{}/pin", k), snaps[k].pin);
      st.put(fmt::format("snapshot{}/disc", k), snaps[k].disc);
      st.put(fmt::format("snapshot{}/pressure", k), snaps[k].pressure);
      st.put(fmt::format("snapshot{}/distance", k), snaps[k].distance);
    }
    st.put_text("snapshot_groups", groups);
  }

  static std::vector<Snapshot> load_snapshots(const CheckpointState& st) {
    std::vector<Snapshot> out;
    const std::string& groups = st.text("snapshot_groups");
    std::size_t start = 0;
    while (start < groups.size()) {
      const auto end = std::min(groups.find('\n', start), groups.size());
      const std::size_t k = out.size();
      out.push_back({groups.substr(start, end - start), st.array(fmt::format("snapshot{}/pin", k)),
                     st.array(fmt::format("snapshot{}/disc", k)), st.array(fmt::format("snapshot{}/pressure", k)),
                     st.scalar(fmt::format("snapshot{}/distance", k))});
      start = end + 1;
    }
    return out;
  }

  static constexpr const char* kSampleColumns[kColumns] = {
      "distance",      "friction",          "friction_integral", "pin_wear",   "disc_wear", "contact_fraction",
      "layer_contact", "substrate_contact", "max_pressure",      "iterations", "grooves"};

  void report(RunContext& ctx, const tribometer::PinOnDisc& model, const std::vector<tribometer::PinOnDiscSample>& x) {
    std::vector<double> s, mu, integral, v_pin, v_disc, area, on_layer, iterations, grooves, k_pin, k_disc;
    for (const auto& e : x) {
      k_pin.push_back(tribometer::specific_wear_rate(e.pin_wear, s_.normal_load, e.distance));
      k_disc.push_back(tribometer::specific_wear_rate(e.disc_wear, s_.normal_load, e.distance));
      s.push_back(e.distance);
      mu.push_back(e.friction);
      integral.push_back(e.friction_integral);
      v_pin.push_back(e.pin_wear);
      v_disc.push_back(e.disc_wear);
      area.push_back(e.contact_fraction);
      on_layer.push_back(e.layer_contact);
      iterations.push_back(e.iterations);
      // Grooves are bands worn through an oxide into the substrate: none to count without both (h = 0 or bulk).
      grooves.push_back(layered() ? static_cast<double>(e.grooves) : std::nan(""));
    }
    // Every average of μ is over sliding distance, from the integral ∫μ ds the
    // integrator carries (samples of an adaptive run are not evenly spaced).
    const tribometer::FrictionAverage average(s, integral);
    const auto smoothed = average.centred_moving_average(moving_window_);
    const std::string k_unit = tribometer::specific_wear_rate_unit;
    ctx.h5().write_table("/macro/series",
                         {"distance", "friction", "friction_moving_average", "friction_integral", "pin_wear",
                          "disc_wear", "contact_fraction", "layer_share", "grooves", "bem_iterations",
                          "pin_specific_wear_rate", "disc_specific_wear_rate"},
                         {s, mu, smoothed, integral, v_pin, v_disc, area, on_layer, grooves, iterations, k_pin, k_disc},
                         {"m", "1", "1", "m", "m^3", "m^3", "1", "1", "1", "1", k_unit, k_unit});
    const auto csv = ctx.output_dir() / "friction.csv";
    write_csv(csv,
              {"distance", "friction", "friction_moving_average", "pin_wear", "disc_wear", "contact_fraction",
               "layer_share", "grooves", "pin_specific_wear_rate", "disc_specific_wear_rate"},
              {s, mu, smoothed, v_pin, v_disc, area, on_layer, grooves, k_pin, k_disc},
              {"m", "1", "1", "m^3", "m^3", "1", "1", "1", k_unit, k_unit},
              {"macro/bem-pin-on-disc (§9.3.2): friction and wear volumes against sliding distance",
               fmt::format("friction_moving_average: centred moving mean over {:g} m of sliding (Fig. 9.23)",
                           moving_window_),
               "grooves: bands across the track worn through the oxide, nan without an oxide on a substrate (h = 0 "
               "or bulk)",
               fmt::format("pin/disc_specific_wear_rate: k = V/(F_N s) (Archard) at F_N = {:g} N, in mm^3/(N·m); nan "
                           "at s = 0",
                           s_.normal_load)});
    ctx.add_file(csv);
    if (s_.measure_roughness) report_roughness(ctx, x);

    const double tilt = s_.nonplanar_slope > 0.0 ? s_.tilt_period() : 0.0;
    const double first = s.front(), last = s.back();
    const bool moved = last > first;
    const auto final_w = tribometer::final_window(first, last, tilt);
    const auto initial_w = tribometer::initial_window(first, last, tilt);
    ctx.report("mu_mean", moved ? average.mean(first, last) : mu.front(), "1",
               "friction coefficient averaged over the sliding distance");
    ctx.report("mu_final", moved ? average.mean(final_w.from, final_w.to) : mu.back(), "1",
               "friction coefficient averaged over " + final_w.description);
    ctx.report("mu_initial", moved ? average.mean(initial_w.from, initial_w.to) : mu.front(), "1",
               "friction coefficient averaged over " + initial_w.description);
    ctx.report("pin_wear", v_pin.back(), "m^3", "worn volume of the pin");
    ctx.report("disc_wear", v_disc.back(), "m^3", "worn volume of the disc (whole track)");
    ctx.report("pin_specific_wear_rate", k_pin.back(), k_unit,
               "specific wear rate of the pin, k = V/(F_N s) (Archard), in mm³/(N·m)");
    ctx.report("disc_specific_wear_rate", k_disc.back(), k_unit,
               "specific wear rate of the disc, k = V/(F_N s) (Archard), in mm³/(N·m)");
    ctx.report("contact_solves", model.contact_solves(), "1", "BEM contact solves");
    ctx.report("contact_iterations", static_cast<double>(model.contact_iterations()), "1",
               "BEM iterations of all the contact solves");
    ctx.note("integrator", integrator_);
    if (integrator_ == "explicit")
      ctx.report("time_step", s_.explicit_step() / s_.velocity, "s",
                 s_.step_bounded() ? "explicit time step, bounded to one cell of sliding on the resolved track"
                                   : "explicit time step");
    ctx.report("distance", s.back(), "m", "sliding distance covered");
    if (layered()) {
      ctx.report("grooves", x.back().grooves, "1",
                 "grooves at the end: separate bands across the track where the oxide is worn through");
      ctx.report("grooves_max", *std::max_element(grooves.begin(), grooves.end()), "1",
                 "the most grooves at any point of the run");
    }
    for (const auto& e : x)
      if (e.substrate_contact > 0.0 && std::isfinite(s_.layer_thickness) && s_.layer_thickness > 0.0) {
        ctx.report("substrate_reached_at", e.distance, "m", "sliding distance at which the pin first touches " + disc_);
        break;
      }
  }

  // The roughness of the worn surfaces against sliding distance (a rough run): roughness.csv,
  // /macro/roughness, and the initial surfaces' and the worn surfaces' final roughness as headline results.
  void report_roughness(RunContext& ctx, const std::vector<tribometer::PinOnDiscSample>& x) const {
    std::vector<double> s, values[8];
    for (const auto& e : x) {
      s.push_back(e.distance);
      const auto v = tribometer::roughness_values(e);
      for (int k = 0; k < 8; ++k) values[k].push_back(v[static_cast<std::size_t>(k)]);
    }
    const std::vector<std::string> names{"distance",       "pin_sa",      "pin_sq",       "pin_hprime_rms",
                                         "pin_region_cells", "disc_sa",   "disc_sq",      "disc_hprime_rms",
                                         "disc_region_cells"};
    const std::vector<std::string> units{"m", "m", "m", "1", "1", "m", "m", "1", "1"};
    std::vector<std::span<const double>> columns{s};
    for (const auto& v : values) columns.emplace_back(v);
    ctx.h5().write_table("/macro/roughness", names, columns, units);
    std::vector<std::string> notes{
        "macro/bem-pin-on-disc: roughness of the worn surfaces against sliding distance",
        "pin: over its worn region (the window's cells worn so far; before any wear, the cells in contact), about "
        "the region's least-squares quadric (the sphere's cap, the worn flat, to second order)",
        "disc: over its wear track on the resolved track's strip (the columns across the track worn anywhere along "
        "the circumference, whole; before any wear, the columns under the contact), about the track's profile (each "
        "column's mean along the track); nan on the averaged track, whose disc holds no roughness along y",
        "Sa (1.4), Sq = h_RMS (1.5), h'_RMS (1.6) by forward differences between neighbouring cells of the region "
        "(cells of size/grid); nan for a region of fewer than 3 cells; region_cells: its cells"};
    for (const auto& [key, what] : surfaces_) notes.push_back(key + ": " + what);
    const auto csv = ctx.output_dir() / "roughness.csv";
    write_csv(csv, names, columns, units, notes);
    ctx.add_file(csv);
    for (const auto& [key, what] : surfaces_) ctx.note(key, what);
    // A figure is reported where it is defined (a region of at least 3 cells).
    const auto report = [&](const std::string& name, double value, const std::string& unit, const std::string& what) {
      if (std::isfinite(value)) ctx.report(name, value, unit, what);
    };
    const Grid2D g = Grid2D::square(s_.grid, s_.size);
    const auto whole = [](const std::vector<double>& h, std::size_t nx, std::size_t ny, double dx) {
      const std::vector<char> all(h.size(), 1);
      return tribometer::residual_roughness(h.data(), all.data(), nx, ny, dx, dx);  // zero mean already
    };
    if (!s_.pin_roughness.empty()) {
      const auto r = whole(s_.pin_roughness, g.nx, g.ny, g.dx());
      report("pin_surface_sq", r.sq, "m", "RMS height Sq of the pin's initial roughness over the window");
      report("pin_surface_hprime_rms", r.hprime_rms, "1",
             "RMS slope h'_RMS of the pin's initial roughness over the window, by differences between cells");
    }
    if (!s_.disc_roughness.empty()) {
      const auto r = whole(s_.disc_roughness, g.nx, s_.track_cells(), g.dx());
      report("disc_surface_sq", r.sq, "m", "RMS height Sq of the disc's initial roughness over the track");
      report("disc_surface_hprime_rms", r.hprime_rms, "1",
             "RMS slope h'_RMS of the disc's initial roughness over the track, by differences between cells");
    }
    const auto& last = x.back();
    report("pin_sq_final", last.pin_roughness.sq, "m", "RMS height Sq of the pin over its worn region at the end");
    report("pin_hprime_rms_final", last.pin_roughness.hprime_rms, "1",
           "RMS slope h'_RMS of the pin over its worn region at the end");
    report("disc_sq_final", last.disc_roughness.sq, "m", "RMS height Sq of the disc over its worn track at the end");
    report("disc_hprime_rms_final", last.disc_roughness.hprime_rms, "1",
           "RMS slope h'_RMS of the disc over its worn track at the end");
  }

  Provenance provenance_;
  std::vector<std::pair<std::string, std::string>> surfaces_;  // key, what the surface is
  std::string pin_, disc_, layer_;
  tribometer::PinOnDiscSetup s_;
  std::string integrator_ = "explicit";
  tribometer::AdaptiveOptions adaptive_;
  std::size_t fields_every_ = 0;
  double moving_window_ = 0.0;
};

}  // namespace

WEARSCALE_BACKEND(macro_pin_on_disc) {
  registry.add<MacroPinOnDisc>("macro", "bem-pin-on-disc",
                               "pin-on-disc wear with the BEM contact of pin and oxidized disc (§9.3.2)",
                               [] { return pin_on_disc_keys().schema("scale.macro"); });
}

}  // namespace wearscale::coupling
