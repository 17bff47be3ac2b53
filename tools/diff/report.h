// orb-diff's reports: a human summary and the --json document.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "gates.h"
#include "orb/image/compare.h"

namespace orb::diff {

struct PassResult {
    orb::image::PassComparison comparison;
    Outcome outcome;
};

std::string summary_line(const PassResult& result, const Gates& gates);

nlohmann::json pass_json(const PassResult& result, const Gates& gates);
nlohmann::json gates_json(const Gates& gates);

}  // namespace orb::diff
