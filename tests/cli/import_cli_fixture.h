// The real orb-import run in a scratch folder of its own, for the CLI suites
// (plain, PLY and binary scenes): arguments and stdin in, exit code and
// output back, and what the folder holds afterwards.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_process.h"

namespace orb::test {

class ImportCliFixture : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // orb-import with these arguments, run inside the scratch folder.
    ProcessResult run(const std::vector<std::string>& args, const std::string& stdin_bytes = "") const;
    std::filesystem::path write(const std::string& name, const std::string& bytes) const;
    // Everything in the scratch folder, hidden temporaries included, sorted.
    std::vector<std::string> files() const;

    std::filesystem::path dir_;
};

}  // namespace orb::test
