#include "orb/cli/io.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>

#include "orb/scene/error.h"

namespace fs = std::filesystem;

namespace orb::cli {

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

namespace {

// A unique hidden sibling of `path` keeping its extension, e.g. dir/.out.exr.tmp-1a2b.exr
std::string temporary_sibling(const std::string& path) {
    fs::path target(path);
    std::random_device rd;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp-%08x", static_cast<unsigned>(rd()));
    fs::path tmp = target.parent_path() /
                   ("." + target.filename().string() + suffix + target.extension().string());
    return tmp.string();
}

void write_all_to_stdout(std::string_view bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(STDOUT_FILENO, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(std::string("<stdout>: write error: ") + std::strerror(errno));
        }
        done += static_cast<size_t>(n);
    }
}

}  // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string&)>& writer) {
    fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw std::runtime_error(path + ": cannot write: directory " + parent.string() + " does not exist");
    const std::string tmp = temporary_sibling(path);
    try {
        writer(tmp);
        fs::rename(tmp, path);
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
}

void write_output(const std::string& path, std::string_view bytes) {
    if (is_stdio(path)) {
        write_all_to_stdout(bytes);
        return;
    }
    write_file_atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot write: " + std::strerror(errno));
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) throw std::runtime_error(path + ": write error");
    });
}

void write_output_via_file(const std::string& path, const std::function<void(const std::string&)>& writer,
                           const std::string& stdout_extension) {
    if (!is_stdio(path)) {
        write_file_atomically(path, writer);
        return;
    }
    fs::path tmp = fs::temp_directory_path() / fs::path(temporary_sibling("orb-stdout" + stdout_extension)).filename();
    std::error_code ec;
    try {
        writer(tmp.string());
        std::ifstream in(tmp, std::ios::binary);
        std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        write_all_to_stdout(data);
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::remove(tmp, ec);
}

}  // namespace orb::cli
