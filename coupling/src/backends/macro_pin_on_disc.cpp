// macro/bem-pin-on-disc: the pin-on-disc wear model of §9.3.2 on the BEM,
// driven by the interface laws of the nanoscale (one per interface the pin
// meets: the oxide layer and the substrate beneath it).
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "backends/backends.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/core/checkpoint.hpp"
#include "wearscale/core/csv.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/xdmf.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::coupling {

namespace {

class MacroPinOnDisc final : public Scale {
 public:
  explicit MacroPinOnDisc(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const Config& c = setup.section;
    const Config& root = setup.root;
    const auto library = material_library(root);
    case_materials(root, library);
    pin_ = root.string("materials.pin");
    disc_ = root.string("materials.disc");
    layer_ = root.string_or("materials.layer.material", disc_);
    s_.layer_thickness = root.has("materials.layer")
                             ? root.number("materials.layer.thickness", Range::non_negative().or_infinite(), units::length)
                             : 0.0;
    // Defaults: the thesis setup (§9.3.2 "Setup").
    s_.grid = static_cast<std::size_t>(c.integer_or("grid", 128, Range::closed(8, 4096)));
    s_.size = c.number_or("size", 2e-3, Range::positive(), units::length);
    s_.pin_radius = c.number_or("pin_radius", 3e-3, Range::positive(), units::length);
    s_.normal_load = c.number_or("normal_load", 1.0, Range::positive(), units::force);
    s_.velocity = c.number_or("velocity", 8e-3, Range::positive(), units::velocity);
    s_.path_length = c.number_or("path_length", 6.28e-3, Range::positive(), units::length);
    s_.distance = c.number_or("distance", 0.5, Range::positive(), units::length);
    // At least one step: a longer one would overshoot the distance (the last step is cut to land on it).
    s_.time_step = c.number_or("time_step", 0.02, Range::open_closed(0.0, s_.distance / s_.velocity), units::time);
    s_.nonplanar_slope = c.number_or("nonplanarity.slope", 0.0, Range::closed_open(0.0, 0.2));
    s_.nonplanar_period = c.number_or("nonplanarity.period", 0.05, Range::positive(), units::length);
    s_.tolerance = c.number_or("tolerance", 1e-10, Range::open(0.0, 1e-3));
    s_.boundary = c.choice_or("boundary", "periodic", {"periodic", "free"}) == "free" ? bem::Boundary::Free
                                                                                   : bem::Boundary::Periodic;
    // Elastic properties of the contact solve: the pin's for both bodies (the
    // thesis, which could not model layered bodies), the pair's, or a value.
    const std::string elastic = c.choice_or("elastic", "pin", {"pin", "pair"});
    s_.e_star = elastic == "pin" ? materials::effective_modulus(library.get(pin_), library.get(pin_))
                                 : materials::effective_modulus(library.get(pin_), library.get(disc_));
    s_.e_star = c.number_or("e_star", s_.e_star, Range::positive(), units::pressure);
    integrator_ = c.choice_or("integrator", "explicit", {"explicit", "adaptive"});
    const tribometer::AdaptiveOptions defaults;
    adaptive_.relative_tolerance = c.number_or("adaptive.rtol", defaults.relative_tolerance, Range::open(0.0, 1.0));
    adaptive_.absolute_tolerance =
        c.number_or("adaptive.atol", defaults.absolute_tolerance, Range::positive(), units::length);
    adaptive_.max_step = c.number_or("adaptive.max_step", defaults.max_step, Range::positive(), units::length);
    fields_every_ = static_cast<std::size_t>(c.integer_or("fields_every", 0, Range::non_negative()));
    s_.validate();
    // Every step keeps a sample (the series, its copy in each checkpoint and in run.h5): a time step
    // many orders below the distance's would exhaust memory long before the run ended.
    const double steps = std::ceil(s_.distance / (s_.velocity * s_.time_step));
    require_memory(steps * 3.0 * 9.0 * sizeof(double),
                   fmt::format("{}: key '{}': {:.3g} steps of {:g} s over {:g} m", c.where("time_step"),
                               c.full_key("time_step"), steps, s_.time_step, s_.distance),
                   "a longer time_step or a shorter distance");
  }

  std::vector<Key> consumes() const override {
    std::vector<Key> out{{Quantity::InterfaceLaw, pin_ + "/" + disc_}};
    if (layer_ != disc_) out.push_back({Quantity::InterfaceLaw, pin_ + "/" + layer_});
    return out;
  }
  std::vector<Key> provides() const override { return {{Quantity::MacroResult, "pin/disc"}}; }

