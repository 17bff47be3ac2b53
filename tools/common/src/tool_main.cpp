#include "orb/cli/tool_main.h"

#include <pthread.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <vector>

#include "orb/cli/help_formatter.h"
#include "orb/cli/help_wrapping.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/paths.h"
#include "orb/cli/version.h"
#include "orb/scene/error.h"

namespace orb::cli {

namespace {

// Ends the process as a tool that never ignored SIGPIPE would have been ended
// by its first write into the closed pipe: killed by SIGPIPE, with no message,
// which shells report as 141 and `set -o pipefail` scripts expect.
[[noreturn]] void end_by_broken_pipe() {
    std::signal(SIGPIPE, SIG_DFL);
    sigset_t pipe_only;
    sigemptyset(&pipe_only);
    sigaddset(&pipe_only, SIGPIPE);
    pthread_sigmask(SIG_UNBLOCK, &pipe_only, nullptr);
    std::raise(SIGPIPE);
    std::_Exit(128 + SIGPIPE);  // not reached: the default action ends the process
}

// CLI11 lists the arguments it did not expect in reverse ("0.002 --radius");
// the first of them on the command line says what went wrong: an option the
// tool does not have, or one argument too many (named with the argument
// that took its place: a file list the shell made of a quoted pattern).
std::string unexpected_arguments(const CLI::App& app, int argc, char** argv) {
    const std::vector<std::string> extras = app.remaining();
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (std::find(extras.begin(), extras.end(), argument) == extras.end()) continue;
        if (argument.size() > 1 && argument[0] == '-')
            return "unknown option " + argument.substr(0, argument.find('='));
        std::string after;  // the last argument taken, which this one came after
        for (const CLI::Option* positional : app.get_options([](const CLI::Option* o) { return o->get_positional(); }))
            if (positional->count() == 1 && positional->get_items_expected_max() == 1)
                after = " after " + positional->get_name() + " " + positional->results().front();
        return "unexpected argument '" + argument + "'" + after;
    }
    return "unexpected arguments";
}

int print_help(const std::string& text) {
    try {
        return print_to_stdout(text);
    } catch (const BrokenPipe&) {
        end_by_broken_pipe();
    }
}

}  // namespace

int run_tool(int argc, char** argv, const std::string& name, const std::string& description,
             const std::function<void(CLI::App&)>& configure, const std::function<int()>& body) {
    // A closed pipe downstream must not kill us mid-write: the write fails with
    // EPIPE instead, the stack unwinds (temporary files removed, locks released)
    // and end_by_broken_pipe() ends the process the conventional way.
    std::signal(SIGPIPE, SIG_IGN);
    set_tool_name(name);
    CLI::App app{description, name};
    app.formatter(std::make_shared<HelpFormatter>(help_width()));
    app.set_version_flag("--version", version_text(name));
    bool quiet_flag = false;
    app.add_flag("-q,--quiet", quiet_flag, "Print only errors");
    try {
        configure(app);
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        return print_help(app.help());
    } catch (const CLI::CallForAllHelp&) {
        return print_help(app.help("", CLI::AppFormatMode::All));
    } catch (const CLI::CallForVersion& e) {
        return print_help(e.what());
    } catch (const CLI::ExtrasError&) {
        error(unexpected_arguments(app, argc, argv));
        std::cerr << "Run with --help for more information." << std::endl;
        return kUsage;
    } catch (const CLI::ParseError& e) {
        error(e.what());
        std::cerr << "Run with --help for more information." << std::endl;
        return kUsage;
    }
    set_quiet(quiet_flag);
    // A BrokenPipe may reach us wrapped in another exception (a frame's
    // message, a worker thread's error): broken_pipe_seen() still tells.
    try {
        const int code = body();
        if (broken_pipe_seen()) end_by_broken_pipe();
        return code;
    } catch (const UsageError& e) {
        if (broken_pipe_seen()) end_by_broken_pipe();
        error(e.what());
        return kUsage;
    } catch (const InputError& e) {
        if (broken_pipe_seen()) end_by_broken_pipe();
        error(e.what());
        return kFailure;
    } catch (const std::bad_alloc&) {
        error("out of memory");
        return kFailure;
    } catch (const std::exception& e) {
        if (broken_pipe_seen()) end_by_broken_pipe();
        error(e.what());
        return kFailure;
    }
}

}  // namespace orb::cli
