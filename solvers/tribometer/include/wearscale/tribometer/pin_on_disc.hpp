#pragma once
// The pin-on-disc wear model of §9.3.2: a spherical pin pressed on a disc
// whose oxide layer of thickness h_layer covers the substrate. At each step
// the contact is solved with the BEM; each contacting cell slides with
// p_T = μ0 p_N of its interface (9.12) and wears by dh = (p_N/p_crit) v dt
// (9.23), shared ½/½ between pin and disc on a like-on-like interface
// (9.24)–(9.25) and all on the disc otherwise (9.26)–(9.27).
//
// The disc track is either averaged (§9.3.2: one height per x column,
// invariant along the sliding direction y, its wear scaled by L/L_path) or
// resolved (the whole circumference stored as a strip of L_path along y, the
// wear deposited on the part of the strip the pin slides over, a tilt of the
// disc turning once per revolution).
//
// Geometry: heights z along the pin's axis; the pin's surface is
// z_pin = R − √(R² − r²) (+ its wear), the disc's z_disc = −(its wear) (+ a
// rotating tilt); the BEM sees the rigid profile h = z_disc − z_pin on a flat
// of contact modulus E*.
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/materials/junction_model.hpp"

namespace wearscale::tribometer {

/// An implicit stage whose contact solve did not converge (see solve_stage).
struct StageNotSolved : NumericalError {
  using NumericalError::NumericalError;
};

/// Which material the pin meets at a cell: the oxide while the worn depth is
/// below h_layer. `Disc`: the depth of the worn disc (the oxide tilts with the
/// disc, physical). `Tilted`: the depth with the tilt plane added, the
/// literal reading of §9.3.2 that reproduces the trends of Figs. 9.23–9.25.
enum class LayerTest { Disc, Tilted };
/// The disc track: averaged along y (§9.3.2) or resolved over the circumference.
enum class Track { Averaged, Resolved };

struct PinOnDiscSetup {
  std::size_t grid = 128;           ///< n × n cells
  double size = 2e-3;               ///< L [m]
  double pin_radius = 3e-3;         ///< R [m]
  double normal_load = 1.0;         ///< F_N [N]
  double velocity = 8e-3;           ///< v [m/s]
  double path_length = 6.28e-3;     ///< L_path [m]
  double time_step = 0.02;          ///< dt [s] (explicit stepping; first step of the adaptive one)
  double distance = 0.5;            ///< sliding distance to cover [m]
  double layer_thickness = 1e-6;    ///< h_layer [m]; 0: bare substrate; +inf: bulk layer material
  double e_star = 37.6e9;           ///< contact modulus of the BEM solve [Pa]
  double nonplanar_slope = 0.0;     ///< slope of the rotating tilt of the disc
  double nonplanar_period = 0.05;   ///< its rotation period in sliding distance [m] (resolved track: L_path)
  LayerTest layer_test = LayerTest::Disc;
  Track track = Track::Averaged;
  double tolerance = 1e-10;         ///< BEM orthogonality error (explicit steps, and the adaptive integrator's rates)
  /// BEM orthogonality error of an implicit stage's solve (adaptive integrator):
  /// ε h_rms ≈ 1e-12 m of gap on the contact at 1e-8, 1e-4 of the heights' tolerance
  double stage_tolerance = 1e-8;
  /// Whether an implicit stage's solve is preconditioned by the stage's own
  /// (K(0) + A)⁻¹ (true), or unpreconditioned (Polonsky–Keer), for comparison.
  bool stage_preconditioner = true;
  int max_iterations = 20000;       ///< BEM iterations of a solve (of an implicit stage: at most 3000, then a shorter step)
  bem::Boundary boundary = bem::Boundary::Periodic;  ///< of the BEM cell: periodic images, or an isolated pin (free)
  materials::InterfaceLaw on_layer;      ///< pin on the oxide layer (e.g. SiO2/SiO2)
  materials::InterfaceLaw on_substrate;  ///< pin on the substrate (e.g. SiO2/Si)
  bool like_on_like = true;         ///< pin and layer of one material: wear shared ½/½ on the layer
  /// Initial roughness [m] added to the unworn surfaces; empty: smooth. The pin's over
  /// its n × n window (grid order, index i·n + j); the disc's over the resolved track's
  /// n × track_cells() strip (index i·track_cells() + m). The averaged track's disc is
  /// invariant along y and holds none (validate refuses it). The oxide of a layered disc
  /// follows the rough surface: the worn depth that decides the material is measured
  /// from the initial (rough) height of each cell.
  std::vector<double> pin_roughness, disc_roughness;
  /// Whether the samples carry the roughness of the worn surfaces (PinOnDiscSample): on
  /// for a rough run; off keeps a smooth run's work as it was.
  bool measure_roughness = false;

