#include "common/usage_error.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace aloft::host {
namespace {

// The subcommand the parse had reached (the program itself when none).
const CLI::App* reached_command(const CLI::App& app) {
  const CLI::App* command = &app;
  for (;;) {
    const std::vector<CLI::App*> parsed = command->get_subcommands();
    if (parsed.empty()) return command;
    command = parsed.front();
  }
}

std::string command_path(const CLI::App& app, const CLI::App* command) {
  return command == &app ? app.get_name() : app.get_name() + " " + command->get_name();
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::vector<std::string> option_names(const CLI::App* command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command->get_options()) {
    if (o->get_lnames().empty()) continue;  // positional
    names.push_back("--" + o->get_lnames().front());
  }
  return names;
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// " (did you mean X?)" when one choice is within two edits of the word.
std::string suggestion(const std::string& word, const std::vector<std::string>& choices) {
  const std::string bare = word.substr(0, word.find('='));
  for (const std::string& c : choices) {
    if (edit_distance(bare, c) <= 2) return " (did you mean " + c + "?)";
  }
  return "";
}

// The first word the parse left unused, looking in the reached command, then the program.
std::string first_unused_word(const CLI::App& app, const CLI::App* command) {
  for (const CLI::App* c : {command, &app}) {
    const std::vector<std::string> left = c->remaining();
    if (!left.empty()) return left.front();
  }
  return "";
}

std::string unknown_command_line(const CLI::App& app, const std::string& word) {
  const std::vector<std::string> commands = command_names(app);
  return app.get_name() + ": unknown command " + word + suggestion(word, commands) +
         "; commands: " + join(commands) + "; see " + app.get_name() + " --help";
}

}  // namespace

std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  const std::string word = argv[1];
  for (const std::string& c : command_names(app)) {
    if (c == word) return std::nullopt;
  }
  return unknown_command_line(app, word);
}

std::string usage_error_line(const CLI::App& app, const CLI::ParseError& error) {
  const CLI::App* command = reached_command(app);
  const std::string who = command_path(app, command);
  const std::string help = "; see " + who + " --help";
  const std::string unused = first_unused_word(app, command);
  if (!unused.empty() && unused[0] == '-' && unused.size() > 1) {
    const std::vector<std::string> options = option_names(command);
    return who + ": unknown option " + unused + suggestion(unused, options) + "; options: " + join(options) +
           help;
  }
  if (!unused.empty() && command == &app) return unknown_command_line(app, unused);
  if (!unused.empty()) {
    return who + ": unexpected argument " + unused + "; options: " + join(option_names(command)) + help;
  }
  if (command == &app && !command_names(app).empty()) {
    return who + ": no command given; commands: " + join(command_names(app)) + help;
  }
  return who + ": " + error.what() + help;
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s\n", usage_error_line(app, e).c_str());
    return 2;
  }
  return std::nullopt;
}

}  // namespace aloft::host
