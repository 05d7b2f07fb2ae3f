#include "gmsh/geo_commands.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"

namespace homesh::gmsh_adapter {
namespace {

constexpr std::array<const char*, 9> kOutside = {
    "System", "SystemCall", "NonBlockingSystemCall", "OnelabRun", "Save",
    "Print",  "CreateDir",  "CreateFolder",          "Sleep"};

struct Token {
  enum class Kind { Word, String, Other } kind;
  std::string text;  // the word, the string's contents, or the character
  int line;
};

// Gmsh's lexer (Gmsh.l), reduced to what the scan needs: words, strings in
// single or double quotes (no escapes), comments skipped, other characters one by one.
std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  int line = 1;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (s.compare(i, 2, "//") == 0) {
      i = std::min(s.find('\n', i), s.size());
    } else if (s.compare(i, 2, "/*") == 0) {
      const std::size_t end = std::min(s.find("*/", i + 2), s.size());
      line += static_cast<int>(std::count(s.begin() + i, s.begin() + end, '\n'));
      i = std::min(end + 2, s.size());
    } else if (c == '"' || c == '\'') {
      const std::size_t end = std::min(s.find(c, i + 1), s.size());
      out.push_back({Token::Kind::String, s.substr(i + 1, end - i - 1), line});
      line += static_cast<int>(std::count(s.begin() + i, s.begin() + end, '\n'));
      i = std::min(end + 1, s.size());
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t end = i;
      while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '_'))
        ++end;
      out.push_back({Token::Kind::Word, s.substr(i, end - i), line});
      i = end;
    } else {
      out.push_back({Token::Kind::Other, std::string(1, c), line});
      ++i;
    }
  }
  return out;
}

bool statement_starts_after(const std::vector<Token>& t, std::size_t k) {
  if (k == 0) return true;
  const Token& p = t[k - 1];
  if (p.kind == Token::Kind::Other)
    return p.text == ";" || p.text == "{" || p.text == "}" || p.text == ")";
  return p.kind == Token::Kind::Word &&
         (p.text == "EndIf" || p.text == "EndFor" || p.text == "Else" || p.text == "Return");
}

// `name = ...`, `name[...]`, `name.x`, `name += ...`: a variable, not a command.
bool assigned(const std::vector<Token>& t, std::size_t k) {
  if (k + 1 >= t.size() || t[k + 1].kind != Token::Kind::Other) return false;
  const std::string& n = t[k + 1].text;
  if (n == "=" || n == "[" || n == ".") return true;
  return (n == "+" || n == "-" || n == "*" || n == "/") && k + 2 < t.size() && t[k + 2].text == "=";
}

bool is_geo(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext == ".geo";
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void scan(const std::string& file, const std::string& text, std::set<std::string>& seen,
          std::vector<GeoCommand>& out) {
  const std::vector<Token> t = tokens(text);
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k].kind != Token::Kind::Word || !statement_starts_after(t, k) || assigned(t, k)) continue;
    const std::string& w = t[k].text;
    if (std::find(kOutside.begin(), kOutside.end(), w) != kOutside.end()) {
      out.push_back({file, t[k].line, w});
    } else if (w == "Include" || w == "Merge") {
      const bool literal =
          k + 2 < t.size() && t[k + 1].kind == Token::Kind::String && t[k + 2].text == ";";
      if (!literal) {
        out.push_back({file, t[k].line, w});
        continue;
      }
      std::filesystem::path p = t[k + 1].text;
      if (p.is_relative()) p = std::filesystem::path(file).parent_path() / p;
      std::error_code ec;
      const std::string key = std::filesystem::weakly_canonical(p, ec).string();
      if ((w == "Include" || is_geo(p.string())) && std::filesystem::is_regular_file(p, ec) &&
          seen.insert(key).second)
        scan(p.string(), read_text(p.string()), seen, out);
    }
  }
}

}  // namespace

std::vector<GeoCommand> geo_commands(const std::string& file, const std::string& text) {
  std::set<std::string> seen;
  std::error_code ec;
  seen.insert(std::filesystem::weakly_canonical(file, ec).string());
  std::vector<GeoCommand> out;
  scan(file, text, seen, out);
  return out;
}

std::vector<GeoCommand> geo_file_commands(const std::string& path) {
  return geo_commands(path, read_text(path));
}

}  // namespace homesh::gmsh_adapter
