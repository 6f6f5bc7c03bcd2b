#pragma once
// A command line CLI11 cannot parse, said in one line: the command, what is
// wrong and, for a mistyped option, the closest one it takes ("did you mean
// --pressure?"), instead of CLI11's message and the whole help.
#include <string>

#include <CLI/CLI.hpp>

namespace wearscale::app {

std::string parse_error_line(const CLI::App& app, int argc, char** argv, const CLI::ParseError& error);

}  // namespace wearscale::app
