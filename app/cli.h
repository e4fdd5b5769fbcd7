// The `scatterlab` command line: one executable, one subcommand per task (docs/design.md, "The command
// line").
#pragma once

namespace scatterlab {

// Parses argv, runs the subcommand, returns the process exit code (app/exit_code.h):
// 0 success, 1 a check failed, 2 bad input (one message on stderr naming the key or option,
// the value and what is allowed), 3 an internal error. Never throws.
int runCli(int argc, char** argv);

}  // namespace scatterlab
