#pragma once
// A [contact] case, read once into a plain struct (ContactCase) that both
// strategies of the contact study run: serial (contact_study.cpp) and in
// slabs over MPI ranks (contact_slab.cpp); the one memory model of both; and
// the files written from the solved whole fields. Private to the studies.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/studies/runner_keys.hpp"

namespace wearscale::studies {

/// [contact.rough] on the contact's grid: the spectrum and the roughness it is scaled to.
struct RoughCase {
  bem::RoughSurfaceSpec spec;
  bem::RoughnessMeasure measure = bem::RoughnessMeasure::HPrimeRms;
  double target = 1.0;
};

/// A frictionless contact: modulus, boundary, load, tolerance, micro-contacts.
struct NormalCase {
  double e_star = 1.0;
  bem::Boundary boundary = bem::Boundary::Periodic;
  bem::ContactOptions options;
  bem::Connectivity connectivity = bem::Connectivity::Four;
  double p0 = 0.0, delta = 0.0;
  bool imposes_interference = false;
  /// The solve the case asks for (imposed mean pressure or interference).
  bem::ContactResult solve(bem::NormalContact& contact) const;
};

/// One headline figure: name, value, unit, what it is.
using FigureReport = std::function<void(const std::string& name, double value, const std::string& unit,
                                        const std::string& what)>;

/// The figures of a normal contact besides the solver's: A, the micro-contacts, h'_RMS.
struct NormalFigures {
  double contact_area = 0.0;
  std::size_t clusters = 0;
  double hprime_rms = 0.0;
};
/// Every headline figure of a frictionless contact, in the order the study writes them
/// (the serial study and the slabs' alike).
void report_normal_figures(const NormalCase& n, const bem::ContactResult& r, const NormalFigures& f,
                           const FigureReport& report);

/// The micro-contacts' table, as the /clusters group of contact.h5 and as
/// clusters.csv: area and centroid of each, largest first, and with `checks`
/// (crack initiation at σ_m, one a micro-contact) the edges' extremes and
/// whether (4.25) holds. The serial study and the slabs' write the same table.
class ClusterTable {
 public:
  explicit ClusterTable(const std::vector<bem::ContactCluster>& clusters,
                        const std::vector<bem::EdgeCrackCheck>* checks = nullptr, double sigma_m = 0.0);
  /// The micro-contacts meeting (4.25) at both edges.
  double crack_sites() const { return sites_; }
  void write(H5Writer& h5) const;
  /// clusters.csv (and its .json) in `folder`; its path.
  std::filesystem::path write_csv(const std::filesystem::path& folder) const;

