// plantfield: the renderer's command-line front end.
#include "field_export.h"
#include "field_setup.h"
#include "modes.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

#include "lsystem/common/file_reader.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/common/output_file.h"
#include "tools/crash_report.h"

namespace pf {
namespace {

int listDevices(const PlantfieldOptions& o) {
    GpuContext ctx;
    createInstance(ctx, gpuOptions(o));
    for (const PhysicalDeviceInfo& d : listPhysicalDevices(ctx.instance))
        std::printf("%s (%s, Vulkan %u.%u)\n", d.name.c_str(), d.type.c_str(), VK_API_VERSION_MAJOR(d.apiVersion),
                    VK_API_VERSION_MINOR(d.apiVersion));
    destroyContext(ctx);
    return 0;
}

// --export / --export-placements: the field built on the CPU and written out;
// no Vulkan instance or device is created.
int runExport(const PlantfieldOptions& o) {
    // The glTF bakes the models' plants again (field_export.h); placements need none.
    const FieldContent content =
        loadFieldContent(o, nullptr, o.exportPath.empty() ? ModelAssets::Drop : ModelAssets::Keep);
    if (!o.exportPath.empty()) {
        const auto start = std::chrono::steady_clock::now();
        FieldExportOptions options;
        options.gpuInstancing = o.gpuInstancing;
        options.memory = o.memory;
        const FieldExportSummary written = exportField(content, o.exportPath, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "plantfield: %s: %zu plants%s, %zu meshes, %zu nodes, %zu materials, %.1f MiB in %.2f s\n",
                     o.exportPath.c_str(), written.plants, o.gpuInstancing ? " (EXT_mesh_gpu_instancing)" : "",
                     written.meshes, written.nodes, written.materials,
                     double(std::filesystem::file_size(o.exportPath)) / (1024.0 * 1024.0), seconds);
    }
    if (!o.placementsPath.empty()) {
        exportPlacements(content, o.placementsPath);
        std::fprintf(stderr, "plantfield: %s: %zu plants\n", o.placementsPath.c_str(), content.plants.size());
    }
    return 0;
}

} // namespace
} // namespace pf

int main(int argc, char** argv) {
    tools::reportCrashes("plantfield");
    // Every file the run reads, which no output may replace (output_check.h).
    const lsys::ReadFileLog runInputs;
    try {
        int exitCode = 0;
        const std::optional<pf::PlantfieldOptions> options = pf::parsePlantfieldOptions(argc, argv, &exitCode);
        if (!options) return exitCode;
        if (options->listDevices) return pf::listDevices(*options);
        if (options->physicsCheck) return pf::runPhysicsCheck(*options);
        if (pf::exportsField(*options)) return pf::runExport(*options);
        return options->window ? pf::runWindow(*options) : pf::runHeadless(*options);
    } catch (const pf::SceneError& e) { // bad input, like a bad flag
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 2;
    } catch (const lsys::DerivationError& e) { // past a budget (memory, modules), like a scene too large
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 2;
    } catch (const lsys::OutputRefusedError& e) { // an output onto an input, a folder or a device
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 2;
    } catch (const pf::DeviceLimitError& e) { // work the device cannot take, like a scene too large
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) { // a stage the memory budget does not count
        std::cerr << "plantfield: error: out of memory (a smaller scene, fewer --instances or a --memory-budget)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 1;
    }
}
