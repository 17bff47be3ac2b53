// Messages on stderr as "<tool>: error: ..." / "<tool>: warning: ...".
#pragma once

#include <string>

namespace orb::cli {

void set_tool_name(std::string name);
const std::string& tool_name();
void set_quiet(bool quiet);  // silences warnings and progress, never errors
bool quiet();

void error(const std::string& message);
void warning(const std::string& message);
void info(const std::string& message);  // progress-like notes, silenced by -q

}  // namespace orb::cli
