// wearscale strength-table [CASE.toml] --backend lammps --material NAME --pressures 0,10,25
//                          [--preset smoke|thesis] [--lmp PATH] [--ranks N] [--table NAME.csv|.h5]
//                          [--set KEY=VALUE]... [--out DIR] [--resume DIR] [--json]
// The strength-table study (studies/src/strength_table_study.cpp); its flags
// are the aliases its schema declares. --pressures takes plain numbers in GPa;
// case keys (md.pressures, --set) take SI numbers or unit strings ("10 GPa").
#include "study_command.hpp"

namespace wearscale::app {

Command add_strength_table(CLI::App& app) {
  return add_study_command(
      app, "strength-table", "strength-table",
      "Shear strengths sigma_max(p), sigma_dyn(p) of Si, SiO2 or a material the case defines with its interatomic "
      "model ([materials.define.NAME.interatomic]) from the MD shear test of §9.3.1 (LAMMPS), after an elastic check "
      "of the sample, written as a strength table into the output folder. Identical inputs are read from the cache "
      "($WEARSCALE_CACHE/lammps, else ~/.cache/wearscale/lammps) instead of running lmp again.",
      "md.shear_velocity=\"10 m/s\"");
}

}  // namespace wearscale::app