  /// InputError naming the parameter for any value out of range.
  void validate() const;
  /// InputError if an interface law is missing or incomplete.
  void validate_laws() const;
  /// Cells of the resolved track along y: L_path/Δx rounded (≥ n).
  std::size_t track_cells() const;
  /// The rotation period of the tilt: nonplanar_period, or the track's length when resolved.
  double tilt_period() const;
  /// The sliding distance of an explicit step: v·time_step, but on a resolved
  /// track at most one cell (size/grid): the pin moves at most one cell a step,
  /// the step below which the resolved track converges (docs/pin_on_disc.md).
  double explicit_step() const;
  /// Whether that bound shortens the step (v·time_step is longer than a cell on a resolved track).
  bool step_bounded() const;
  /// Whether the tilt enters the test of the material (layer_test = Tilted
  /// with a slope): the material then changes with the tilt's turn, not only
  /// with the wear.
  bool tilt_in_layer_test() const { return layer_test == LayerTest::Tilted && nonplanar_slope > 0.0; }
};

/// Roughness of a surface inside a region, its form removed: Sa (1.4), Sq = h_RMS
/// (1.5), and h'_RMS (1.6) by forward differences over the pairs of neighbouring
/// cells both inside the region. NaN when not measured (or fewer than 3 cells).
struct RegionRoughness {
  double sa = std::numeric_limits<double>::quiet_NaN();
  double sq = std::numeric_limits<double>::quiet_NaN();
  double hprime_rms = std::numeric_limits<double>::quiet_NaN();
  double cells = 0.0;  ///< cells in the region
};

/// The roughness of residual heights e (their form already removed; nx × ny, index
/// i·ny + j, cells dx × dy) over the cells with in[k] != 0.
RegionRoughness residual_roughness(const double* e, const char* in, std::size_t nx, std::size_t ny, double dx,
                                   double dy);
/// The same of heights h about their form over the region: its least-squares
/// quadric (a sphere's cap, a worn flat or a groove across it, to second order),
/// a plane for fewer than 6 cells.
RegionRoughness region_roughness(const double* h, const char* in, std::size_t nx, std::size_t ny, double dx,
                                 double dy);

struct PinOnDiscSample;
/// A sample's two roughnesses as 8 values (pin Sa, Sq, h'_RMS, cells, then the disc's), for checkpoints.
std::vector<double> roughness_values(const PinOnDiscSample& x);
void set_roughness_values(PinOnDiscSample& x, const double* values);

/// The state after a step, and what happened during it.
struct PinOnDiscSample {
  double distance = 0.0;           ///< s [m]
  double friction = 0.0;           ///< μ = Σ p_T ΔA / F_N
  double friction_integral = 0.0;  ///< ∫₀ˢ μ ds' [m], by the integrator (the source of every average of μ)
  double pin_wear = 0.0;           ///< worn volume of the pin so far [m³]
  double disc_wear = 0.0;          ///< worn volume of the disc (whole track) so far [m³]
  double contact_fraction = 0.0;   ///< A/A0 of the BEM contact (cells with p > 0)
  double layer_contact = 0.0;      ///< share of the contact cells on the layer
  double substrate_contact = 0.0;  ///< share on the substrate
  double max_pressure = 0.0;       ///< [Pa]
  int iterations = 0;              ///< BEM iterations of this step's solve
  int grooves = 0;                 ///< grooves: separate bands of x where the disc is worn through the layer
  /// With setup().measure_roughness: the pin's roughness over its worn region (the
  /// cells worn so far; before any wear, the cells in contact) about its quadric form;
  /// the disc's over its wear track on the resolved strip (the columns worn anywhere
  /// along the circumference, whole; before any wear, the columns under the contact)
  /// about the track's profile (each column's mean along it). The averaged track's
  /// disc holds no roughness: NaN.
  RegionRoughness pin_roughness{}, disc_roughness{};
};

class PinOnDisc {
 public:
  explicit PinOnDisc(const PinOnDiscSetup& setup);
  ~PinOnDisc();
  PinOnDisc(const PinOnDisc&) = delete;
  PinOnDisc& operator=(const PinOnDisc&) = delete;

