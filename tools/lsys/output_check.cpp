#include "tools/lsys/output_check.h"

#include <iostream>
#include <string>

#include "lsystem/common/output_file.h"

namespace tools {

bool outputRefused(std::span<const std::filesystem::path> outputs, const std::filesystem::path& input) {
    for (const std::filesystem::path& output : outputs)
        if (const std::string problem = lsys::outputPathProblem(output, {&input, 1}); !problem.empty()) {
            std::cerr << "lsys: error: " << problem << '\n';
            return true;
        }
    return false;
}

} // namespace tools
