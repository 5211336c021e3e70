#include "cli/option_table.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace radbake {

std::string got(const std::string& text) { return ", got '" + clipped(text) + "'"; }

std::string bound_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, v == std::floor(v) && std::fabs(v) < 1e16 ? "%.0f" : "%g", v);
  return text;
}

std::string range_text(double lo, double hi, const std::string& unit) {
  return bound_text(lo) + ".." + bound_text(hi) + (unit.empty() ? "" : " " + unit);
}

std::string echo_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

double parse_number(const std::string& option, const std::string& text, double lo, double hi) {
  // strtod, not stod: a value too large for a double is out of range (HUGE_VAL), not "no number".
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || std::isnan(v)) throw UsageError("option " + option + " needs a number" + got(text));
  if (v < lo || v > hi)
    throw UsageError("option " + option + " must be between " + bound_text(lo) + " and " + bound_text(hi) + got(text));
  return v;
}

long parse_integer(const std::string& option, const std::string& text, long lo, long hi) {
  const double v = parse_number(option, text, double(lo), double(hi));
  if (v != std::floor(v)) throw UsageError("option " + option + " needs a whole number" + got(text));
  return long(v);
}

std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count, double lo,
                                  double hi) {
  std::vector<double> values;
  size_t start = 0;
  for (size_t k = 0; k < count; ++k) {
    const size_t comma = k + 1 < count ? text.find(',', start) : text.size();
    if (comma == std::string::npos)
      throw UsageError("option " + option + " needs " + std::to_string(count) + " numbers separated by commas" + got(text));
    values.push_back(parse_number(option, text.substr(start, comma - start), lo, hi));
    start = comma + 1;
  }
  return values;
}

std::string one_of(const std::vector<std::string>& words) {
  std::string out;
  for (size_t k = 0; k < words.size(); ++k)
    out += (k == 0 ? "" : k + 1 == words.size() ? " or " : ", ") + words[k];
  return out;
}

std::string option_line(const std::string& name, const std::string& help) {
  constexpr size_t kColumn = 26, kWidth = 100;
  std::string out = "  " + name;
  std::string line;
  if (out.size() + 2 > kColumn) out += "\n" + std::string(kColumn, ' ');
  else out += std::string(kColumn - out.size(), ' ');
  std::istringstream words(help);
  size_t at = kColumn;
  bool first = true;
  for (std::string word; words >> word;) {
    if (!first && at + 1 + word.size() > kWidth) {
      out += "\n" + std::string(kColumn, ' ');
      at = kColumn;
      first = true;
    }
    if (!first) {
      out += ' ';
      ++at;
    }
    out += word;
    at += word.size();
    first = false;
  }
  return out + "\n";
}

}  // namespace radbake
