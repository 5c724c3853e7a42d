#include "arguments.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
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

std::string givenValue(py::handle value) {
    return py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value) ? std::string(py::repr(value))
                                                                                : typeName(value);
}

BoundArguments bindArguments(const std::string& function, const std::vector<Parameter>& parameters,
                             const py::args& args, const py::kwargs& kwargs, size_t skip) {
    BoundArguments bound{std::vector<py::handle>(parameters.size()), std::vector<bool>(parameters.size(), false)};
    const size_t positional = args.size() > skip ? args.size() - skip : 0;
    if (positional > parameters.size())
        throw py::type_error(function + "() takes at most " + std::to_string(parameters.size()) + " arguments (" +
                             std::to_string(positional) + " given)");
    for (size_t i = 0; i < positional; ++i) {
        bound.values[i] = args[skip + i];
        bound.given[i] = true;
    }
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        const auto at = std::find_if(parameters.begin(), parameters.end(),
                                     [&](const Parameter& parameter) { return parameter.name == name; });
        if (at == parameters.end())
            throw py::type_error(function + "() got an unexpected keyword argument '" + name + "'");
        const size_t i = size_t(at - parameters.begin());
        if (bound.given[i]) throw py::type_error(function + "() got multiple values for argument '" + name + "'");
        bound.values[i] = value;
        bound.given[i] = true;
    }
    for (size_t i = 0; i < parameters.size(); ++i)
        if (parameters[i].required && !bound.given[i])
            throw py::type_error(function + "() missing required argument '" + parameters[i].name + "'");
    return bound;
}

void setDocstring(py::handle function, py::handle typed) {
    const std::string doc = py::str(typed.attr("__doc__"));
    PyObject* object = function.ptr();
    if (PyInstanceMethod_Check(object)) object = PyInstanceMethod_GET_FUNCTION(object);
    if (!PyCFunction_Check(object)) return;
    auto* cfunction = reinterpret_cast<PyCFunctionObject*>(object);
    // pybind11 strdup'ed the one it installed, and frees it if an overload is chained later.
    std::free(const_cast<char*>(cfunction->m_ml->ml_doc));
    cfunction->m_ml->ml_doc = strdup(doc.c_str());
}

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
