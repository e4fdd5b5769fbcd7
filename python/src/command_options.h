// Python keywords as a command's options (docs/python.md, "Keywords are the command's options"):
// sl.fit(data, samples=2000, per_channel=True) is parsed as `scatterlab fit DATA --samples 2000
// --per-channel` by the very CLI11 subcommand the command line registers, so every keyword has the
// command's name, default, range and message, and the two cannot drift apart.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <CLI/CLI.hpp>

namespace scatterlab::python {

class CommandOptions {
 public:
  // `caller` ("sl.fit") starts every message; `addCommand` registers the subcommand on the app it
  // is given and binds its options; `withheld` names options (without dashes) that only shape what
  // the command writes or prints and have no meaning in Python (--out, --json): passing one is an
  // error that says so.
  CommandOptions(std::string caller, const std::function<CLI::App*(CLI::App&)>& addCommand,
                 std::set<std::string> withheld);

  // Parses the keywords (name with underscores for dashes; None means the default; True gives a
  // flag, False leaves it off; a list or tuple gives an option several values; anything else is
  // passed as its str(), a float as its repr() so no digit is lost) and the positional arguments.
  // Raises ValueError naming the keyword and what is allowed.
  void parse(const pybind11::dict& keywords, const std::vector<std::string>& positionals);

  // Runs the command's work with the GIL released (it calls no Python), its library errors
  // becoming ValueError (errors.cpp).
  template <typename Work> auto run(Work&& work) const {
    pybind11::gil_scoped_release release;
    return std::forward<Work>(work)();
  }

 private:
  // The keywords the command accepts, for messages: "samples, seed, per_channel, ...".
  std::string allowedKeywords() const;

  std::string caller_;
  CLI::App app_;
  CLI::App* command_ = nullptr;
  std::set<std::string> withheld_;
};

}  // namespace scatterlab::python
