#include "pipeline/option_parsers.h"

#include <fmt/core.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace homesh {
namespace {

// The finite number `s` spells entirely, if it does.
std::optional<double> number(const std::string& s) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string number_text(double v) { return fmt::format("{:g}", v); }

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

std::string names_text(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " | ") + n;
  return out;
}

Parser<int> integer(int lo, int hi, std::vector<std::pair<std::string, int>> words) {
  Parser<int> p;
  p.read = [lo, hi, words](const std::string& s, int& out) -> std::string {
    std::string names;
    for (const auto& [word, value] : words) {
      if (s == word) {
        out = value;
        return "";
      }
      names += " nor '" + word + "'";
    }
    const std::optional<double> v = number(s);
    if (!v || *v != std::floor(*v)) return "not an integer" + names;
    if (*v < lo || *v > hi) return fmt::format("out of range [{}, {}]", lo, hi);
    out = static_cast<int>(*v);
    return "";
  };
  p.show = [words](const int& v) {
    for (const auto& [word, value] : words)
      if (value == v) return word;
    return std::to_string(v);
  };
  return p;
}

Parser<double> real(double lo, double hi, const char* bounds) {
  const bool open_lo = bounds[0] == '(', open_hi = bounds[1] == ')';
  std::string range;
  if (std::isfinite(lo) && std::isfinite(hi))
    range = fmt::format("out of range {}{:g}, {:g}{}", bounds[0], lo, hi, bounds[1]);
  else if (std::isfinite(lo))
    range = fmt::format("must be {} {:g}", open_lo ? ">" : ">=", lo);
  else if (std::isfinite(hi))
    range = fmt::format("must be {} {:g}", open_hi ? "<" : "<=", hi);
  Parser<double> p;
  p.read = [=](const std::string& s, double& out) -> std::string {
    const std::optional<double> v = number(s);
    if (!v) return "not a finite number";
    if (*v < lo || *v > hi || (open_lo && *v == lo) || (open_hi && *v == hi)) return range;
    out = *v;
    return "";
  };
  p.show = number_text;
  return p;
}

Parser<bool> boolean() {
  return choice<bool>({{"true", true},
                       {"false", false},
                       {"1", true},
                       {"0", false},
                       {"yes", true},
                       {"no", false},
                       {"on", true},
                       {"off", false}});
}

Parser<std::string> text() {
  Parser<std::string> p;
  p.read = [](const std::string& s, std::string& out) {
    out = s;
    return std::string();
  };
  p.show = [](const std::string& v) { return v; };
  return p;
}

Parser<std::string> one_of(std::vector<std::string> names) {
  std::vector<std::pair<std::string, std::string>> choices;
  for (const std::string& n : names) choices.emplace_back(n, n);
  return choice(choices);
}

Parser<std::vector<std::string>> list(Parser<std::string> item) {
  Parser<std::vector<std::string>> p;
  p.read = [item](const std::string& s, std::vector<std::string>& out) -> std::string {
    std::vector<std::string> items = split(s);
    for (std::string& i : items) {
      const std::string refused = item.read(i, i);
      if (!refused.empty()) return "'" + i + "': " + refused;
    }
    out = std::move(items);
    return "";
  };
  p.show = [item](const std::vector<std::string>& v) {
    std::string joined;
    for (const std::string& i : v) joined += (joined.empty() ? "" : ",") + item.show(i);
    return joined;
  };
  return p;
}

Parser<std::optional<Eigen::Vector2d>> point_or(std::string word) {
  Parser<std::optional<Eigen::Vector2d>> p;
  p.read = [word](const std::string& s, std::optional<Eigen::Vector2d>& out) -> std::string {
    if (s == word) {
      out.reset();
      return "";
    }
    const std::size_t comma = s.find(',');
    const std::optional<double> x = number(s.substr(0, comma));
    const std::optional<double> y =
        comma == std::string::npos ? std::nullopt : number(s.substr(comma + 1));
    if (!x || !y) return "expected " + word + " or two numbers x,y";
    out = Eigen::Vector2d(*x, *y);
    return "";
  };
  p.show = [word](const std::optional<Eigen::Vector2d>& v) {
    return v ? fmt::format("{:g},{:g}", v->x(), v->y()) : word;
  };
  return p;
}

}  // namespace homesh
