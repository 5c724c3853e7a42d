// The readers of a vlab object's files (lsystem/vlab): the view file, the
// function files and sets, the surface files and the colour maps and
// material files. Each target feeds one input to every reader of its kind.
#include "fuzz_targets.h"
#include "input_file.h"

#include "lsystem/vlab/color_files.h"
#include "lsystem/vlab/function_file.h"
#include "lsystem/vlab/surface_file.h"
#include "lsystem/vlab/view_file.h"

#include <string_view>

namespace pf::fuzz {

namespace vlab = lsys::vlab;

void runViewInput(const uint8_t* data, size_t size) {
    // The text as the preprocessor would hand it on: the reader's own
    // scanning, without a cpp process per input (the lsys target runs cpp).
    (void)vlab::parseViewFile(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.v");
}

void runFuncInput(const uint8_t* data, size_t size) {
    const std::filesystem::path path = writeInputFile(data, size, "vlab/input.func");
    constexpr double kXs[] = {-1.0, 0.0, 0.3, 0.5, 0.999, 1.0, 2.0};
    // Without samples (bisection on every call) and with a view file's 100.
    for (const int samples : {-1, 100}) {
        const vlab::FunctionReadResult read = vlab::readFunctionFile(path, samples);
        for (const double x : kXs) (void)vlab::evaluateFunction(read.function, x);
    }
    for (const vlab::VlabFunction& function : vlab::readFunctionSet(path).functions)
        for (const double x : kXs) (void)vlab::evaluateFunction(function, x);
}

void runSurfaceInput(const uint8_t* data, size_t size) {
    const std::filesystem::path path = writeInputFile(data, size, "vlab/input.s");
    (void)vlab::readSurfaceFile(path, "s");                // the file's own precision
    (void)vlab::readSurfaceFile(path, "s", -2.0f, 10, 10); // a view file's, at cpfg's most
}

void runColorInput(const uint8_t* data, size_t size) {
    const std::filesystem::path path = writeInputFile(data, size, "vlab/input.map");
    (void)vlab::readColorMap(path);
    (void)vlab::readMaterialFile(path);
}

} // namespace pf::fuzz
