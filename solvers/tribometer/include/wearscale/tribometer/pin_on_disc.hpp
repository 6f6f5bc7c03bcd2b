#pragma once
// The pin-on-disc wear model of §9.3.2: a spherical pin pressed on a disc
// whose oxide layer of thickness h_layer covers the substrate. At each step
// the contact is solved with the BEM; each contacting cell slides with
// p_T = μ0 p_N of its interface (9.12) and wears by dh = (p_N/p_crit) v dt
// (9.23), shared ½/½ between pin and disc on a like-on-like interface
// (9.24)–(9.25) and all on the disc otherwise (9.26)–(9.27). The disc wear is
// scaled by L/L_path and averaged along the sliding direction y.
//
// Geometry: heights z along the pin's axis; the pin's surface is
// z_pin = R − √(R² − r²) (+ its wear), the disc's z_disc = −(its wear) (+ a
// rotating tilt); the BEM sees the rigid profile h = z_disc − z_pin on a flat
// of contact modulus E*.
#include <cstddef>
#include <functional>
#include <vector>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/core/checkpoint.hpp"
#include "wearscale/materials/junction_model.hpp"

namespace wearscale::tribometer {

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
  double nonplanar_period = 0.05;   ///< its rotation period in sliding distance [m]
  double tolerance = 1e-10;         ///< BEM orthogonality error
  bem::Boundary boundary = bem::Boundary::Periodic;  ///< of the BEM cell: periodic images, or an isolated pin (free)
  materials::InterfaceLaw on_layer;      ///< pin on the oxide layer (e.g. SiO2/SiO2)
  materials::InterfaceLaw on_substrate;  ///< pin on the substrate (e.g. SiO2/Si)
  bool like_on_like = true;         ///< pin and layer of one material: wear shared ½/½ on the layer

  /// InputError naming the parameter for any value out of range.
  void validate() const;
  /// InputError if an interface law is missing or incomplete.
  void validate_laws() const;
};

/// The state after a step, and what happened during it.
struct PinOnDiscSample {
  double distance = 0.0;           ///< s [m]
  double friction = 0.0;           ///< μ = Σ p_T ΔA / F_N
  double pin_wear = 0.0;           ///< worn volume of the pin so far [m³]
  double disc_wear = 0.0;          ///< worn volume of the disc (whole track) so far [m³]
  double contact_fraction = 0.0;   ///< A/A0 of the BEM contact (cells with p > 0)
  double layer_contact = 0.0;      ///< share of the contact cells on the layer
  double substrate_contact = 0.0;  ///< share on the substrate
  double max_pressure = 0.0;       ///< [Pa]
  int iterations = 0;              ///< BEM iterations of this step's solve
};

class PinOnDisc {
 public:
  explicit PinOnDisc(const PinOnDiscSetup& setup);

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
  /// step count and the contact solver's warm start), bit for bit.
  void save(CheckpointState& state) const;
  /// Restores a saved state; InputError if it does not fit this setup's grid.
  void restore(const CheckpointState& state);

  double distance() const { return s_; }
  int contact_solves() const { return solves_; }
  /// Pin and disc surface heights (z_pin over the grid; z_disc per x column, invariant in y).
  const RealField& pin_surface() const { return pin_; }
  const std::vector<double>& disc_profile() const { return disc_; }
  const bem::NormalContact& contact() const { return contact_; }
  const PinOnDiscSetup& setup() const { return setup_; }
  const Grid2D& grid() const { return pin_.grid(); }

  /// State for integrators: z_pin (n²), z_disc (n), then the worn volumes V_pin, V_disc.
  std::size_t state_size() const { return pin_.size() + disc_.size() + 2; }
  std::vector<double> state() const;
  void set_state(const double* y, double s);
  /// dy/ds at (s, y) for that state layout: one contact solve. Fills `sample`.
  void derivative(double s, const double* y, double* dyds, PinOnDiscSample& sample);

 private:
  void build_profile(double s);
  PinOnDiscSetup setup_;
  RealField pin_, profile_;
  std::vector<double> disc_;
  bem::NormalContact contact_;
  std::vector<double> pin_rate_, disc_rate_;
  double s_ = 0.0, pin_wear_ = 0.0, disc_wear_ = 0.0;
  long steps_ = 0;
  double last_pin_volume_rate_ = 0.0, last_disc_volume_rate_ = 0.0;  // dV/ds of the last evaluate()
  int solves_ = 0;
};

}  // namespace wearscale::tribometer
