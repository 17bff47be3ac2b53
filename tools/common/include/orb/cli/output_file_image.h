// An output file of the tools (orb/cli/output_file.h: staged beside its
// target, renamed into place) as the render job writes its images
// (orb/job/image_output.h). Header only: the tools that render link the job
// library, the others never see it (target orb_cli_image_output).
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include "orb/cli/output_file.h"
#include "orb/job/image_output.h"

namespace orb::cli {

class OutputFileImage : public job::ImageOutput {
public:
    explicit OutputFileImage(OutputFile file) : file_(std::move(file)) {}
    void stage(std::string_view bytes) override { file_.stage(bytes); }
    void commit(std::string_view bytes) override { file_.commit(bytes); }
    std::string display_name() const override { return file_.display_name(); }
    std::string path() const override { return file_.path(); }

private:
    OutputFile file_;
};

}  // namespace orb::cli
