// wearscale completion bash|zsh: prints the shell's completion script, made
// from the parser itself (cmake --install also installs both, docs/cli.md).
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "completion.hpp"

namespace wearscale::app {

Command add_completion(CLI::App& app) {
  auto* cmd = app.add_subcommand("completion", "Print a bash or zsh completion script for wearscale");
  auto shell = std::make_shared<std::string>();
  cmd->add_option("shell", *shell, "Shell: bash or zsh")->required()->check(CLI::IsMember({"bash", "zsh"}));
  const CLI::App* root = &app;
  return [root, shell]() {
    std::cout << (*shell == "bash" ? bash_completion(*root) : zsh_completion(*root));
    return 0;
  };
}

}  // namespace wearscale::app
