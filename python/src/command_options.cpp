#include "python/src/command_options.h"

#include <algorithm>

#include "python/src/json_conversion.h"

namespace py = pybind11;

namespace scatterlab::python {
namespace {

// A keyword's value as the text the command line would have been given.
std::string optionText(py::handle value, const std::string& keyword) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  if (py::isinstance<py::dict>(value)) return jsonFromPython(value, keyword).dump();
  // os.PathLike (pathlib.Path) as its path; any other object as its str(), for the command's own
  // parser to accept or refuse with its message.
  if (py::hasattr(value, "__fspath__")) return py::str(value.attr("__fspath__")()).cast<std::string>();
  return py::str(value).cast<std::string>();
}

}  // namespace

CommandOptions::CommandOptions(std::string caller, const std::function<CLI::App*(CLI::App&)>& addCommand,
                               std::set<std::string> withheld)
    : caller_(std::move(caller)), app_(caller_), withheld_(std::move(withheld)) {
  app_.require_subcommand(1);
  command_ = addCommand(app_);
  // A withheld option the command line requires (render's --out) is not needed here.
  for (const std::string& name : withheld_)
    if (CLI::Option* option = command_->get_option_no_throw("--" + name)) option->required(false);
}

std::string CommandOptions::allowedKeywords() const {
  std::vector<std::string> names;
  for (const CLI::Option* option : command_->get_options()) {
    if (!option->nonpositional() || option->get_lnames().empty()) continue;
    std::string name = option->get_lnames().front();
    if (name == "help" || withheld_.count(name)) continue;
    std::replace(name.begin(), name.end(), '-', '_');
    names.push_back(name);
  }
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void CommandOptions::parse(const py::dict& keywords, const std::vector<std::string>& positionals) {
  std::vector<std::string> args{command_->get_name()};
  for (const auto& [key, value] : keywords) {
    const std::string keyword = py::str(key).cast<std::string>();
    std::string name = keyword;
    std::replace(name.begin(), name.end(), '_', '-');
    const CLI::Option* option = command_->get_option_no_throw("--" + name);
    if (withheld_.count(name))
      throw py::value_error(caller_ + ": " + keyword +
                            ": only shapes what the command line writes or prints; the result is returned "
                            "instead. Allowed keywords: " +
                            allowedKeywords());
    if (option == nullptr || name == "help" || !option->nonpositional())
      throw py::value_error(caller_ + ": unknown keyword " + keyword + "; allowed: " + allowedKeywords());
    if (value.is_none()) continue;
    const bool flag = option->get_type_size_max() == 0;
    if (flag) {
      if (!py::isinstance<py::bool_>(value))
        throw py::value_error(caller_ + ": " + keyword + ": a switch; allowed: True or False, got " +
                              py::repr(value).cast<std::string>());
      if (value.cast<bool>()) args.push_back("--" + name);
      continue;
    }
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      for (py::handle item : value) args.push_back("--" + name + "=" + optionText(item, keyword));
      continue;
    }
    args.push_back("--" + name + "=" + optionText(value, keyword));
  }
  // After "--" every argument is positional, whatever its first character.
  args.push_back("--");
  args.insert(args.end(), positionals.begin(), positionals.end());
  std::reverse(args.begin(), args.end());  // CLI11 takes the vector last argument first
  try {
    app_.parse(args);
  } catch (const CLI::ParseError& error) {
    throw py::value_error(caller_ + ": " + error.what() +
                          " (a keyword is its option's name with underscores for dashes)");
  }
}

}  // namespace scatterlab::python
