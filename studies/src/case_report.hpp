#pragma once
// What `wearscale check` adds to the runner's checks (runner.hpp: inspect_case):
// the keys a study reads at the start of its run, and the defaults a run applies.
// Private to the studies.
#include "wearscale/io/config.hpp"
#include "wearscale/studies/runner.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

/// Runs `study` on `cfg` up to its check of the whole case
/// (Config::reject_unknown_keys, which then throws CaseChecked), with a
/// scratch folder for what the run opens before it; nothing of the work runs.
/// Throws the case's errors as the run would.
void check_keys_in_run(Study& study, const Config& cfg);

/// The resolved case of `cfg` with the defaults its getters applied, and the
/// keys of the study's schema still absent with their defaults in words.
void describe_defaults(CaseReport& report, const Study& study, const Config& cfg);

}  // namespace wearscale::studies
