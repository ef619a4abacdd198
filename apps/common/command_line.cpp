#include "command_line.hpp"
#include "option_helpers.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/output.hpp"
#include "asperity/surface.hpp"
#include "asperity/table_file.hpp"
#include "asperity/number_text.hpp"

namespace asperity::cli {
namespace {

// Carries an action's nonzero exit status out of CLI11's parse().
struct ActionExit {
  int status;
};

std::string selected_name(const CLI::App& app) {
  const auto selected = app.get_subcommands();
  return selected.empty() ? command_name(app) : command_name(*selected.front());
}

// CLI11 messages start with a capital ("The following argument..."); ours do not.
std::string sentence_case(std::string message) {
  if (message.size() > 1 && std::isupper(static_cast<unsigned char>(message[0])) &&
      (std::islower(static_cast<unsigned char>(message[1])) || message[1] == ' '))
    message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
  return message;
}

// Adds an option taking one value per use; `store` gets the value if it was given exactly once.
CLI::Option* add_once(CLI::App& command, const std::string& name, const std::string& description,
                      std::function<void(const std::string&)> store) {
  return command
      .add_option_function<std::vector<std::string>>(
          name,
          [name, store](const std::vector<std::string>& values) {
            if (values.size() != 1)
              throw CLI::ValidationError(name + " is given " + std::to_string(values.size()) + " times; give it once");
            store(values.front());
          },
          description)
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace

std::string command_name(const CLI::App& command) {
  std::string name = command.get_name();
  for (const CLI::App* parent = command.get_parent(); parent; parent = parent->get_parent())
    name = parent->get_name() + " " + name;
  return name;
}

void set_action(CLI::App& command, std::function<int()> action) {
  command.callback([action] {
    const int status = action();
    if (status != exit_success) throw ActionExit{status};
  });
}

void add_version_flag(CLI::App& app, std::function<int()> print, const std::string& description) {
  app.add_flag_callback("--version", [print] { throw ActionExit{print()}; }, description);
}

int run(CLI::App& app, int argc, const char* const* argv) {
  int status = exit_success;
  install_output_signal_cleanup();  // the first Ctrl-C unwinds (outputs removed), a second exits
  try {
    app.parse(argc, argv);
  } catch (const ActionExit& exit) {
    status = exit.status;
  } catch (const CLI::Success& success) {  // --help
    status = app.exit(success);
  } catch (const CLI::ParseError& error) {
    const std::string name = selected_name(app);
    std::string message = sentence_case(error.what());
    if (app.get_subcommands().empty() &&
        dynamic_cast<const CLI::RequiredError*>(&error) && message == "a subcommand is required") {
      std::string names;
      for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
        names += (names.empty() ? "" : ", ") + command->get_name();
      if (argc > 1 && argv[1][0] != '-') {
        message = "unknown command '" + quote_text(argv[1]) + "' (" + names + ")";
      } else {
        std::fputs(app.help().c_str(), stderr);
        message = "a command is required (" + names + ")";
      }
    }
    std::fprintf(stderr, "%s: %s\nRun '%s --help' for the usage.\n", name.c_str(), terminal_text(message).c_str(),
                 name.c_str());
    status = exit_failure;
  } catch (const Interrupted&) {
    std::fprintf(stderr, "%s: interrupted; no output was written\n", selected_name(app).c_str());
    status = exit_interrupted;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: out of memory (std::bad_alloc); no output was written\n", selected_name(app).c_str());
    status = exit_failure;
  } catch (const std::exception& error) {
    // messages quote files' bytes: nothing of them may reach the terminal as a control sequence
    std::fprintf(stderr, "%s: %s\n", selected_name(app).c_str(), terminal_text(error.what()).c_str());
    status = exit_failure;
  }
  // Output that could not be written is a failure, whatever the command did.
  // (std::cout writes through stdout's buffer: sync_with_stdio is left on.)
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int flush_errno = flushed ? 0 : errno;
  std::cout.flush();
  if (!flushed || std::ferror(stdout) || !std::cout) {
    std::fprintf(stderr, "%s: writing the output failed%s%s\n", selected_name(app).c_str(),
                 flush_errno ? ": " : "", flush_errno ? std::strerror(flush_errno) : "");
    status = exit_failure;
  }
  return status;
}

CLI::Option* add_text(CLI::App& command, const std::string& name, std::string& value, const std::string& description) {
  return add_once(command, name, description, [name, &value](const std::string& text) {
    if (text.empty()) throw CLI::ValidationError(name + ": an empty value");
    value = text;
  });
}

CLI::Option* add_number(CLI::App& command, const std::string& name, double& value, const std::string& description) {
  return add_once(command, name, description,
                  [name, &value](const std::string& text) { value = number_from_text(text, name); })
      ->type_name("X");
}

CLI::Option* add_numbers(CLI::App& command, const std::string& name, std::vector<double>& values,
                         const std::string& description) {
  return add_once(command, name, description,
                  [name, &values](const std::string& text) {
                    values.clear();
                    for (const std::string& part : split(text, ','))
                      values.push_back(number_from_text(part, name));
                  })
      ->type_name("X[,X...]");
}

CLI::Option* add_whole_number(CLI::App& command, const std::string& name, long long& value, long long lo,
                              long long hi, const std::string& description) {
  return add_once(command, name, description,
                  [name, &value, lo, hi](const std::string& text) {
                    if (!read_whole_number(text, lo, hi, value))
                      throw CLI::ValidationError(name + ": '" + quote_text(text) + "' is not a whole number from " +
                                                 std::to_string(lo) + " to " + std::to_string(hi));
                  })
      ->type_name("N");
}

double contact_modulus_option(double modulus, double e1, double nu1, double e2, double nu2) {
  try {
    return contact_modulus_given(modulus, e1, nu1, e2, nu2);
  } catch (const Error& error) {
    throw CLI::ValidationError(error.what());
  }
}

bool MaterialOptions::any_given() const {
  return given(modulus) || given(e1) || given(nu1) || given(e2) || given(nu2);
}

void add_material_options(CLI::App& command, MaterialOptions& material, const std::string& modulus_help,
                          const std::string& group) {
  add_number(command, "--modulus", material.modulus, modulus_help)->type_name("PA")->group(group);
  add_number(command, "--e1", material.e1, "Young's modulus of body 1 [Pa] (with --nu1 --e2 --nu2, instead of --modulus)")
      ->type_name("PA")->group(group);
  add_number(command, "--nu1", material.nu1, "Poisson's ratio of body 1")->group(group);
  add_number(command, "--e2", material.e2, "Young's modulus of body 2 [Pa]")->type_name("PA")->group(group);
  add_number(command, "--nu2", material.nu2, "Poisson's ratio of body 2")->group(group);
}

double number_from_text(const std::string& text, const std::string& what) {
  double value = 0;
  if (!read_double(text, value)) throw CLI::ValidationError(what + ": '" + quote_text(text) + "' is not a number");
  if (!std::isfinite(value)) throw CLI::ValidationError(what + ": '" + quote_text(text) + "' is not a finite number");
  return value;
}

CLI::Option* add_table_option(CLI::App& command, std::string& path) {
  return add_text(command, "--table", path,
                  "table file (default: $ASPERITY_TABLE if set, else the default table; "
                  "`asperity --version` shows which)")
      ->type_name("FILE");
}

Table open_table(const std::string& path) { return path.empty() ? Table::open_default() : Table::open(path); }

void warn(const CLI::App& command, const std::string& message) {
  std::fprintf(stderr, "%s: warning: %s\n", command_name(command).c_str(), terminal_text(message).c_str());
}

namespace {
bool quiet_asked = false;  // --quiet (add_quiet_option): one command runs in a process
}  // namespace

CLI::Option* add_quiet_option(CLI::App& command, bool* quiet_flag) {
  return command.add_flag_callback(
      "--quiet",
      [quiet_flag] {
        quiet_asked = true;
        if (quiet_flag) *quiet_flag = true;
      },
      "no information lines and no progress on standard error (warnings and errors are still written)");
}

bool quiet() { return quiet_asked; }

void note(const CLI::App& command, const std::string& message) {
  if (quiet_asked) return;
  std::fprintf(stderr, "%s: %s\n", command_name(command).c_str(), terminal_text(message).c_str());
}

int print_version() {
  std::printf("asperity %s\n", ASPERITY_VERSION_STRING);
  std::string path;
  try {
    path = Table::default_path();
  } catch (const std::exception& error) {
    std::fflush(stdout);
    std::fprintf(stderr, "asperity: no table found: %s\n", error.what());
    return exit_failure;
  }
  const char* from_environment = std::getenv("ASPERITY_TABLE");
  std::printf("table: %s%s\n", path.c_str(),
              from_environment && *from_environment ? " (from $ASPERITY_TABLE)" : " (the default table)");
  try {
    const Table table = Table::open(path);
    // Opening checked the file's schema and schema_version attributes against these.
    std::printf("schema: %s, version %d\n", table_schema_name(), table_schema_version());
    std::printf("generator: %s\n", table.data().generator.c_str());
    std::printf("generator options: %s\n", table.data().generator_options.c_str());
    for (const CurveSet& set : table.data().sets) {
      if (set.distribution == Distribution::gaussian)
        std::printf("curves: %s %s\n", to_string(set.distribution), to_string(set.side));
      else
        std::printf("curves: %s %s, shapes %s to %s%s\n", to_string(set.distribution), to_string(set.side),
                    format_double(set.shape_min).c_str(), format_double(set.shape_max).c_str(),
                    table.data().exact_shapes ? " (a scene table: its own shapes only)" : "");
    }
  } catch (const std::exception& error) {
    std::fflush(stdout);
    std::fprintf(stderr, "asperity: the table cannot be used: %s\n", error.what());
    return exit_failure;
  }
  return exit_success;
}

void usage(const std::string& message) { throw CLI::ValidationError(message); }

bool given(double value) { return !std::isnan(value); }

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.push_back("");  // getline drops a last empty part
  return parts;
}

std::vector<double> positive_numbers(const std::string& text, const std::string& name) {
  std::vector<double> values;
  for (const std::string& part : split(text, ',')) {
    const double value = number_from_text(part, name);
    if (!(value > 0)) usage(name + ": '" + quote_text(part) + "' is not a positive number");
    values.push_back(value);
  }
  return values;
}

std::string approximately(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace asperity::cli