  /// Solves the contact of the current surfaces (at distance s, for the tilt)
  /// and fills `out` with friction and contact shares; writes the wear rates
  /// dz/ds of pin and disc (per unit sliding distance) if the spans are given.
  void evaluate(double s, PinOnDiscSample& out, std::vector<double>* pin_rate, std::vector<double>* disc_rate);

  /// One explicit step of the thesis (§9.3.2, "Model summary"): solve, then
  /// wear by rate × v dt. Returns the sample of the state the step started from.
  PinOnDiscSample step();
  /// Steps until the sliding distance is covered, calling `observe` after
  /// each, then once more with the final state. Continues from steps() when
  /// the model was restored from a checkpoint.
  void run(const std::function<void(const PinOnDiscSample&)>& observe);

  /// Explicit steps taken so far, and how many cover setup().distance.
  long steps() const { return steps_; }
  long total_steps() const;

  /// Everything the next steps depend on (surfaces, worn volumes, distance,
  /// step count, the contact solver's warm start and the rate of the last
  /// implicit stage), bit for bit.
  void save(CheckpointState& state) const;
  /// Restores a saved state; InputError if it does not fit this setup's grid,
  /// or is no state a run reaches (state_problem: the bounds a computed state is held to).
  void restore(const CheckpointState& state);
  /// "" if the current state is within the physical bounds of a run of this setup (distance within the run's,
  /// worn volumes and ∫μ ds ≥ 0, heights and pressures finite, pressures ≥ 0, steps within total_steps()),
  /// else its first problem. run() checks every step's state; restore() checks a restored one.
  std::string state_problem() const;

  double distance() const { return s_; }
  int contact_solves() const { return solves_; }
  /// BEM iterations of those solves, in all.
  long contact_iterations() const { return iterations_; }
  /// Pin and disc surface heights (z_pin over the grid; z_disc per x column
  /// (averaged track) or over the track's nx × track_cells() strip (resolved)).
  const RealField& pin_surface() const { return pin_; }
  const std::vector<double>& disc_profile() const { return disc_; }
  /// The disc under the pin's window, one value per cell (the averaged profile
  /// repeated along y, or the part of the resolved strip under the pin).
  RealField disc_under_pin() const;
  /// Mean worn disc height per x column (z_disc averaged along the track).
  std::vector<double> disc_column_means() const;
  /// The same of the unworn disc (its initial roughness; zeros for a smooth disc).
  std::vector<double> disc_initial_column_means() const;
  const bem::NormalContact& contact() const { return contact_; }
  const PinOnDiscSetup& setup() const { return setup_; }
  const Grid2D& grid() const { return pin_.grid(); }

  /// State for integrators: z_pin (n²), z_disc (disc_profile().size()), then
  /// the worn volumes V_pin, V_disc and the friction integral ∫μ ds.
  std::size_t state_size() const { return pin_.size() + disc_.size() + 3; }
  std::vector<double> state() const;
  /// The state at s = 0 (unworn surfaces).
  std::vector<double> initial_state() const;
  void set_state(const double* y, double s);
  /// dy/ds at (s, y) for that state layout: one contact solve (none when
  /// (s, y) is the solution of the last implicit stage, whose rate is kept).
  /// Fills `sample`.
  void derivative(double s, const double* y, double* dyds, PinOnDiscSample& sample);

