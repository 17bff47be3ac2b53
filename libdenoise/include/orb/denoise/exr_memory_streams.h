// OpenEXR streams over memory: the tools read their inputs (files or
// standard input) into memory and write outputs through orb::cli::OutputFile,
// so the EXR codec never touches a file itself. Public for the render job,
// which reads the layers of an image it encoded (orb/job/render_job.h).
#pragma once

#include <OpenEXR/ImfIO.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace orb::denoise {

class MemoryInput final : public Imf::IStream {
public:
    MemoryInput(std::string_view bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override;  // throws Iex::InputExc past the end
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = position; }

private:
    std::string_view bytes_;
    uint64_t position_ = 0;
};

class MemoryOutput final : public Imf::OStream {
public:
    explicit MemoryOutput(std::string& bytes) : Imf::OStream("<memory>"), bytes_(bytes) {}
    void write(const char c[], int n) override;
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }

private:
    std::string& bytes_;
    uint64_t position_ = 0;
};

}  // namespace orb::denoise
