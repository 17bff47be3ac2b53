// Where the render job writes an image: the front end's output (orb-render's
// is orb::cli::OutputFile, which writes a temporary file and renames it into
// place under a lock), so that the job never decides how files are written.
#pragma once

#include <string>
#include <string_view>

namespace orb::job {

class ImageOutput {
public:
    virtual ~ImageOutput() = default;
    // Replaces the output with these bytes, whole or not at all; may be
    // called again (checkpoints). Throws std::runtime_error naming the output.
    virtual void write(std::string_view bytes) = 0;
    virtual std::string display_name() const = 0;  // how messages name it
    virtual std::string path() const = 0;          // what --stats-json records ("-": standard output)
};

}  // namespace orb::job
