// The checks every binding of the module makes on its arguments before any
// work, so that a bad argument raises a Python exception instead of reaching
// C++ that assumes it valid (a None grammar was a null pointer): TypeError
// naming the argument for a wrong type, ValueError for a value out of range.
// And the output rule (lsystem/common/output_file.h) for the module's writers:
// the session's inputs are every file the module read since it was imported,
// so `write_png(render(scene), scene)` is refused like `plantfield --capture
// SCENE` is.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include <pybind11/pybind11.h>

#include "lsystem/common/file_reader.h"

namespace pyargs {

// "NoneType", "float", "str": the Python type of `value`, for messages.
std::string typeName(pybind11::handle value);

// `value` as the bound class T, or TypeError "NAME must be EXPECTED, not TYPE".
template <class T>
std::shared_ptr<T> objectArgument(pybind11::handle value, const char* name, const char* expected) {
    if (!pybind11::isinstance<T>(value))
        throw pybind11::type_error(std::string(name) + " must be " + expected + ", not " + typeName(value));
    return value.cast<std::shared_ptr<T>>();
}

// steps: none, or 0 to the longest derivation a plant file may ask for.
void checkSteps(const std::optional<int>& steps);

// defines: values that are finite numbers.
void checkDefines(const std::unordered_map<std::string, double>& defines);

// While alive, records the files the thread reads (a lsys::ReadFileLog);
// closing adds them to the session's inputs, which no writer replaces.
class SessionReads {
public:
    SessionReads() = default;
    SessionReads(const SessionReads&) = delete;
    SessionReads& operator=(const SessionReads&) = delete;
    ~SessionReads();

private:
    lsys::ReadFileLog log_;
};

// ValueError "NAME: cannot write 'PATH': REASON" when `path` is not a file
// a writer may replace (a folder, a device, a file the session read).
void checkOutput(const std::filesystem::path& path, const char* name);

} // namespace pyargs
