#pragma once
// The Examples section that ends every command's --help.
#include <CLI/CLI.hpp>

namespace wearscale::app {

/// Sets the footer of `app` and of every command below it to its examples:
/// command lines that run as they are from the source folder (cases/ beside
/// them), small enough to take a second; an example may read what an earlier
/// one of the same command wrote. tests/apps/test_help_examples_cli.cpp runs
/// each and checks the tables they write.
void add_examples(CLI::App& app);

}  // namespace wearscale::app
