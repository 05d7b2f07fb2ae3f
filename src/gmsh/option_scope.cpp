#include "gmsh/option_scope.h"

#include <gmsh.h>

namespace homesh::gmsh_adapter {

void OptionScope::set(const std::string& name, double value) {
  double old = 0;
  gmsh::option::getNumber(name, old);
  saved_.emplace_back(name, old);
  gmsh::option::setNumber(name, value);
}

OptionScope::~OptionScope() {
  for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
    try {
      gmsh::option::setNumber(it->first, it->second);
    } catch (...) {  // restoring a value Gmsh gave us cannot fail; a destructor never throws
    }
  }
}

}  // namespace homesh::gmsh_adapter
