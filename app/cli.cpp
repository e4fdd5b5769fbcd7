#include "app/cli.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/check_command.h"
#include "app/eval_command.h"
#include "app/exit_code.h"
#include "app/explore_command.h"
#include "app/fit_command.h"
#include "app/generate_table_command.h"
#include "app/interrupt_cleanup.h"
#include "app/lab/lab_command.h"
#include "app/models_command.h"
#include "app/plugin_option.h"
#include "app/profile_command.h"
#include "app/progress.h"
#include "app/render_command.h"
#include "app/shape_factor_command.h"
#include "app/subcommand_names.h"
#include "app/sweep/sweep_command.h"
#include "app/synth_command.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/core/quoted.h"
#include "materials/core/temporary_files.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

int reportError(const std::string& message, ExitCode code) {
  std::cerr << "scatterlab: error: " << shortenLongValues(message) << "\n";
  return static_cast<int>(code);
}

// CLI11's own exit codes (100 and up) are all bad input to scatterlab; help and version are
// successes.
int exitCodeOfParseError(const CLI::App& app, const CLI::ParseError& error) {
  const int cliCode = app.exit(error);
  return static_cast<int>(cliCode == 0 ? ExitCode::Success : ExitCode::BadInput);
}

// Off a terminal stdout is fully buffered anyway; a buffer that holds any ordinary output
// whole makes the write that fails (a full disk) happen in checkStandardOutput's flush, where
// its reason (errno) can still be read.
void bufferStandardOutput() {
  static char buffer[1 << 20];
  if (isatty(STDOUT_FILENO) != 1) std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
}

// Everything printed reached stdout: a full disk or a closed pipe is an error, not a success.
int checkStandardOutput(int code) {
  errno = 0;
  std::cout.flush();
  int error = errno;
  if (std::fflush(stdout) != 0 && error == 0) error = errno;
  if (!std::ferror(stdout) && std::cout.good()) return code;
  const std::string reason = error ? std::strerror(error) : "write failed";
  return reportError(
      "standard output: cannot write the results (" + reason + "); allowed: a writable standard output",
      ExitCode::BadInput);
}

int runParsed(CLI::App& app, int argc, char** argv, const std::function<int()>& dispatch) {
  // Nothing may escape: every failure is one message and an exit code (exit_code.h).
  try {
    app.parse(argc, argv);
    return dispatch();
  } catch (const CLI::ParseError& error) {
    return exitCodeOfParseError(app, error);
  } catch (const MaterialError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const InputError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const InputFileError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const JsonTextError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const std::bad_alloc&) {
    return reportError("out of memory; allowed: a smaller --res, --samples, --grid or --paths",
                       ExitCode::BadInput);
  } catch (const std::exception& error) {
    return reportError(std::string("internal error: ") + error.what(), ExitCode::InternalError);
  } catch (...) {
    return reportError("internal error: unknown exception", ExitCode::InternalError);
  }
}

// CLI11 reads an argument written [a,b] as a list of values split at its commas, which would
// turn a JSON array of materials into fragments. A leading space keeps it one argument (JSON and
// every option's parser ignore it), so the array reaches the material reader and is refused
// there with a message.
std::vector<std::string> protectBracketedArguments(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  for (size_t i = 1; i < args.size(); ++i)
    if (args[i].size() >= 2 && args[i].front() == '[' && args[i].back() == ']') args[i].insert(0, " ");
  return args;
}

}  // namespace

int runCli(int argc, char** argv) {
  // First, before any thread exists: an interruption removes every temporary file.
  installInterruptCleanup();
  bufferStandardOutput();
  CLI::App app{
      "scatterlab: a laboratory for reflectance models. Checks a material's sampling "
      "statistically; every material is a JSON object, see `scatterlab models`.",
      "scatterlab"};
  app.set_version_flag("--version", std::string("scatterlab ") + SCATTERLAB_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // --quiet after the subcommand too
  bool quiet = false;
  app.add_flag("--quiet", quiet, "No progress lines or work estimates on stderr (errors still go there)");
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return "scatterlab: error: " + shortenLongValues(error.what()) + "\n";
  });
  ModelsCommandOptions modelsOptions;
  CheckCommandOptions checkOptions;
  const CLI::App* models = addModelsCommand(app, modelsOptions);
  const CLI::App* check = addCheckCommand(app, checkOptions);
  EvalCommandOptions evalOptions;
  const CLI::App* evalCommand = addEvalCommand(app, evalOptions);
  SynthCommandOptions synthOptions;
  const CLI::App* synth = addSynthCommand(app, synthOptions);
  ProfileCommandOptions profileOptions;
  const CLI::App* profile = addProfileCommand(app, profileOptions);
  FitCommandOptions fitOptions;
  const CLI::App* fit = addFitCommand(app, fitOptions);
  ShapeFactorCommandOptions shapeFactorOptions;
  const CLI::App* shapeFactor = addShapeFactorCommand(app, shapeFactorOptions);
  RenderCommandOptions renderOptions;
  const CLI::App* renderCommand = addRenderCommand(app, renderOptions);
  LabCommandOptions labOptions;
  const CLI::App* lab = addLabCommand(app, labOptions);
  ExploreCommandOptions exploreOptions;
  const CLI::App* explore = addExploreCommand(app, exploreOptions);
  SweepCommandOptions sweepOptions;
  const CLI::App* sweep = addSweepCommand(app, sweepOptions);
  MergeCommandOptions mergeOptions;
  const CLI::App* merge = addMergeCommand(app, mergeOptions);

  GenerateTableOptions generateTableOptions;  // a hidden developer command
  const CLI::App* generateTable = addGenerateTableCommand(app, generateTableOptions);

  // `scatterlab help [SUBCOMMAND]`, and a word that is no subcommand ("chek").
  if (const auto handled = handleSubcommandWord(app, argc, argv)) return checkStandardOutput(*handled);

  std::vector<std::string> arguments = protectBracketedArguments(argc, argv);
  std::vector<char*> protectedArgv;
  for (std::string& argument : arguments) protectedArgv.push_back(argument.data());
  const int code = runParsed(app, argc, protectedArgv.data(), [&] {
    setProgressMode(quiet ? ProgressMode::Quiet : ProgressMode::Automatic);
    loadPluginsFromEnvironment();
    if (*models) return runModelsCommand(modelsOptions);
    if (*check) return runCheckCommand(checkOptions);
    if (*evalCommand) return runEvalCommand(evalOptions);
    if (*generateTable) return runGenerateTableCommand(generateTableOptions);
    if (*synth) return runSynthCommand(synthOptions);
    if (*profile) return runProfileCommand(profileOptions);
    if (*fit) return runFitCommand(fitOptions);
    if (*shapeFactor) return runShapeFactorCommand(shapeFactorOptions);
    if (*renderCommand) return runRenderCommand(renderOptions);
    if (*lab) return runLabCommand(labOptions);
    if (*explore) return runExploreCommand(exploreOptions);
    if (*sweep) return runSweepCommand(sweepOptions);
    if (*merge) return runMergeCommand(mergeOptions);
    return reportError("no subcommand ran", ExitCode::InternalError);
  });
  return checkStandardOutput(code);
}

}  // namespace scatterlab