  void run(Exchange& exchange, RunContext& ctx) override {
    s_.on_substrate = exchange.get<materials::InterfaceLaw>({Quantity::InterfaceLaw, pin_ + "/" + disc_});
    s_.on_layer = exchange.get<materials::InterfaceLaw>({Quantity::InterfaceLaw, pin_ + "/" + layer_});
    tribometer::PinOnDisc model(s_);

    // Resuming: the model, the samples so far and the field snapshots written
    // before the checkpoint come back; the run then goes on from there.
    std::vector<tribometer::PinOnDiscSample> samples;
    std::vector<Snapshot> snapshots;
    XdmfSidecar series(model.grid());  // the snapshots in ParaView, the sliding distance as time
    std::size_t n = 0;
    long adaptive_steps = 0;
    double next_step = 0.0;
    Checkpointer& checkpoints = ctx.checkpoints();
    const CheckpointState* saved = checkpoints.restored(kOwner);
    if (saved != nullptr) {
      if (saved->text("integrator") != integrator_)
        throw InputError(fmt::format("{}: saved by the {} integrator, the case asks for {}", saved->origin,
                                     saved->text("integrator"), integrator_));
      model.restore(*saved);
      samples = load_samples(*saved);
      snapshots = load_snapshots(*saved);
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
      save_snapshots(st, snapshots);
      st.put("snapshot_counter", static_cast<double>(n));
      st.put("adaptive_steps", static_cast<double>(adaptive_steps));
      st.put("next_step", next_step);
      return st;
    };

    Progress progress = ctx.show_progress() ? Progress("pin-on-disc", s_.distance * 1e3, "mm")
                                            : Progress::silent(s_.distance * 1e3);
    auto observe = [&](const tribometer::PinOnDiscSample& x) {
      samples.push_back(x);
      progress.update(x.distance * 1e3);
      if (fields_every_ > 0 && n++ % fields_every_ == 0) {
        snapshots.push_back(snapshot(model, fmt::format("/macro/fields/{:08.4f}", x.distance)));
        write_fields(ctx, model.grid(), snapshots.back(), &series);
      }
    };
    if (integrator_ == "explicit") {
      model.run([&](const tribometer::PinOnDiscSample& x) {
        observe(x);
        if (model.steps() < model.total_steps()) checkpoints.at_step(kOwner, model.steps(), state);
      });
    } else {
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
    XdmfSidecar(model.grid())
        .add(ctx.h5(), snapshot_fields("/macro/final"))
        .write(ctx.output_dir() / "final_surfaces.xdmf", ctx.h5().final_path());
    ctx.add_file(ctx.output_dir() / "final_surfaces.xdmf");
    if (series.steps() > 0) {
      series.write(ctx.output_dir() / "fields.xdmf", ctx.h5().final_path(), "s", "m");
      ctx.add_file(ctx.output_dir() / "fields.xdmf");
    }
    exchange.put(provides().front(), ctx.results(), provenance_);
  }

 private:
  static constexpr const char* kOwner = "macro/bem-pin-on-disc";

  // Surfaces and pressure at one distance (fields_every, and the final state).
  struct Snapshot {
    std::string group;
    std::vector<double> pin, disc, pressure;  // pin and pressure n×n, disc one value per x column
    double distance = 0.0;                    // sliding distance [m]
  };

  static Snapshot snapshot(const tribometer::PinOnDisc& model, std::string group) {
    return {std::move(group), {model.pin_surface().begin(), model.pin_surface().end()}, model.disc_profile(),
            {model.contact().pressure().begin(), model.contact().pressure().end()}, model.distance()};
  }

  static std::vector<XdmfField> snapshot_fields(const std::string& group) {
    return {{group + "/pin", "pin"}, {group + "/disc", "disc"}, {group + "/pressure", "pressure"}};
  }

  // The snapshot's fields and its distance attribute; a step of `series` if given.
  static void write_fields(RunContext& ctx, const Grid2D& g, const Snapshot& snap, XdmfSidecar* series = nullptr) {
    RealField pin(g), disc(g), pressure(g);
    std::copy(snap.pin.begin(), snap.pin.end(), pin.begin());
    std::copy(snap.pressure.begin(), snap.pressure.end(), pressure.begin());
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.ny; ++j) disc(i, j) = snap.disc[i];
    ctx.h5().write_field(snap.group + "/pin", pin, "m");
    ctx.h5().write_field(snap.group + "/disc", disc, "m");
    ctx.h5().write_field(snap.group + "/pressure", pressure, "Pa");
    ctx.h5().set_attribute(snap.group, "distance", snap.distance);
    ctx.h5().set_attribute(snap.group, "distance_unit", "m");
    if (series != nullptr) series->add_step(ctx.h5(), snap.distance, snapshot_fields(snap.group));
  }

  // The samples so far as columns of the checkpoint, and back.
  static void save_samples(CheckpointState& st, const std::vector<tribometer::PinOnDiscSample>& x) {
    std::vector<double> c[9];
    for (const auto& e : x) {
      const double row[9] = {e.distance,      e.friction,          e.pin_wear,     e.disc_wear, e.contact_fraction,
                             e.layer_contact, e.substrate_contact, e.max_pressure, static_cast<double>(e.iterations)};
      for (int k = 0; k < 9; ++k) c[k].push_back(row[k]);
    }
    for (int k = 0; k < 9; ++k) st.put(std::string("samples/") + kSampleColumns[k], c[k]);
  }

