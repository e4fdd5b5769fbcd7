// Where plugins (materials/registry/plugin.h) come from on the command line: `--plugin LIB` on a
// command, and the SCATTERLAB_PLUGIN_PATH environment variable.
#pragma once

#include <CLI/CLI.hpp>

namespace scatterlab {

// Adds `--plugin LIB` (repeatable) to `command`: each library is loaded (app/plugin_loader.h)
// while the command line is parsed, so its models exist before the command reads any
// material. A bad plugin throws InputError or MaterialError out of the parse (exit 2).
void addPluginOption(CLI::App& command);

// Loads every plugin SCATTERLAB_PLUGIN_PATH lists: library files, or directories whose *.so
// files are all loaded (in name order), separated by ':'. Empty entries are skipped. Called once
// at start-up, before the command line is parsed.
void loadPluginsFromEnvironment();

}  // namespace scatterlab
