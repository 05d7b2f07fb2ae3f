#include "core/wall_curves.h"

#include <algorithm>

#include "core/error.h"

namespace homesh {
namespace {

bool is_number(const std::string& s) {
  return !s.empty() && s.size() < 10 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The curves of the dimension-1 physical groups `w` names (by name, else by
// number); empty if none.
std::vector<int> group_curves(const Mesh& m, const std::string& w) {
  std::vector<int> curves;
  for (const PhysicalGroup& g : m.physicals)
    if (g.dim == 1 && g.name == w)
      curves.insert(curves.end(), g.entities.begin(), g.entities.end());
  if (!curves.empty() || !is_number(w)) return curves;
  for (const PhysicalGroup& g : m.physicals)
    if (g.dim == 1 && g.tag == std::stoi(w))
      curves.insert(curves.end(), g.entities.begin(), g.entities.end());
  return curves;
}

bool is_curve(const Mesh& m, int tag) {
  return std::any_of(m.entities.begin(), m.entities.end(),
                     [&](const Entity& e) { return e.dim == 1 && e.tag == tag; }) ||
         std::find(m.line_entity.begin(), m.line_entity.end(), tag) != m.line_entity.end();
}

}  // namespace

std::vector<int> wall_curves(const Mesh& m, const std::vector<std::string>& walls,
                             const std::string& context) {
  if (walls.empty())
    throw Error(context +
                ": no walls given (curve physical group names or numbers, or curve tags)");
  std::vector<int> curves;
  for (const std::string& w : walls) {
    const std::vector<int> group = group_curves(m, w);
    if (!group.empty()) {
      curves.insert(curves.end(), group.begin(), group.end());
    } else if (is_number(w) && is_curve(m, std::stoi(w))) {
      curves.push_back(std::stoi(w));
    } else {
      std::string known;
      for (const PhysicalGroup& g : m.physicals)
        if (g.dim == 1 && !g.name.empty()) known += (known.empty() ? "" : ", ") + g.name;
      throw Error(context + ": no wall '" + w + "': not a curve physical group (" +
                  (known.empty() ? "none" : known) +
                  ") by name or number, nor a curve tag of the mesh");
    }
  }
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  return curves;
}

}  // namespace homesh
