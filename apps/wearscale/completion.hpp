#pragma once
// Shell completion scripts and the full help generated from the parser's
// tree of commands, so that a new command, flag or choice completes and is
// documented (man page) without editing a script.
#include <string>

#include <CLI/CLI.hpp>

namespace wearscale::app {

/// A bash completion script for `app` (complete -F, file names where a value is a path).
std::string bash_completion(const CLI::App& app);
/// A zsh completion script (#compdef) for `app`, with descriptions.
std::string zsh_completion(const CLI::App& app);
/// The help of `app` and of every command below it, depth first (--help-all, for help2man).
std::string help_of_every_command(const CLI::App& app);
/// The allowed values of an option, "{a,b,c}" in its type name (CLI::IsMember
/// or with_choices), or none.
std::vector<std::string> choices_of(const CLI::Option& option);
/// Declares the allowed values of `option` for help and completion, without
/// checking them (the study checks its keys and names the key when refusing).
CLI::Option* with_choices(CLI::Option* option, const std::vector<std::string>& choices);

}  // namespace wearscale::app
