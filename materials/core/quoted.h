// Values in messages (docs/reliability.md, "Messages"): a message names the bad value, but echoes
// at most about MaxEchoedCharacters of it, so a 10 MB argument or a runaway string in a file
// gives a readable line, not a screenful.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace scatterlab {

inline constexpr size_t MaxEchoedCharacters = 200;

// `text` as it is when short; otherwise its start and end around "... (N characters) ...",
// about MaxEchoedCharacters in all, cut between UTF-8 characters.
std::string shortened(std::string_view text);

// shortened(text) in double quotes. (Not `quoted`: std::quoted would win by argument-dependent
// lookup for a std::string.)
std::string inQuotes(std::string_view text);

// The whole message with every run longer than MaxEchoedCharacters shortened: runs between
// quotes ("..." or '...') and runs without spaces. The last guard before a message is
// printed, for values no caller put through inQuotes().
std::string shortenLongValues(std::string_view message);

}  // namespace scatterlab
