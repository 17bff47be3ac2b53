// Which format orb-import writes: --to, else the output file's extension
// (.scn: SmallptGPU, .orb: the binary scene, anything else Orb JSON).
#pragma once

#include <string>

namespace orb::import_tool {

enum class OutputFormat { OrbJson, Scn, OrbBinary };

// `to` is the --to value ("" when not given), `output` the -o path.
// Throws orb::cli::UsageError for an output named like a format Orb cannot write.
OutputFormat choose_output_format(const std::string& to, const std::string& output);

}  // namespace orb::import_tool
