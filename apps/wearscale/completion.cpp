#include "completion.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace wearscale::app {

namespace {

struct Node {
  std::string path;  // " dem patch-test": the command words after the program
  const CLI::App* app;
};

// Every visible command below `app`, depth first, the program itself first.
void collect(const CLI::App& app, const std::string& path, std::vector<Node>& out) {
  out.push_back({path, &app});
  for (const auto* sub : app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
    collect(*sub, path + " " + sub->get_name(), out);
}

std::vector<const CLI::Option*> visible_options(const CLI::App& app) {
  return app.get_options([](const CLI::Option* o) { return !o->get_group().empty() && o->nonpositional(); });
}

bool takes_value(const CLI::Option& o) { return o.get_expected_max() != 0; }

std::vector<std::string> spellings(const CLI::Option& o) {
  std::vector<std::string> out;
  for (const auto& s : o.get_snames()) out.push_back("-" + s);
  for (const auto& l : o.get_lnames()) out.push_back("--" + l);
  return out;
}

std::vector<const CLI::Option*> positionals(const CLI::App& app) {
  return app.get_options([](const CLI::Option* o) { return o->get_positional() && !o->nonpositional(); });
}

// The values a positional argument takes when it names them (completion bash|zsh).
std::vector<std::string> positional_choices(const CLI::App& app) {
  std::vector<std::string> out;
  for (const auto* o : positionals(app))
    for (const auto& c : choices_of(*o)) out.push_back(c);
  return out;
}

// A positional argument that is a file (a case, a topography), not one of named values.
bool has_files(const CLI::App& app) {
  for (const auto* o : positionals(app))
    if (choices_of(*o).empty()) return true;
  return false;
}

// A word inside single quotes in either shell.
std::string single_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The case patterns that step from one command to a subcommand: "PATH:WORD") path="PATH WORD".
std::string transitions(const std::vector<Node>& nodes, const std::string& var) {
  std::string out;
  for (const auto& n : nodes)
    for (const auto* sub : n.app->get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
      out += fmt::format("      {}) {}={} ;;\n", single_quoted(n.path + ":" + sub->get_name()), var,
                         single_quoted(n.path + " " + sub->get_name()));
  return out;
}

}  // namespace

std::string help_of_every_command(const CLI::App& app) {
  std::vector<Node> nodes;
  collect(app, "", nodes);
  std::string out;
  for (const auto& n : nodes) {
    if (!n.path.empty()) out += fmt::format("\n{}{}:\n", app.get_name(), n.path);
    // CLI11 puts the prefix before the command's own name: the parent's path.
    const std::string parent = n.path.substr(0, n.path.rfind(' ') == std::string::npos ? 0 : n.path.rfind(' '));
    const std::string help = n.app->help(n.path.empty() ? "" : app.get_name() + parent, CLI::AppFormatMode::Normal);
    if (n.path.empty()) {
      out += help;
      continue;
    }
    // The description and usage indented under the command's heading (help2man
    // makes a section of it), then its positionals and options.
    bool head = true;
    for (std::size_t start = 0; start < help.size();) {
      const auto end = help.find('\n', start);
      const std::string line = help.substr(start, end == std::string::npos ? std::string::npos : end - start);
      head = head && !line.empty();
      out += (head ? "  " : "") + line + "\n";
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  return out;
}

std::vector<std::string> choices_of(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const auto open = type.find('{'), close = type.rfind('}');
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  std::vector<std::string> out;
  const std::string list = type.substr(open + 1, close - open - 1);
  for (std::size_t start = 0;;) {
    const auto comma = list.find(',', start);
    out.push_back(list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

CLI::Option* with_choices(CLI::Option* option, const std::vector<std::string>& choices) {
  const std::string description = fmt::format("{{{}}}", fmt::join(choices, ","));
  return option->check(CLI::Validator([](const std::string&) { return std::string(); }, description, "choices"));
}

std::string bash_completion(const CLI::App& app) {
  std::vector<Node> nodes;
  collect(app, "", nodes);
  const std::string name = app.get_name();
  std::string values, words;
  for (const auto& n : nodes) {
    std::vector<std::string> all, flags;
    for (const auto* sub : n.app->get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
      all.push_back(sub->get_name());
    for (const auto& c : positional_choices(*n.app)) all.push_back(c);
    for (const auto* o : visible_options(*n.app)) {
      const auto names = spellings(*o);
      flags.insert(flags.end(), names.begin(), names.end());
      if (!takes_value(*o)) continue;
      std::vector<std::string> patterns;
      for (const auto& s : names) patterns.push_back(single_quoted(n.path + ":" + s));
      const auto choices = choices_of(*o);
      values += fmt::format("      {}) {} return 0 ;;\n", fmt::join(patterns, "|"),
                            choices.empty() ? std::string("compopt -o default 2>/dev/null;")
                                            : fmt::format("COMPREPLY=($(compgen -W {} -- \"$cur\"));",
                                                          single_quoted(fmt::format("{}", fmt::join(choices, " ")))));
    }
    words += fmt::format("      {}) words={}; flags={}; files={} ;;\n", single_quoted(n.path),
                         single_quoted(fmt::format("{}", fmt::join(all, " "))),
                         single_quoted(fmt::format("{}", fmt::join(flags, " "))), has_files(*n.app) ? 1 : 0);
  }
  return fmt::format(R"(# bash completion for {0} (generated by `{0} completion bash`)
_{0}() {{
  local cur prev path="" words="" flags="" files=0 w i
  cur="${{COMP_WORDS[COMP_CWORD]}}"
  prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  for ((i = 1; i < COMP_CWORD; i++)); do
    w="${{COMP_WORDS[i]}}"
    case "$path:$w" in
{1}    esac
  done
  if ((COMP_CWORD > 1)); then
    case "$path:$prev" in
{2}    esac
  fi
  case "$path" in
{3}  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$flags" -- "$cur"))
  else
    COMPREPLY=($(compgen -W "$words" -- "$cur"))
    if [[ $files == 1 ]]; then compopt -o default 2>/dev/null; fi
  fi
  return 0
}}
complete -F _{0} {0}
)",
                     name, transitions(nodes, "path"), values, words);
}

std::string zsh_completion(const CLI::App& app) {
  std::vector<Node> nodes;
  collect(app, "", nodes);
  const std::string name = app.get_name();
  auto described = [](const std::string& word, const std::string& doc) {
    std::string escaped;
    for (char c : word) escaped += c == ':' ? std::string("\\:") : std::string(1, c);
    std::string line = doc.substr(0, doc.find('\n'));
    return single_quoted(escaped + ":" + line);
  };
  std::string values, lists;
  for (const auto& n : nodes) {
    std::vector<std::string> subs, opts;
    for (const auto* sub : n.app->get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
      subs.push_back(described(sub->get_name(), sub->get_description()));
    for (const auto& c : positional_choices(*n.app)) subs.push_back(described(c, ""));
    for (const auto* o : visible_options(*n.app)) {
      const auto names = spellings(*o);
      for (const auto& s : names) opts.push_back(described(s, o->get_description()));
      if (!takes_value(*o)) continue;
      std::vector<std::string> patterns;
      for (const auto& s : names) patterns.push_back(single_quoted(n.path + ":" + s));
      const auto choices = choices_of(*o);
      values += fmt::format("    {}) {}; return ;;\n", fmt::join(patterns, "|"),
                            choices.empty() ? std::string("_files")
                                            : fmt::format("compadd -- {}", fmt::join(choices, " ")));
    }
    lists += fmt::format("    {}) subs=({}); opts=({}); files={} ;;\n", single_quoted(n.path), fmt::join(subs, " "),
                         fmt::join(opts, " "), has_files(*n.app) ? 1 : 0);
  }
  return fmt::format(R"(#compdef {0}
# zsh completion for {0} (generated by `{0} completion zsh`)
_{0}() {{
  local cmdpath="" w i files=0
  local -a subs opts
  for ((i = 2; i < CURRENT; i++)); do
    w=${{words[i]}}
    case "$cmdpath:$w" in
{1}    esac
  done
  if ((CURRENT > 2)); then
    case "$cmdpath:${{words[CURRENT-1]}}" in
{2}    esac
  fi
  case "$cmdpath" in
{3}  esac
  if [[ $PREFIX == -* ]]; then
    _describe -t options option opts
  else
    ((${{#subs}})) && _describe -t commands command subs
    ((files)) && _files
  fi
}}
_{0} "$@"
)",
                     name, transitions(nodes, "cmdpath"), values, lists);
}

}  // namespace wearscale::app
