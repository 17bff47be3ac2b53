#include "orb/exr/render_status.h"

#include <OpenEXR/openexr.h>

#include <filesystem>
#include <system_error>

#include "orb/exr/film_exr.h"
#include "orb/scene/error.h"

namespace orb::exr {
namespace {

// OpenEXR's core library reports errors through a callback; the status
// carries our own reason instead.
void ignore_error(exr_const_context_t, exr_result_t, const char*) {}

// Closes the context however the check returns.
struct ReadContext {
    exr_context_t context = nullptr;
    ~ReadContext() {
        if (context) exr_finish(&context);
    }
};

// Every block's recorded offset and size lie inside the file: what catches a
// file cut short anywhere without decoding it (Imf::InputFile::isComplete
// looks only at the offset table, which a file missing its last bytes still
// has whole). Empty when they do, else why not.
std::string blocks_outside_file(const std::string& path) {
    std::error_code ec;
    const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
    if (ec) return "unreadable: " + ec.message();
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = ignore_error;
    ReadContext read;
    exr_attr_box2i_t window{};
    int32_t lines_per_chunk = 0;
    if (exr_start_read(&read.context, path.c_str(), &init) != EXR_ERR_SUCCESS ||
        exr_get_data_window(read.context, 0, &window) != EXR_ERR_SUCCESS ||
        exr_get_scanlines_per_chunk(read.context, 0, &lines_per_chunk) != EXR_ERR_SUCCESS || lines_per_chunk < 1)
        return "unreadable EXR";
    for (long long y = window.min.y; y <= window.max.y; y += lines_per_chunk) {
        exr_chunk_info_t chunk{};
        if (exr_read_scanline_chunk_info(read.context, 0, static_cast<int>(y), &chunk) != EXR_ERR_SUCCESS ||
            chunk.data_offset > file_size || chunk.packed_size > file_size - chunk.data_offset)
            return "truncated or damaged (some scanlines are missing)";
    }
    return "";
}

}  // namespace

RenderStatus inspect_render(const std::string& path, RenderCheck check) {
    RenderStatus status;
    std::error_code ec;
    status.exists = std::filesystem::exists(path, ec);
    if (!status.exists) {
        status.reason = "no such file";
        return status;
    }
    ExrFilmSummary summary;
    try {
        summary = check == RenderCheck::Pixels ? read_film_exr_summary(path) : read_film_exr_header(path);
    } catch (const InputError& e) {
        // The message names the file first; the reason is what follows.
        const std::string message = e.what();
        status.reason = message.rfind(path + ": ", 0) == 0 ? message.substr(path.size() + 2) : message;
        return status;
    }
    if (check == RenderCheck::Structure) {
        status.reason = blocks_outside_file(path);
        if (!status.reason.empty()) return status;
    }
    status.readable = true;
    status.summary = std::move(summary);
    return status;
}

}  // namespace orb::exr