  /// Solves the implicit stage z = a + γ f(s, z) exactly, in one contact
  /// solve: wearing by γ p/p_crit over the stage acts as a compliance added to
  /// the half-space's, so z is the contact of the surfaces of `a` on K + A_γ
  /// (on a resolved track, the strip cells under the window wearing with
  /// the window's cells over them). The material of each cell is that of `layer`
  /// (1: the oxide) when given, else made consistent with z by re-solving
  /// (at most a few times). Writes z, f(s, z) and the sample at z.
  /// StageNotSolved if a contact solve does not converge (a shorter stage
  /// may: the state and the warm start are left as they were).
  void solve_stage(double s, const double* a, double gamma, double* z, double* rate, PinOnDiscSample& sample,
                   const std::vector<char>* layer = nullptr);
  /// The material the pin meets at each cell for a state at s (1: the oxide).
  std::vector<char> layer_cells(double s, const double* y) const;
  /// Worn depth of the disc minus h_layer per x column (the averaged track):
  /// the oxide is worn through where it is ≥ 0.
  void depth_below_layer(const double* y, double* out) const;

 private:
  struct StageCompliance;
  std::string state_problem(double s, double pin_wear, double disc_wear, double friction_integral,
                            std::span<const double> pin, std::span<const double> disc,
                            std::span<const double> pressure, double gap_shift) const;
  struct TrackStageCompliance;
  void solve_track_stage(double s, const double* a, double gamma, double* z, double* rate, PinOnDiscSample& sample,
                         const std::vector<char>* layer);
  // The end of either stage: the rate, volumes, sample and reusable state at z.
  void finish_stage(double s, const double* a, double gamma, double* z, double* rate, PinOnDiscSample& sample,
                    int iterations, std::vector<char>& consistent);
  // Resolved track: the window cells' disc rates (disc_rate_) onto the strip
  // cells they read at s, as dz/ds of the strip (the window's weights R).
  void spread_on_track(double s, double* strip_rate) const;
  void build_profile(double s);
  void classify(double s, const double* disc, std::vector<char>& layer) const;
  // S itself, not the two-level default: on the pin-on-disc's 32–128 grids the two-level saves no time,
  // and the tilted reading's wear history turns iterate-level differences into percent (docs/bem.md).
  bem::ContactResult solve_contact(double s, int max_iterations,
                                  bem::ContactMethod method = bem::ContactMethod::PreconditionedCG,
                                  double tolerance = 0.0);  // 0: setup().tolerance
  void rates(double s, PinOnDiscSample& out, std::vector<double>* pin_rate, std::vector<double>* disc_rate);
  double disc_height(const double* disc, std::size_t i, std::size_t j, double s) const;
  void measure_roughness(double s, PinOnDiscSample& out) const;
  void deposit_swept(double s0, double s1);
  int count_grooves(const double* disc) const;
  PinOnDiscSetup setup_;
  RealField pin_, profile_;
  std::vector<double> disc_;
  std::vector<double> pin0_, disc0_;  // the unworn surfaces of a rough run (empty when smooth)
  bem::NormalContact contact_;
  std::vector<double> pin_rate_, disc_rate_;
  std::vector<char> layer_;  // per cell: 1 where the pin meets the oxide
  double s_ = 0.0, pin_wear_ = 0.0, disc_wear_ = 0.0, friction_integral_ = 0.0;
  long steps_ = 0;
  double last_pin_volume_rate_ = 0.0, last_disc_volume_rate_ = 0.0;  // dV/ds of the last evaluate()
  int solves_ = 0;
  long iterations_ = 0;
  std::size_t track_ = 0;  // strip cells along y (resolved), else 0
  // The solution of the last implicit stage and its rate, for derivative().
  std::vector<double> stage_state_, stage_rate_;
  double stage_s_ = 0.0;
  bool stage_valid_ = false;
  PinOnDiscSample stage_sample_;
  std::unique_ptr<StageCompliance> compliance_;
  std::unique_ptr<TrackStageCompliance> track_compliance_;
};

}  // namespace wearscale::tribometer
