// Messages on stderr as "<tool>: error: ..." / "<tool>: warning: ...".
#pragma once

#include <functional>
#include <string>

namespace orb::cli {

void set_tool_name(std::string name);
const std::string& tool_name();
void set_quiet(bool quiet);  // silences warnings and progress, never errors
bool quiet();

void error(const std::string& message);
void warning(const std::string& message);
// Where warnings go instead of stderr while set (an embedding such as the
// Python module turns them into its own warnings); an empty function: stderr again.
void set_warning_sink(std::function<void(const std::string&)> sink);
void info(const std::string& message);  // progress-like notes, silenced by -q

}  // namespace orb::cli