 private:
  std::vector<std::string> names_, units_;
  std::vector<std::vector<double>> columns_;
  std::vector<std::string> comments_;
  double sites_ = 0.0;
};

/// The crack sites' headline figure, after the frictional ones.
void report_crack_sites(const ClusterTable& table, const FigureReport& report);

/// contact.h5 (+ .xdmf) and clusters.csv from the whole fields, and the
/// headline figures reported to `context`.
void write_normal_study(const Config& config, const NormalCase& n, const RealField& h, const RealField& p,
                        const RealField& gap, const RealField& u, const bem::ContactResult& r,
                        coupling::RunContext& context);

/// A frictional contact (friction = "coulomb" or "tresca"): E, ν, the law,
/// the mean tractions, tolerance, micro-contacts, σ_m, stress depths.
struct FrictionalCase {
  double young = 1.0, poisson = 0.0;
  bem::FrictionLaw law = bem::FrictionLaw::coulomb(0.0);
  bem::MeanTraction load;
  std::string tangential_key = "tangential_pressure";  ///< the key a gross sliding is refused under
  bem::FrictionalOptions options;
  bem::Connectivity connectivity = bem::Connectivity::Four;
  bool crack = false;
  double sigma_m = 0.0;
  std::vector<double> depths;
  /// The sliding direction (4.25) is checked along: the tangential load's (+x when there is none).
  double crack_direction_x() const { return load.x != 0.0 ? load.x : 1.0; }
  /// The solve the case asks for; gross sliding refused naming the tangential key.
  bem::FrictionalResult solve(bem::FrictionalContact& contact, const Config& contact_section) const;
};

/// The figures of a frictional contact besides the solver's: the micro-contacts and the stresses' maxima.
struct FrictionalFigures {
  std::size_t clusters = 0;
  double max_sigma_I = 0.0;
  double max_tau = 0.0, max_tau_depth = 0.0;  // over the stress depths, if any
};
/// Every headline figure of a frictional contact but the crack sites, in the
/// order the study writes them (the serial study and the slabs' alike).
void report_frictional_figures(const FrictionalCase& f, const bem::FrictionalResult& r, const FrictionalFigures& figures,
                               const FigureReport& report);

/// The whole fields of a solved frictional contact.
struct FrictionalFields {
  const RealField& height;
  const bem::VectorField& traction;
  const bem::VectorField& displacement;
  const RealField& gap;
  const bem::VectorField& slip;
  const RealField& stick_slip;
};

/// contact.h5 (+ .xdmf, the surface and subsurface stresses, (4.25) per
/// micro-contact) and clusters.csv from the whole fields, and the headline
/// figures reported to `context`.
void write_frictional_study(const Config& config, const FrictionalCase& f, const FrictionalFields& fields,
                            const bem::FrictionalResult& r, coupling::RunContext& context);

/// The keys of [contact] as given, where a value is not yet what the case
/// holds: which surface, a modulus before ν converts it, a load before the
/// grid's area divides it, the one roughness target given.
struct ContactInputs {
  std::string friction = "none";  ///< "none" | "coulomb" | "tresca"
  std::filesystem::path surface;  ///< a height file (empty: none)
  bem::TopographyOptions read;    ///< how it is read (dataset, missing; size when given)
  long grid = 0;                  ///< points per side of a generated surface
  std::optional<double> size;     ///< side of the cell (a file's: overrides its own)
  std::optional<double> hprime_rms, h_rms, sa;  ///< [contact.rough]: exactly one
  std::optional<double> e_star;  ///< E* (1.12); with friction exactly one of e_star, young
  double young = 0.0;            ///< read when e_star is not given
  double poisson = 0.0;
  double friction_coefficient = 0.0, shear_strength = 0.0;
  std::optional<double> mean_pressure, normal_load, interference, tangential_load;
  double tangential_pressure = 0.0;
  std::optional<double> tensile_strength;
};

/// A [contact] case, every key read and checked, before any work.
struct ContactCase {
  int ranks = 1;  ///< the ranks it is read for (the slabs refuse a file of fewer rows)
  ContactInputs given;
  Grid2D grid;
  NormalCase normal;                       ///< frictionless (friction = "none"); its boundary either way
  std::optional<FrictionalCase> friction;  ///< friction = "coulomb" | "tresca"
  RealField measured;  ///< contact.surface's heights, whole (empty: none)
  std::optional<RoughCase> rough;
  double sphere_radius = 0.0;  ///< 0: no sphere
  bool measured_plans = true;  ///< slabs: FFTW MEASURE plans ([run] fft_planning, and from 512²)
  std::size_t gather_limit = RunKeys{}.gather_limit;  ///< slabs: [run] gather_limit, larger grids written in place
};

/// Every key of [contact], declared once (io/key_table.hpp): read() fills a
/// ContactCase whose `ranks` is set, in the order the refusals come; its
/// schema() is the study's. The frictionless and frictional keys are read
/// by the friction key's value, the others' defaults by it too.
const KeyTable<ContactCase>& contact_keys();

/// Reads and checks [contact] for a run on `ranks` ranks (the slabs refuse a
/// file of fewer rows than ranks), and the memory the run needs on this rank
/// (contact_memory); ends with config.reject_unknown_keys(). Under mpirun
/// every rank reads it alike, so a refusal is every rank's.
ContactCase read_contact_case(const Config& config, int ranks);

/// The peak memory of a contact run on this rank, in bytes: serial (ranks =
/// 1) the whole fields and outputs; in slabs a rank's share of the solve and,
/// on rank 0 up to the gather limit, the gathered fields.
double contact_memory(const ContactCase& c, int ranks, bool root);

}  // namespace wearscale::studies
