// --claim: processes on several machines that share an output folder split
// an animation without a scheduler, as Blender's placeholders do: a frame is
// rendered by whoever creates its claim file (OUT.claim, with O_CREAT|O_EXCL)
// first. The claim names its host and process and is refreshed while the
// frame renders, so a claim whose process died is taken over: at once on the
// same host (the process is gone), after `stale_after` seconds without a
// refresh from another host.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>

namespace orb::job {

class FrameClaim {
public:
    // Claims `output`. Returns nothing when a live claim holds it, and then
    // sets `holder` to its "host HOST pid PID" line.
    static std::optional<FrameClaim> acquire(const std::string& output, double stale_after, std::string& holder);

    FrameClaim(FrameClaim&& other) noexcept;
    FrameClaim& operator=(FrameClaim&& other) noexcept;
    FrameClaim(const FrameClaim&) = delete;
    FrameClaim& operator=(const FrameClaim&) = delete;
    ~FrameClaim();  // removes the claim file if it is still this one

    // Marks the claim alive (its modification time); at most once a second.
    void refresh();
    const std::string& path() const { return path_; }

private:
    FrameClaim(std::string path, int fd);
    void release() noexcept;

    std::string path_;
    int fd_ = -1;
    dev_t device_ = 0;
    ino_t inode_ = 0;
    double last_refresh_ = 0;
};

// OUT.claim for an output OUT.
std::string claim_path(const std::string& output);

}  // namespace orb::job
