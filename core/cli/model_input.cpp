#include "core/cli/model_input.h"

#include <iostream>

#include "core/anneal/clearance_index.h"
#include "core/io/model_io.h"

namespace zomeify::cli {

ZomeModel read_model_warning_of_clashes(const std::string& path)
{
    ZomeModel model = read_model_file(path);
    const ClearanceReport clearance = clearance_report(model);
    if (clearance.total() > 0)
        std::cerr << "warning: " << path << ": " << clearance_summary(clearance)
                  << " (parts closer than real Zometool allows)\n";
    return model;
}

} // namespace zomeify::cli
