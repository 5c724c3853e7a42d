// plantbench: how the field frame's cost grows with the number of plants
// (docs/PLANTBENCH.md).
#include "plantbench_options.h"
#include "plot.h"
#include "report.h"
#include "sweep.h"

#include "engine/scene/scene.h"
#include "lsystem/common/file_reader.h"
#include "lsystem/common/output_file.h"

#include "tools/crash_report.h"
#include <exception>
#include <iostream>
#include <new>

namespace pf {
namespace {

void writeOutputs(const PlantbenchOptions& o, const SweepResult& result) {
    if (!o.plotPath.empty()) drawPlot(o, result);
    if (!o.jsonPath.empty()) writeTextFile(o.jsonPath, sweepJson(o, result).dump(2) + "\n");
    if (!o.csvPath.empty()) writeTextFile(o.csvPath, sweepCsv(o, result));
    for (const std::string* path : {&o.jsonPath, &o.csvPath, &o.plotPath})
        if (!path->empty()) std::cerr << "plantbench: wrote " << *path << "\n";
}

int run(const PlantbenchOptions& o) {
    GpuContext ctx;
    GpuOptions gpu;
    gpu.validation = o.validation;
    gpu.deviceName = o.deviceName;
    gpu.hostMemoryLimit = o.memory.limitBytes;
    SweepResult result;
    int exitCode = 0;
    try {
        Scene scene = loadScene(o.scenePath, o.memory); // before the device: a bad scene is bad input
        if (o.seed) scene.seed = *o.seed;
        createHeadlessContext(ctx, gpu);
        runSweep(o, scene, ctx, result);
    } catch (const SceneError& e) { // bad input, like a bad flag
        std::cerr << "plantbench: error: " << e.what() << "\n";
        exitCode = 2;
    } catch (const lsys::DerivationError& e) { // past a budget (memory, modules), like a scene too large
        std::cerr << "\nplantbench: error: " << e.what() << "\n";
        exitCode = 2;
    } catch (const DeviceLimitError& e) { // work the device cannot take, like a scene too large
        std::cerr << "\nplantbench: error: " << e.what() << "\n";
        exitCode = 2;
    } catch (const std::bad_alloc&) { // a stage the memory budget does not count
        std::cerr << "\nplantbench: error: out of memory (measure fewer plants or set a lower --memory-budget)\n";
        exitCode = 2;
    } catch (const std::exception& e) {
        std::cerr << "\nplantbench: error: " << e.what() << "\n";
        exitCode = 1;
    }
    destroyContext(ctx);
    if (exitCode != 0) {
        if (!result.counts.empty()) {
            std::cerr << "plantbench: measured before the failure (no output files written):\n";
            printSummaryTable(std::cerr, o, result);
        }
        return exitCode;
    }
    printSummaryTable(std::cout, o, result);
    writeOutputs(o, result);
    return 0;
}

} // namespace
} // namespace pf

int main(int argc, char** argv) {
    tools::reportCrashes("plantbench");
    // Every file the run reads, which no output may replace (outputsProblem).
    const lsys::ReadFileLog runInputs;
    try {
        int exitCode = 0;
        const std::optional<pf::PlantbenchOptions> options = pf::parsePlantbenchOptions(argc, argv, &exitCode);
        if (!options) return exitCode;
        return pf::run(*options);
    } catch (const lsys::OutputRefusedError& e) { // writing the outputs: onto an input, a folder or a device
        std::cerr << "plantbench: error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) { // writing the outputs
        std::cerr << "plantbench: error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "plantbench: error: " << e.what() << "\n";
        return 1;
    }
}
