#include "arguments.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "lsystem/common/output_file.h"
#include "lsystem/language/grammar.h"

namespace py = pybind11;

namespace pyargs {
namespace {

// Appended to with the GIL released (loads run without it), hence the lock.
std::mutex sessionInputsMutex;
std::vector<std::filesystem::path>& sessionInputs() {
    static std::vector<std::filesystem::path> inputs;
    return inputs;
}

} // namespace

std::string typeName(py::handle value) { return py::str(py::type::handle_of(value).attr("__name__")); }

void checkSteps(const std::optional<int>& steps) {
    if (steps && (*steps < 0 || *steps > lsys::kMaxDerivationLength))
        throw py::value_error("steps must be 0 to " + std::to_string(lsys::kMaxDerivationLength) + ", not " +
                              std::to_string(*steps));
}

void checkDefines(const std::unordered_map<std::string, double>& defines) {
    for (const auto& [name, value] : defines)
        if (!std::isfinite(value)) throw py::value_error("defines['" + name + "'] must be a finite number");
}

SessionReads::~SessionReads() {
    const std::lock_guard lock(sessionInputsMutex);
    std::vector<std::filesystem::path>& inputs = sessionInputs();
    for (const std::filesystem::path& path : log_.paths())
        if (std::find(inputs.begin(), inputs.end(), path) == inputs.end()) inputs.push_back(path);
}

void checkOutput(const std::filesystem::path& path, const char* name) {
    std::string problem;
    {
        const std::lock_guard lock(sessionInputsMutex);
        problem = lsys::outputPathProblem(path, sessionInputs());
    }
    if (!problem.empty())
        throw py::value_error(std::string(name) + ": cannot write '" + path.string() + "': " + problem);
}

} // namespace pyargs
