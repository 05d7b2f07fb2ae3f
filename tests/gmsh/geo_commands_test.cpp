// The scan of a .geo for commands that reach outside the model, against
// scripts whose answer is known: commands at statement starts in the file and
// in files it includes, nothing in comments, strings or variables.
#include "gmsh/geo_commands.h"

#include <catch2/catch.hpp>
#include <fstream>

#include "../support/temp_dir.h"

using homesh::gmsh_adapter::geo_commands;
using homesh::gmsh_adapter::geo_file_commands;

namespace {

std::vector<std::string> names(const std::vector<homesh::gmsh_adapter::GeoCommand>& c) {
  std::vector<std::string> out;
  for (const auto& x : c) out.push_back(x.name + "@" + std::to_string(x.line));
  return out;
}

}  // namespace

TEST_CASE("geo_commands finds the commands at statement starts, with their lines", "[gmsh]") {
  const std::string text =
      "Point(1) = {0, 0, 0};\n"
      "System \"rm -rf /\";\n"
      "If (x > 1)\n"
      "  SystemCall StrCat(\"a\", \"b\");\n"
      "EndIf\n"
      "Save \"out.msh\"; Print \"x.png\";\n"
      "Sleep 1e9;\n"
      "OnelabRun(\"c\", \"d\");\n";
  REQUIRE(names(geo_commands("/nowhere/a.geo", text)) ==
          std::vector<std::string>{"System@2", "SystemCall@4", "Save@6", "Print@6", "Sleep@7",
                                   "OnelabRun@8"});
}

TEST_CASE("geo_commands skips comments, strings and variables named like commands", "[gmsh]") {
  const std::string text =
      "// System \"ls\";\n"
      "/* Save \"a.msh\";\n   Exit; */\n"
      "s = \"; System 'ls'\";\n"
      "Sleep = 2; Save[0] = 1; Print += 1;\n"
      "x = Sleep + 1;\n"
      "Printf(\"Save this\");\n";
  REQUIRE(geo_commands("/nowhere/a.geo", text).empty());
}

TEST_CASE("geo_commands follows Include and .geo Merge by literal path, once each", "[gmsh]") {
  const homesh::test::TempDir dir;
  std::ofstream(dir / "inner.geo") << "\n\nNonBlockingSystemCall \"x\";\nInclude \"outer.geo\";\n";
  std::ofstream(dir / "part.step") << "System is not a .geo command here";
  std::ofstream(dir / "outer.geo") << "Include \"inner.geo\";\nMerge \"part.step\";\n"
                                   << "Merge \"inner.geo\";\nInclude StrCat(\"a\", \".geo\");\n";
  const auto c = geo_file_commands(dir / "outer.geo");
  REQUIRE(names(c) == std::vector<std::string>{"NonBlockingSystemCall@3", "Include@4"});
  REQUIRE(c[0].file == dir / "inner.geo");
  REQUIRE(c[1].file == dir / "outer.geo");
}
