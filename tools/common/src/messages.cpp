#include "orb/cli/messages.h"

#include <iostream>

namespace orb::cli {
namespace {
std::string g_tool_name = "orb";
bool g_quiet = false;
}  // namespace

void set_tool_name(std::string name) { g_tool_name = std::move(name); }
const std::string& tool_name() { return g_tool_name; }
void set_quiet(bool q) { g_quiet = q; }
bool quiet() { return g_quiet; }

void error(const std::string& message) { std::cerr << g_tool_name << ": error: " << message << std::endl; }

void warning(const std::string& message) {
    if (!g_quiet) std::cerr << g_tool_name << ": warning: " << message << std::endl;
}

void info(const std::string& message) {
    if (!g_quiet) std::cerr << g_tool_name << ": " << message << std::endl;
}

}  // namespace orb::cli
