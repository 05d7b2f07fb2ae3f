#pragma once
// Stage options on the command line: `name:key=value:key=value`. Each stage
// declares its keys in an option table (pipeline/option_table.h), which reads
// them into the options struct of the stage's library entry point.
#include <map>
#include <string>
#include <vector>

namespace homesh {

/// One option a stage accepts, as listed: key, default value as text, help.
struct OptionSpec {
  std::string name;
  std::string default_value;
  std::string help;
};

/// A stage call parsed from "name:key=value:...": the stage name and the given pairs.
struct StageCall {
  std::string text;
  std::string name;
  std::map<std::string, std::string> given;
};

/// Parses one `-m` argument; throws homesh::Error on an empty name, an entry
/// without '=' or a repeated key.
StageCall parse_stage_call(const std::string& text);

}  // namespace homesh
