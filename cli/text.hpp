// Small string helpers shared by the option and INI parsers.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace lumen::cli {

std::string lower(std::string_view s);
std::string trim(std::string_view s);
// Removes one pair of surrounding double quotes, if present.
std::string unquote(std::string_view s);
bool iequals(std::string_view a, std::string_view b);
bool ends_with_nocase(std::string_view s, std::string_view suffix);
// Splits on blanks, keeping "quoted parts" (with their quotes) inside one word.
std::vector<std::string> split_words(std::string_view line);

}  // namespace lumen::cli
