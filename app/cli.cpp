#include "app/cli.h"

#include <iostream>

#include <CLI/CLI.hpp>

#include "app/check_command.h"
#include "app/exit_code.h"
#include "app/fit_command.h"
#include "app/generate_table_command.h"
#include "app/lab/lab_command.h"
#include "app/models_command.h"
#include "app/profile_command.h"
#include "app/render_command.h"
#include "app/shape_factor_command.h"
#include "app/synth_command.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

int reportError(const std::string& message, ExitCode code) {
  std::cerr << "scatterlab: error: " << message << "\n";
  return static_cast<int>(code);
}

// CLI11's own exit codes (100 and up) are all bad input to scatterlab; help and version are
// successes.
int exitCodeOfParseError(const CLI::App& app, const CLI::ParseError& error) {
  const int cliCode = app.exit(error);
  return static_cast<int>(cliCode == 0 ? ExitCode::Success : ExitCode::BadInput);
}

}  // namespace

int runCli(int argc, char** argv) {
  CLI::App app{
      "scatterlab: a laboratory for reflectance models. Checks a material's sampling "
      "statistically; every material is a JSON object, see `scatterlab models`.",
      "scatterlab"};
  app.set_version_flag("--version", std::string("scatterlab ") + SCATTERLAB_VERSION);
  app.require_subcommand(1);
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return "scatterlab: error: " + std::string(error.what()) + "\n";
  });
  ModelsCommandOptions modelsOptions;
  CheckCommandOptions checkOptions;
  const CLI::App* models = addModelsCommand(app, modelsOptions);
  const CLI::App* check = addCheckCommand(app, checkOptions);
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

  GenerateTableOptions generateTableOptions;  // a hidden developer command
  const CLI::App* generateTable = addGenerateTableCommand(app, generateTableOptions);

  // Nothing may escape: every failure is one message and an exit code (exit_code.h).
  try {
    app.parse(argc, argv);
    if (*models) return runModelsCommand(modelsOptions);
    if (*check) return runCheckCommand(checkOptions);
    if (*generateTable) return runGenerateTableCommand(generateTableOptions);
    if (*synth) return runSynthCommand(synthOptions);
    if (*profile) return runProfileCommand(profileOptions);
    if (*fit) return runFitCommand(fitOptions);
    if (*shapeFactor) return runShapeFactorCommand(shapeFactorOptions);
    if (*renderCommand) return runRenderCommand(renderOptions);
    if (*lab) return runLabCommand(labOptions);
    return reportError("no subcommand ran", ExitCode::InternalError);
  } catch (const CLI::ParseError& error) {
    return exitCodeOfParseError(app, error);
  } catch (const MaterialError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const InputError& error) {
    return reportError(error.what(), ExitCode::BadInput);
  } catch (const std::exception& error) {
    return reportError(std::string("internal error: ") + error.what(), ExitCode::InternalError);
  } catch (...) {
    return reportError("internal error: unknown exception", ExitCode::InternalError);
  }
}

}  // namespace scatterlab
