#include "gmsh/msh_header.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace homesh::gmsh_adapter {
namespace {

// The offset just past the line "$NAME" (at the start of the file or of a
// line), or npos. Reads the file in chunks: MSH files may be gigabytes.
std::uint64_t section_start(std::ifstream& in, const std::string& name) {
  const std::string marker = "\n" + name;
  constexpr std::size_t kChunk = 1 << 22;
  std::vector<char> buf(kChunk + marker.size() + 2);
  in.clear();
  in.seekg(0);
  buf[0] = '\n';  // the file's start counts as a line start
  std::size_t kept = 1;
  std::uint64_t offset_of_0 = static_cast<std::uint64_t>(-1);  // buf[0] stands at offset -1
  for (;;) {
    in.read(buf.data() + kept, static_cast<std::streamsize>(kChunk));
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    const auto end = buf.begin() + static_cast<std::ptrdiff_t>(kept + got);
    for (auto hit = std::search(buf.begin(), end, marker.begin(), marker.end()); hit != end;
         hit = std::search(hit + 1, end, marker.begin(), marker.end())) {
      const auto k = hit + static_cast<std::ptrdiff_t>(marker.size());
      if (k == end || (*k == '\r' && k + 1 == end)) break;  // the line ends in the next chunk
      if (*k == '\n' || (*k == '\r' && k[1] == '\n'))
        return offset_of_0 + static_cast<std::uint64_t>(k - buf.begin()) + (*k == '\r' ? 2 : 1);
    }
    if (got == 0) return std::string::npos;
    // Keep the tail, where a marker may start.
    const std::size_t have = kept + got;
    kept = std::min(have, marker.size() + 1);
    std::memmove(buf.data(), buf.data() + have - kept, kept);
    offset_of_0 += have - kept;
  }
}

std::string bytes_at(std::ifstream& in, std::uint64_t offset, std::size_t count) {
  std::string s(count, '\0');
  in.clear();
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(s.data(), static_cast<std::streamsize>(count));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

std::uint64_t ascii_count(const std::string& path, const std::string& section, const std::string& s,
                          int index) {
  std::istringstream line(s.substr(0, s.find('\n')));
  std::string word;
  for (int k = 0; k <= index; ++k)
    if (!(line >> word)) word.clear();
  if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos || word.size() > 19)
    throw Error(path + ": the " + section + " section's header is not a count of entries");
  return std::stoull(word);
}

}  // namespace

MshHeader read_msh_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  MshHeader h;
  const std::string start = bytes_at(in, 0, 128);
  std::istringstream format(start);
  std::string first;
  int file_type = 0, data_size = 0;
  std::getline(format, first);
  if (!first.empty() && first.back() == '\r') first.pop_back();
  if (first != "$MeshFormat" || !(format >> h.version >> file_type >> data_size))
    throw Error(path + ": not a Gmsh .msh file (it does not start with a $MeshFormat section)");
  h.binary = file_type == 1;
  bool swap = false;
  if (h.binary) {
    const auto one = start.find('\n', start.find('\n') + 1) + 1;
    int value = 0;
    if (one + sizeof value > start.size())
      throw Error(path + ": the binary $MeshFormat section is cut short");
    std::memcpy(&value, start.data() + one, sizeof value);
    swap = value != 1;
  }
  const bool v4 = h.version >= 4;
  auto count = [&](const std::string& section) -> std::optional<std::uint64_t> {
    const std::uint64_t at = section_start(in, section);
    if (at == std::string::npos) return std::nullopt;
    const std::string s = bytes_at(in, at, 128);
    if (!(h.binary && v4)) return ascii_count(path, section, s, v4 ? 1 : 0);
    if (data_size != 8 || s.size() < 16)
      throw Error(path + ": the binary " + section + " section's header is cut short");
    std::uint64_t value = 0;
    std::memcpy(&value, s.data() + 8, 8);
    return swap ? __builtin_bswap64(value) : value;
  };
  h.nodes = count("$Nodes");
  h.elements = count("$Elements");
  return h;
}

void check_element_node_tags(const std::string& path) {
  const MshHeader h = read_msh_header(path);
  if (h.binary) return;
  std::ifstream in(path, std::ios::binary);
  const std::uint64_t at = section_start(in, "$Elements");
  if (at == std::string::npos) return;
  in.clear();
  in.seekg(static_cast<std::streamoff>(at));
  std::string line;
  std::getline(in, line);  // the section's header: counts
  for (long number = 2; std::getline(in, line); ++number) {
    if (line.rfind("$EndElements", 0) == 0) return;
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    // MSH 4: block headers (dim, entity, type, count) and elements (tag, nodes) hold no
    // negative number. MSH 2.2: tag, type, number of tags, tags (a ghost partition's may
    // be negative), nodes.
    std::size_t first_node = 0;
    if (h.version < 4 && w.size() >= 3) {
      const std::string& n = w[2];
      first_node = n.find_first_not_of("0123456789") == std::string::npos && n.size() < 6
                       ? 3 + std::stoul(n)
                       : w.size();
    }
    for (std::size_t k = first_node; k < w.size(); ++k)
      if (w[k][0] == '-')
        throw Error(path + ": line " + std::to_string(number) + " of its $Elements section names " +
                    w[k] + "; node and element tags are positive");
  }
}

}  // namespace homesh::gmsh_adapter
