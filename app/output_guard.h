// One check of every output against every input, before any work (docs/reliability.md, "Outputs"):
// a command never writes over a file it reads, and never replaces a directory that holds one.
// Paths are compared by their canonical form (symbolic links and ".." resolved) and, for
// files that exist, by device and inode, so that a hard link or a bind mount does not hide
// the clash.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

// A file the command reads; `what` names it in messages ("material file", "--env").
struct InputPath {
  std::string what;
  std::filesystem::path path;
};

// How a command writes an output path.
enum class OutputKind {
  File,               // the file is replaced whole
  ReplacedDirectory,  // the directory is replaced whole (lab --out): no input may be inside
  FilesInDirectory,   // files whose names end with given suffixes are written into it
};

// Throws InputError naming `option`, the output and the input when the output is an input,
// or (ReplacedDirectory) contains one, or (FilesInDirectory) holds one whose name ends with
// one of `suffixes`.
void refuseOutputOverInputs(const std::string& option, const std::filesystem::path& output, OutputKind kind,
                            const std::vector<InputPath>& inputs,
                            const std::vector<std::string>& suffixes = {});

// The files a material description reads (the path parameters of it and of every nested
// material: a measured table's "file"), for the check above.
std::vector<std::filesystem::path> materialInputFiles(const nlohmann::json& material);

// The inputs of a material argument: its file (unless it is inline JSON) and the files its
// description reads, appended to `inputs`.
void addMaterialInputs(std::vector<InputPath>& inputs, const std::string& argument,
                       const nlohmann::json& material);

}  // namespace scatterlab
