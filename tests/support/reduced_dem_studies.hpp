#pragma once
// The DEM studies a user runs on their own, reduced to a second or two each:
// `wearscale dem <args>` writes summary.json, and <dump> if not empty. The
// reliability tests (stop, resume, outputs) and the MPI engine tests run them.
#include <ostream>
#include <string>
#include <vector>

namespace wearscale::test_support {

struct ReducedDemStudy {
  std::string label, args, name, dump;
  friend void PrintTo(const ReducedDemStudy& s, std::ostream* os) { *os << s.label; }
};

inline const std::vector<ReducedDemStudy> reduced_dem_studies = {
    {"junction", "dem junction --material SiO2 --D 20e-9 --d0 '6 nm' --slide '6 nm' --velocity 10", "junction",
     "junction.dump"},
    {"rough_shear",
     "dem rough-shear --material SiO2 --d0 '6 nm' --length '60 nm' --velocity 50 --slide '12 nm' --roughness 0.04 "
     "--set dem.rough_shear.height='60 nm'",
     "rough_shear", "rough_shear.dump"},
    {"trapped_particles",
     "dem trapped-particles --material SiO2 --n 2 --D 20e-9 --d0 '6 nm' --velocity 100 --slide '12 nm'",
     "trapped_particles", "trapped_particles.dump"},
    {"patch_test", "dem patch-test --lattice hcp --nu 0.1 --length 8 --set dem.patch_test.strain_rate=1e-4",
     "patch_test", ""},
    {"oxide_asperity",
     "dem oxide-asperity --d0 '6 nm' --slide '12 nm' --set \"dem.oxide_asperity.box=['150 nm','150 nm','95 nm']\" "
     "--set dem.oxide_asperity.velocity=50 --set \"dem.oxide_asperity.settle_distance='1 nm'\"",
     "oxide_asperity", "oxide_asperity.dump"},
};

}  // namespace wearscale::test_support
