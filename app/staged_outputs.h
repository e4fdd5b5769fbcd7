// Every file a command writes, staged and committed as one set (docs/reliability.md, "Outputs").
//
//   StagedOutputs outputs(inputs);                    // the files the command reads
//   outputs.addFile("--out", "out/gold.exr", ...);    // checked now: nothing is created
//   outputs.addFile("--out", "out/gold.png", ...);
//   outputs.prepare();         // after every input is valid, before the work: missing parent
//                              // directories and one empty temporary per output are created,
//                              // which proves each place writable (exit 2 if not)
//   writeExr(outputs.staged("out/gold.exr"), ...);    // the work writes the temporaries
//   outputs.commit();          // then every temporary is renamed over its target
//
// Until commit() the old outputs are untouched: a failed write, an exception or an
// interruption (SIGINT, SIGTERM: temporary_files.h) removes the temporaries and leaves the
// previous set exactly as it was. commit() keeps a hard link to each old file until every
// rename succeeded, and puts the old files back if one fails; an interruption waits for it.
//
// An output is refused when it is empty, ends in '/', is an existing directory or a device
// (/dev/null), or is (or would overwrite) one of the inputs (output_guard.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/output_guard.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

class StagedOutputs {
 public:
  explicit StagedOutputs(std::vector<InputPath> inputs = {});
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  // A file replaced whole. Throws InputError naming `option`; `example` ends the message
  // ("out/gold.exr").
  void addFile(const std::string& option, const std::filesystem::path& target, const std::string& example);
  // A directory (created when missing) into which the work writes files whose names end with
  // one of `suffixes`; each replaces a file of the same name at commit(), other files in the
  // directory stay. staged(target) is then a directory.
  void addDirectory(const std::string& option, const std::filesystem::path& target,
                    std::vector<std::string> suffixes);

  // See above. Throws InputError naming the option when a directory or temporary cannot be
  // created.
  void prepare();

  // Where the work writes `target` (as given to addFile or addDirectory).
  std::filesystem::path staged(const std::filesystem::path& target) const;

  // Renames every staged file over its target (see above). Throws InputError naming the
  // option when a rename fails; the previous files are then back in place.
  void commit();

 private:
  struct Output {
    std::string option;
    std::filesystem::path target;
    bool directory = false;
    TemporaryPath staging;
  };
  const Output& find(const std::filesystem::path& target) const;

  std::vector<InputPath> inputs_;
  std::vector<Output> outputs_;
  bool prepared_ = false;
};

// Creates `directory` and its missing parents, under the interruption lock (temporary_files.h).
// Throws InputError naming `option`, the directory and why ("a file is in the way" when a file
// has the name of one); `allowed` ends the message.
void createOutputDirectory(const std::string& option, const std::filesystem::path& directory,
                           const std::string& allowed = "; allowed: a path where a directory can be created");

}  // namespace scatterlab
