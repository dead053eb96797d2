#include "core/cli/model_input.h"

#include <iostream>

#include "core/anneal/rules/clearance_index.h"
#include "core/io/model_io.h"

namespace zomeify::cli {

void warn_of_clashes(const ZomeModel& model, const std::string& source)
{
    const ClearanceReport clearance = clearance_report(model);
    if (clearance.total() > 0)
        std::cerr << "warning: " << source << ": " << clearance_summary(clearance)
                  << " (parts closer than real Zometool allows)\n";
}

ZomeModel read_model_warning_of_clashes(const std::string& path)
{
    std::vector<std::string> notes;
    ZomeModel model = read_model_file(path, &notes);
    for (const std::string& note : notes)
        std::cerr << "note: " << path << ": " << note << "\n";
    warn_of_clashes(model, path);
    return model;
}

} // namespace zomeify::cli
