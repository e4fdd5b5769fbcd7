#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

constexpr size_t HeadCharacters = 120;
constexpr size_t TailCharacters = 50;

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The longest start of `text` of at most `n` bytes that ends between UTF-8 characters.
std::string_view head(std::string_view text, size_t n) {
  while (n > 0 && n < text.size() && isContinuationByte(text[n])) --n;
  return text.substr(0, n);
}

std::string_view tail(std::string_view text, size_t n) {
  size_t start = text.size() - n;
  while (start < text.size() && isContinuationByte(text[start])) ++start;
  return text.substr(start);
}

}  // namespace

std::string shortened(std::string_view text) {
  if (text.size() <= MaxEchoedCharacters) return std::string(text);
  return std::string(head(text, HeadCharacters)) + " ... (" + std::to_string(text.size()) +
         " characters) ... " + std::string(tail(text, TailCharacters));
}

std::string inQuotes(std::string_view text) {
  std::string out(1, '"');
  out += shortened(text);
  out += '"';
  return out;
}

std::string shortenLongValues(std::string_view message) {
  std::string out;
  size_t i = 0;
  while (i < message.size()) {
    const char c = message[i];
    size_t end = i;
    // A single quote opens a run only after a space, '(' or ':' (an apostrophe follows a letter).
    const bool opensQuote =
        c == '"' ||
        (c == '\'' && (i == 0 || message[i - 1] == ' ' || message[i - 1] == '(' || message[i - 1] == ':'));
    if (opensQuote) {
      // A quoted run: up to the matching quote (or the end of the message).
      end = message.find(c, i + 1);
      end = end == std::string_view::npos ? message.size() : end + 1;
    } else if (c != ' ' && c != '\n') {
      end = message.find_first_of(" \n\"", i);
      if (end == std::string_view::npos) end = message.size();
    } else {
      out += c;
      ++i;
      continue;
    }
    const std::string_view run = message.substr(i, end - i);
    out += run.size() > MaxEchoedCharacters + 2 ? shortened(run) : std::string(run);
    i = end;
  }
  return out;
}

}  // namespace scatterlab
