#include "orb/exr/render_status.h"

#include <OpenEXR/openexr.h>

#include <filesystem>
#include <system_error>

#include "exr_attributes.h"

namespace orb::exr {
namespace {

// OpenEXR's core library reports errors through a callback; the status
// carries our own reason instead.
void ignore_error(exr_const_context_t, exr_result_t, const char*) {}

// Closes the context however inspect_render returns.
struct ReadContext {
    exr_context_t context = nullptr;
    ~ReadContext() {
        if (context) exr_finish(&context);
    }
};

// Every chunk's recorded offset and size lie inside the file: the check that
// catches a file cut short anywhere (Imf::InputFile::isComplete only looks at
// the offset table, which a file missing its last bytes still has whole).
bool chunks_inside_file(exr_const_context_t context, const exr_attr_box2i_t& window, std::uintmax_t file_size) {
    int32_t lines_per_chunk = 0;
    if (exr_get_scanlines_per_chunk(context, 0, &lines_per_chunk) != EXR_ERR_SUCCESS || lines_per_chunk < 1)
        return false;
    for (long long y = window.min.y; y <= window.max.y; y += lines_per_chunk) {
        exr_chunk_info_t chunk{};
        if (exr_read_scanline_chunk_info(context, 0, static_cast<int>(y), &chunk) != EXR_ERR_SUCCESS) return false;
        if (chunk.data_offset > file_size || chunk.packed_size > file_size - chunk.data_offset) return false;
    }
    return true;
}

}  // namespace

RenderStatus inspect_render(const std::string& path) {
    RenderStatus status;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        status.reason = "no such file";
        return status;
    }
    if (!std::filesystem::is_regular_file(path, ec)) {
        status.reason = "not a regular file";
        return status;
    }
    const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
    if (ec) {
        status.reason = "unreadable: " + ec.message();
        return status;
    }

    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = ignore_error;
    ReadContext read;
    if (exr_start_read(&read.context, path.c_str(), &init) != EXR_ERR_SUCCESS) {
        status.reason = "not an orb-render EXR (not a readable OpenEXR file)";
        return status;
    }
    exr_storage_t storage{};
    int32_t parts = 0;
    if (exr_get_count(read.context, &parts) != EXR_ERR_SUCCESS || parts != 1 ||
        exr_get_storage(read.context, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE) {
        status.reason = "not an orb-render EXR (orb-render writes one scanline part)";
        return status;
    }
    int32_t spp = 0, target = 0;
    if (exr_attr_get_int(read.context, 0, attr::kSpp, &spp) != EXR_ERR_SUCCESS ||
        exr_attr_get_int(read.context, 0, attr::kTargetSpp, &target) != EXR_ERR_SUCCESS || spp < 1 || target < 1) {
        status.reason = "not an orb-render EXR (no orb:spp and orb:targetSpp)";
        return status;
    }
    status.spp = static_cast<std::uint64_t>(spp);
    status.target_spp = static_cast<std::uint64_t>(target);
    // Files from before sample slices (film format 1) hold the samples 0 ... spp-1.
    const char* ranges = nullptr;
    int32_t ranges_length = 0;
    if (exr_attr_get_string(read.context, 0, attr::kSampleRanges, &ranges_length, &ranges) == EXR_ERR_SUCCESS &&
        ranges && ranges_length >= 0)
        status.sample_ranges.assign(ranges, static_cast<std::size_t>(ranges_length));
    else
        status.sample_ranges = "0:" + std::to_string(status.spp);
    exr_attr_box2i_t window{};
    if (exr_get_data_window(read.context, 0, &window) != EXR_ERR_SUCCESS || window.max.x < window.min.x ||
        window.max.y < window.min.y) {
        status.reason = "not an orb-render EXR (no data window)";
        return status;
    }
    status.width = static_cast<int>(static_cast<long long>(window.max.x) - window.min.x + 1);
    status.height = static_cast<int>(static_cast<long long>(window.max.y) - window.min.y + 1);
    if (!chunks_inside_file(read.context, window, file_size)) {
        status.reason = "truncated or damaged (some scanlines are missing)";
        return status;
    }
    if (status.spp < status.target_spp) {
        status.reason = "stopped at " + std::to_string(status.spp) + " of " + std::to_string(status.target_spp) +
                        " samples per pixel";
        return status;
    }
    status.complete = true;
    return status;
}

}  // namespace orb::exr
