#include "orb/cli/tool_main.h"

#include <csignal>
#include <exception>
#include <iostream>

#include "orb/cli/messages.h"
#include "orb/cli/paths.h"
#include "orb/scene/error.h"

namespace orb::cli {

int run_tool(int argc, char** argv, const std::string& name, const std::string& description,
             const std::function<void(CLI::App&)>& configure, const std::function<int()>& body) {
    // A closed pipe downstream must end us with an error, not a silent SIGPIPE death
    // that leaves the pipeline's status unclear.
    std::signal(SIGPIPE, SIG_IGN);
    set_tool_name(name);
    CLI::App app{description, name};
    app.set_version_flag("--version", name + " (Orb) " + version_string());
    bool quiet_flag = false;
    app.add_flag("-q,--quiet", quiet_flag, "Print only errors");
    app.get_formatter()->column_width(34);
    try {
        configure(app);
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        error(e.what());
        std::cerr << "Run with --help for more information." << std::endl;
        return kUsage;
    }
    set_quiet(quiet_flag);
    try {
        return body();
    } catch (const UsageError& e) {
        error(e.what());
        return kUsage;
    } catch (const InputError& e) {
        error(e.what());
        return kFailure;
    } catch (const std::bad_alloc&) {
        error("out of memory");
        return kFailure;
    } catch (const std::exception& e) {
        error(e.what());
        return kFailure;
    }
}

}  // namespace orb::cli
