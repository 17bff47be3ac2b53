#include "orb/cli/messages.h"

#include <iostream>

#include "orb/scene/error.h"

namespace orb::cli {
namespace {
std::string g_tool_name = "orb";
bool g_quiet = false;
std::function<void(const std::string&)> g_warning_sink;

// Each line in one write, so that lines from several threads (orb-render's
// frame writers) never interleave within a line; the bytes of an input a
// message quotes are escaped where they are not text (orb::printable).
void say(const char* kind, const std::string& message) {
    std::cerr << (g_tool_name + ": " + kind + printable(message) + "\n") << std::flush;
}
}  // namespace

void set_tool_name(std::string name) { g_tool_name = std::move(name); }
const std::string& tool_name() { return g_tool_name; }
void set_quiet(bool q) { g_quiet = q; }
bool quiet() { return g_quiet; }

void error(const std::string& message) { say("error: ", message); }

void set_warning_sink(std::function<void(const std::string&)> sink) { g_warning_sink = std::move(sink); }

void warning(const std::string& message) {
    if (g_warning_sink) return g_warning_sink(message);
    if (!g_quiet) say("warning: ", message);
}

void info(const std::string& message) {
    if (!g_quiet) say("", message);
}

}  // namespace orb::cli
