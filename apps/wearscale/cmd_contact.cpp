// wearscale contact [CASE.toml] [--surface F] [--pressure P | --load F | --interference D]
//                   [--e-star E] [--poisson NU] [--friction coulomb|tresca [--mu M | --shear-strength S]
//                   [--tangential-pressure Q] [--tensile-strength SM]] [--set KEY=VALUE]... [--out DIR] [--json]
// The contact study (studies/src/contact_study.cpp); its flags are the aliases its schema declares.
#include "study_command.hpp"

namespace wearscale::app {

Command add_contact(CLI::App& app) {
  return add_study_command(
      app, "contact", "contact",
      "Normal or frictional contact of a rigid surface (file, generated rough surface, sphere) on an elastic flat",
      "contact.rough.seed=3");
}

}  // namespace wearscale::app
