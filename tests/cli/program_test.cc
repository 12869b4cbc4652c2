// The split of the commands between slamsweep and its helper programs (cli/program.h): the core
// lists every helper command with the helper's own description, and every command of a helper is
// reachable from the core.
#include "cli/program.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

namespace slamsweep::cli {
namespace {

/// "name" or "parent name" -> description, for the commands one registration list adds.
std::map<std::string, std::string> CommandsOf(RegisterCommands register_commands) {
  CLI::App app;
  std::ostringstream out;
  std::ostringstream err;
  int exit_code = 0;
  const Streams streams{out, err};  // CommandLine keeps a reference: a temporary here would dangle
  CommandLine line(app, streams, exit_code);
  register_commands(line);
  std::map<std::string, std::string> commands;
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    if (command->get_name() == "eval") {
      for (CLI::App* child : command->get_subcommands([](CLI::App*) { return true; })) {
        commands["eval " + child->get_name()] = child->get_description();
      }
    } else {
      commands[command->get_name()] = command->get_description();
    }
  }
  return commands;
}

std::string FullName(const HelperCommand& command) {
  return command.parent.empty() ? std::string(command.name)
                                : std::string(command.parent) + " " + std::string(command.name);
}

TEST(ProgramTest, TheCoreListsEachHelperCommandAsItsHelperDescribesIt) {
  const std::map<std::string, RegisterCommands> helpers = {{"slamsweep-maps", RegisterMapsCommands},
                                                           {"slamsweep-sweep", RegisterSweepCommands}};
  const std::map<std::string, std::string> core = CommandsOf(RegisterCoreCommands);
  std::map<std::string, std::size_t> listed;
  for (const HelperCommand& command : HelperCommands()) {
    SCOPED_TRACE(FullName(command));
    ASSERT_EQ(helpers.count(std::string(command.program)), 1u) << "unknown helper " << command.program;
    const std::map<std::string, std::string> own = CommandsOf(helpers.at(std::string(command.program)));
    ASSERT_EQ(own.count(FullName(command)), 1u) << command.program << " does not run it";
    EXPECT_EQ(own.at(FullName(command)), command.description);
    EXPECT_EQ(core.count(FullName(command)), 0u) << "the core runs it itself";
    ++listed[std::string(command.program)];
  }
  for (const auto& [program, register_commands] : helpers) {
    EXPECT_EQ(listed[program], CommandsOf(register_commands).size())
        << program << " has a command the core cannot reach";
  }
}

TEST(ProgramTest, NoCommandIsInTwoPrograms) {
  const std::map<std::string, std::string> core = CommandsOf(RegisterCoreCommands);
  const std::map<std::string, std::string> maps = CommandsOf(RegisterMapsCommands);
  const std::map<std::string, std::string> sweep = CommandsOf(RegisterSweepCommands);
  for (const auto& [name, description] : core) {
    EXPECT_EQ(maps.count(name) + sweep.count(name), 0u) << name;
  }
  for (const auto& [name, description] : maps) EXPECT_EQ(sweep.count(name), 0u) << name;
}

}  // namespace
}  // namespace slamsweep::cli
