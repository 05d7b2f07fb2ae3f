#include "gmsh/gmsh_call.h"

#include <gmsh.h>

#include <exception>

#include "core/error.h"

namespace homesh::gmsh_adapter {

void gmsh_call(const std::string& what, const std::function<void()>& body) {
  std::string message;
  gmsh::logger::start();
  std::string before;
  gmsh::logger::getLastError(before);
  try {
    body();
  } catch (const std::string& e) {
    message = e;
  } catch (const Error&) {
    gmsh::logger::stop();
    throw;
  } catch (const std::exception& e) {
    message = e.what();
  }
  if (message.empty()) {
    std::string last;
    gmsh::logger::getLastError(last);
    if (last != before) message = last;
  }
  gmsh::logger::stop();
  if (!message.empty()) throw Error(what + ": " + message);
}

}  // namespace homesh::gmsh_adapter
