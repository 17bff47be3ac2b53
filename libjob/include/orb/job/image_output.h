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
    void write(std::string_view bytes) {
        stage(bytes);
        commit(bytes);
    }
    // write() in two steps, for a writer that makes several outputs at once
    // but puts them in place in order (orb/job/ordered_writes.h): stage()
    // writes the bytes beside the output and flushes them to disk, commit()
    // puts them in place (a stream is written by commit() alone, so `bytes`
    // are the same in both calls). Each throws as write() does; after a
    // failure the output's previous content is untouched.
    virtual void stage(std::string_view bytes) = 0;
    virtual void commit(std::string_view bytes) = 0;
    virtual std::string display_name() const = 0;  // how messages name it
    virtual std::string path() const = 0;          // what --stats-json records ("-": standard output)
};

}  // namespace orb::job
