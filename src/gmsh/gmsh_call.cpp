#include "gmsh/gmsh_call.h"

#include <gmsh.h>

#include <exception>
#include <new>

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
  } catch (
      const std::bad_alloc&) {  // out of memory is not Gmsh's error: the caller says what ran out
    gmsh::logger::stop();
    throw;
  } catch (const std::exception& e) {
    message = e.what();
  }
  // With General.AbortOnError 0 (as homesh runs Gmsh) errors are only logged:
  // the first one logged during the call is the cause. The last error also
  // catches one logged while the logger did not record (a nested call stopped it).
  if (message.empty()) {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (const std::string& line : log)
      if (line.rfind("Error", 0) == 0) {
        message = line.substr(std::min(line.find(':') + 1, line.size()));
        message.erase(0, message.find_first_not_of(' '));
        break;
      }
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
