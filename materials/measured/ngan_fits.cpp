#include "materials/measured/ngan_fits.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <fstream>
#include <optional>

#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// A call in a fit line: Name(key = value, ...) or Name(Call, Call, ...).
struct Call {
  std::string name;
  json arguments = json::object();  // key = value arguments
  std::vector<Call> calls;          // nested calls (Aggregate's terms)
};

// Recursive descent over: call := ident '(' [arg (',' arg)*] ')';
// arg := call | ident '=' value; value := number | '[' number (',' number)* ']'.
class LineParser {
 public:
  LineParser(std::string_view text, size_t column0) : text_(text), column0_(column0) {}

  Call call() {
    Call c{identifier(), json::object(), {}};
    expect('(');
    if (!peek(')')) {
      do {
        const size_t start = skipSpace();
        std::string word = identifier();
        if (peek('(')) {
          pos_ = start;
          c.calls.push_back(call());
        } else {
          expect('=');
          if (c.arguments.contains(word)) fail("parameter \"" + word + "\" given twice");
          c.arguments[word] = value();
        }
      } while (accept(','));
    }
    expect(')');
    return c;
  }
  void end() {
    skipSpace();
    if (pos_ != text_.size()) fail("unexpected text after the closing parenthesis");
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw MaterialError(problem + " at column " + std::to_string(column0_ + pos_ + 1));
  }

 private:
  size_t skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return pos_;
  }
  bool peek(char ch) {
    skipSpace();
    return pos_ < text_.size() && text_[pos_] == ch;
  }
  bool accept(char ch) {
    if (!peek(ch)) return false;
    ++pos_;
    return true;
  }
  void expect(char ch) {
    if (!accept(ch)) fail(std::string("expected '") + ch + "'");
  }
  std::string identifier() {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    if (pos_ == start) fail("expected a name");
    return std::string(text_.substr(start, pos_ - start));
  }
  double number() {
    skipSpace();
    double x = 0;
    const auto [end, error] = std::from_chars(text_.data() + pos_, text_.data() + text_.size(), x);
    if (error != std::errc() || !std::isfinite(x)) fail("expected a finite number");
    pos_ = size_t(end - text_.data());
    return x;
  }
  json value() {
    if (!accept('[')) return number();
    json list = json::array();
    do list.push_back(number());
    while (accept(','));
    expect(']');
    return list;
  }

  std::string_view text_;
  size_t column0_;  // columns of the line before text_
  size_t pos_ = 0;
};

// Lobe models: the parameters a line must give, and the registry material they become.
struct LobeMapping {
  const char* model;
  std::vector<std::string> keys;
  json (*material)(const json& p);
};

const std::array<LobeMapping, 5>& lobeMappings() {
  static const std::array<LobeMapping, 5> mappings{{
      {"NganCookTorrance",
       {"albedo", "eta", "roughness"},
       [](const json& p) {
         return json{{"type", "ngan-cook-torrance"},
                     {"albedo", p["albedo"]},
                     {"eta", p["eta"]},
                     {"roughness", p["roughness"]}};
       }},
      {"NganWard",
       {"albedo", "roughness"},
       [](const json& p) {
         return json{{"type", "ngan-ward"}, {"albedo", p["albedo"]}, {"roughness", p["roughness"]}};
       }},
      {"NganAshikhminShirley",
       {"albedo", "fresnelReflectance", "sharpness"},
       [](const json& p) {
         return json{{"type", "ngan-ashikhmin-shirley"},
                     {"albedo", p["albedo"]},
                     {"fresnelReflectance", p["fresnelReflectance"]},
                     {"sharpness", p["sharpness"]}};
       }},
      {"NganBlinnPhong",
       {"albedo", "sharpness"},
       [](const json& p) {
         return json{{"type", "blinn-phong"}, {"kd", 0.0}, {"ks", p["albedo"]}, {"exponent", p["sharpness"]}};
       }},
      {"NganLafortune",
       {"albedo", "Cxy", "Cz", "sharpness"},
       [](const json& p) {
         return json{
             {"type", "lafortune"}, {"kd", 0.0},     {"ks", p["albedo"]},          {"cx", p["Cxy"]},
             {"cy", p["Cxy"]},      {"cz", p["Cz"]}, {"exponent", p["sharpness"]}, {"normalization", "ngan"}};
       }},
  }};
  return mappings;
}

