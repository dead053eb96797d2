#pragma once
//! \file commands.h
//! The CLI's commands (design.md §5), one file each. Each returns the process exit status and
//! throws the core's exceptions for bad input; main() turns those into one-line messages.

#include <string>
#include <vector>

namespace zomeify::cli {

using CommandArgs = std::vector<std::string>;

int cmd_inspect(const CommandArgs& args); // cmd_inspect.cpp
int cmd_parts(const CommandArgs& args);   // cmd_parts.cpp
int cmd_convert(const CommandArgs& args); // cmd_convert.cpp
int cmd_link(const CommandArgs& args);    // cmd_link.cpp
int cmd_run(const CommandArgs& args);     // cmd_run.cpp
int cmd_score(const CommandArgs& args);   // cmd_score.cpp
int cmd_steps(const CommandArgs& args);   // cmd_steps.cpp

struct Command
{
    const char* name;
    const char* usage;
    int (*run)(const CommandArgs&);
};

//! Every command, in the order `zomeify --help` lists them.
const std::vector<Command>& commands();

} // namespace zomeify::cli
