// One output of a tool, prepared before any work starts and written so that
// no data is ever destroyed (docs/outputs.md):
//   - "-" is standard output;
//   - a character or block device, a FIFO, a socket or any other existing
//     non-regular file is written straight into (streamed, never replaced:
//     "-o /dev/null" leaves the device node alone);
//   - anything else is a regular file, new or existing, possibly behind a
//     symbolic link: the bytes go to a temporary sibling of the link's
//     *target*, are flushed to disk and checked, then renamed over the target,
//     so the link stays a link and a previous good file survives any failure.
// Preparing a file output takes an advisory lock next to it (a second
// process writing the same output fails at once) and creates its temporary
// file, so a missing or unwritable folder is an error before an hour of work.
#pragma once

#include <string>
#include <string_view>

#include "orb/cli/detail/held_lock.h"

namespace orb::cli {

class OutputFile {
public:
    enum class Kind { Stdout, Stream, File };

    // `option` names the output in messages ("-o", "--stats-json").
    // Throws orb::InputError (exit 1) when the output cannot be written.
    OutputFile(std::string path, std::string option);
    ~OutputFile();  // removes an unused temporary file and releases the lock
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;

    // Replaces the whole content with `bytes`; for files this may be called
    // again (checkpoints), each call atomic. Throws std::runtime_error naming
    // the file on any error; a file's previous content is then untouched.
    void write(std::string_view bytes);
    // write() in two steps, for a writer that makes several files at once
    // but puts them in place in order: stage() writes a file's bytes to its
    // temporary file and flushes them to disk, commit() renames that into
    // place. A stream (or stdout) is written by commit() alone, so `bytes`
    // must be the same in both calls. Each throws as write() does; after a
    // failure the previous content is untouched and no temporary file stays.
    void stage(std::string_view bytes);
    void commit(std::string_view bytes);

    Kind kind() const { return kind_; }
    const std::string& path() const { return path_; }
    const std::string& option() const { return option_; }
    // "<stdout>" or the path, for messages.
    std::string display_name() const;
    // What kind of file a Stream output is ("a character device", "a FIFO", ...).
    const std::string& stream_description() const { return stream_description_; }

    // Removes the lock beside `path` that a process which died while writing
    // it left (same host, pid gone), for a tool that finds an output it will
    // not write (orb-render --skip-existing skipping a finished frame). Best
    // effort: errors are ignored.
    static void remove_stale_lock(const std::string& path) noexcept;

private:
    void write_stream(std::string_view bytes);
    void open_temporary();
    void discard_temporary() noexcept;
    void release() noexcept;

    std::string path_;    // as given
    std::string option_;
    Kind kind_ = Kind::File;
    std::string target_;  // File: symbolic links resolved; Stream: the path to open
    std::string stream_description_;
    detail::HeldLock held_lock_;
    int temp_fd_ = -1;
    std::string temp_path_;
};

}  // namespace orb::cli
