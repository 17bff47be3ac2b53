#include "orb/cli/io.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"
#include "orb/scene/error.h"

namespace fs = std::filesystem;

namespace orb::cli {
namespace {
std::atomic<bool> g_broken_pipe{false};
}  // namespace

void throw_broken_pipe(const std::string& where) {
    g_broken_pipe = true;
    throw BrokenPipe(where);
}

bool broken_pipe_seen() { return g_broken_pipe; }

bool is_stdio(const std::string& path) { return path == "-"; }

std::string read_input(const std::string& path) {
    if (is_stdio(path)) {
        std::string data;
        char buffer[1 << 16];
        size_t n;
        while ((n = std::fread(buffer, 1, sizeof buffer, stdin)) > 0) data.append(buffer, n);
        if (std::ferror(stdin)) throw InputError("<stdin>: read error");
        return data;
    }
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, expected a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path + ": read error");
    return data;
}

int print_to_stdout(const std::string& text) {
    errno = 0;
    std::fwrite(text.data(), 1, text.size(), stdout);
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        if (errno == EPIPE) throw_broken_pipe("<stdout>");
        error("cannot write to stdout");
        return kFailure;
    }
    return kSuccess;
}

}  // namespace orb::cli