  static std::vector<tribometer::PinOnDiscSample> load_samples(const CheckpointState& st) {
    const std::vector<double>* c[9];
    for (int k = 0; k < 9; ++k) c[k] = &st.array(std::string("samples/") + kSampleColumns[k]);
    std::vector<tribometer::PinOnDiscSample> x(c[0]->size());
    for (int k = 1; k < 9; ++k)
      if (c[k]->size() != x.size()) throw InputError(fmt::format("{}: sample columns of different lengths", st.origin));
    for (std::size_t r = 0; r < x.size(); ++r)
      x[r] = {(*c[0])[r], (*c[1])[r], (*c[2])[r], (*c[3])[r], (*c[4])[r],
              (*c[5])[r], (*c[6])[r], (*c[7])[r], static_cast<int>((*c[8])[r])};
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

  static constexpr const char* kSampleColumns[9] = {"distance",          "friction",     "pin_wear",
                                                    "disc_wear",         "contact_fraction", "layer_contact",
                                                    "substrate_contact", "max_pressure", "iterations"};

  void report(RunContext& ctx, const tribometer::PinOnDisc& model, const std::vector<tribometer::PinOnDiscSample>& x) {
    std::vector<double> s, mu, v_pin, v_disc, area, on_layer, iterations;
    for (const auto& e : x) {
      s.push_back(e.distance);
      mu.push_back(e.friction);
      v_pin.push_back(e.pin_wear);
      v_disc.push_back(e.disc_wear);
      area.push_back(e.contact_fraction);
      on_layer.push_back(e.layer_contact);
      iterations.push_back(e.iterations);
    }
    ctx.h5().write_table("/macro/series", {"distance", "friction", "pin_wear", "disc_wear", "contact_fraction",
                                           "layer_share", "bem_iterations"},
                         {s, mu, v_pin, v_disc, area, on_layer, iterations}, {"m", "1", "m^3", "m^3", "1", "1", "1"});
    const auto csv = ctx.output_dir() / "friction.csv";
    write_csv(csv, {"distance_m", "friction", "pin_wear_m3", "disc_wear_m3", "contact_fraction", "layer_share"},
              {s, mu, v_pin, v_disc, area, on_layer},
              {"macro/bem-pin-on-disc (§9.3.2): friction and wear volumes against sliding distance"});
    ctx.add_file(csv);

    // Time average over the run (samples are uniform in s for the explicit
    // integrator; weighted by the sample spacing otherwise) and the final value
    // as the mean over the last 5 % of the distance (μ(s) is noisy, Fig. 9.20).
    double integral = 0.0, tail = 0.0, tail_length = 0.0;
    const double total = s.back() - s.front(), tail_start = s.back() - 0.05 * total;
    for (std::size_t k = 1; k < s.size(); ++k) {
      const double ds = s[k] - s[k - 1], m = 0.5 * (mu[k] + mu[k - 1]);
      integral += m * ds;
      if (s[k] > tail_start) tail += m * ds, tail_length += ds;
    }
    ctx.report("mu_mean", total > 0 ? integral / total : mu.front(), "1", "time-averaged friction coefficient");
    ctx.report("mu_final", tail_length > 0 ? tail / tail_length : mu.back(), "1",
               "friction coefficient over the last 5 % of the sliding distance");
    ctx.report("pin_wear", v_pin.back(), "m^3", "worn volume of the pin");
    ctx.report("disc_wear", v_disc.back(), "m^3", "worn volume of the disc (whole track)");
    ctx.report("contact_solves", model.contact_solves(), "1", "BEM contact solves");
    ctx.report("distance", s.back(), "m", "sliding distance covered");
    for (const auto& e : x)
      if (e.substrate_contact > 0.0 && std::isfinite(s_.layer_thickness) && s_.layer_thickness > 0.0) {
        ctx.report("substrate_reached_at", e.distance, "m", "sliding distance at which the pin first touches " + disc_);
        break;
      }
  }

  Provenance provenance_;
  std::string pin_, disc_, layer_;
  tribometer::PinOnDiscSetup s_;
  std::string integrator_ = "explicit";
  tribometer::AdaptiveOptions adaptive_;
  std::size_t fields_every_ = 0;
};

}  // namespace

void register_macro_pin_on_disc(ScaleRegistry& registry) {
  registry.add({"macro", "bem-pin-on-disc", "pin-on-disc wear with the BEM contact of pin and oxidized disc (§9.3.2)",
                {"InterfaceLaw(pin/disc)", "InterfaceLaw(pin/layer)"},
                {"MacroResult(pin/disc)"}},
               [](const ScaleSetup& s) { return std::make_unique<MacroPinOnDisc>(s); });
}

}  // namespace wearscale::coupling