const LobeMapping* findMapping(const std::string& model) {
  for (const LobeMapping& m : lobeMappings())
    if (model == m.model) return &m;
  return nullptr;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// The call's arguments are exactly `keys`, "albedo" an RGB triple and the others numbers.
void checkArguments(const Call& c, const std::vector<std::string>& keys, const LineParser& parser) {
  for (const auto& [key, value] : c.arguments.items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      parser.fail(c.name + ": unknown parameter \"" + key + "\" (expected " + joined(keys) + ")");
    const bool rgb = key == "albedo";
    if (rgb ? !(value.is_array() && value.size() == 3) : !value.is_number())
      parser.fail(c.name + ": parameter \"" + key + "\" must be " + (rgb ? "[r, g, b]" : "a number"));
  }
  for (const std::string& key : keys)
    if (!c.arguments.contains(key)) parser.fail(c.name + ": parameter \"" + key + "\" is missing");
}

}  // namespace

std::vector<std::string> publishedFitModels() {
  std::vector<std::string> names;
  for (const LobeMapping& m : lobeMappings()) names.emplace_back(m.model);
  return names;
}

std::vector<json> PublishedFit::components() const {
  const LobeMapping* mapping = findMapping(lobeModel);
  if (!mapping)
    throw MaterialError("published fit \"" + name + "\": unknown lobe model \"" + lobeModel + "\"");
  return {json{{"type", "lambertian"}, {"albedo", {diffuseAlbedo.x, diffuseAlbedo.y, diffuseAlbedo.z}}},
          mapping->material(lobeParameters)};
}

PublishedFit parsePublishedFitLine(const std::string& line) {
  const size_t equals = line.find('=');
  if (equals == std::string::npos) throw MaterialError("expected \"name = Aggregate(...)\"");
  PublishedFit fit;
  fit.line = line;
  fit.name = line.substr(0, equals);
  fit.name.erase(fit.name.find_last_not_of(" \t") + 1);
  fit.name.erase(0, fit.name.find_first_not_of(" \t"));
  if (fit.name.empty()) throw MaterialError("the material name before '=' is empty");

  LineParser parser(std::string_view(line).substr(equals + 1), equals + 1);
  const Call aggregate = parser.call();
  parser.end();
  if (aggregate.name != "Aggregate" || aggregate.calls.size() != 2 || !aggregate.arguments.empty())
    throw MaterialError("expected Aggregate(Lambertian(...), <lobe>(...)) after the name");
  const Call& diffuse = aggregate.calls[0];
  const Call& lobe = aggregate.calls[1];
  if (diffuse.name != "Lambertian")
    throw MaterialError("the first term of Aggregate must be Lambertian(albedo = [r, g, b])");
  checkArguments(diffuse, {"albedo"}, parser);
  const json& albedo = diffuse.arguments["albedo"];
  fit.diffuseAlbedo = Rgb(albedo[0].get<double>(), albedo[1].get<double>(), albedo[2].get<double>());

  const LobeMapping* mapping = findMapping(lobe.name);
  if (!mapping)
    throw MaterialError("unknown lobe model \"" + lobe.name + "\"; allowed: " + joined(publishedFitModels()));
  checkArguments(lobe, mapping->keys, parser);
  fit.lobeModel = lobe.name;
  fit.lobeParameters = lobe.arguments;
  return fit;
}

std::vector<PublishedFit> readPublishedFits(const std::filesystem::path& file) {
  const std::string source = "published-fits file \"" + file.string() + "\"";
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw MaterialError(source + ": not found");
  if (std::filesystem::is_directory(status)) throw MaterialError(source + ": is a directory, not a file");
  std::ifstream in(file);
  if (!in) throw MaterialError(source + ": not readable");
  std::vector<PublishedFit> fits;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    try {
      fits.push_back(parsePublishedFitLine(line));
    } catch (const MaterialError& e) {
      throw MaterialError(source + ", line " + std::to_string(number) + ": " + e.what());
    }
  }
  if (in.bad()) throw MaterialError(source + ": read error");
  return fits;
}

}  // namespace scatterlab
