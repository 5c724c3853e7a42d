// plantfield: the renderer's command-line front end.
#include "field_setup.h"
#include "modes.h"

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>

#include "lsystem/memory_budget.h"

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

} // namespace
} // namespace pf

int main(int argc, char** argv) {
    try {
        int exitCode = 0;
        const std::optional<pf::PlantfieldOptions> options = pf::parsePlantfieldOptions(argc, argv, &exitCode);
        if (!options) return exitCode;
        if (options->listDevices) return pf::listDevices(*options);
        if (options->physicsCheck) return pf::runPhysicsCheck(*options);
        return options->window ? pf::runWindow(*options) : pf::runHeadless(*options);
    } catch (const pf::SceneError& e) { // bad input, like a bad flag
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 2;
    } catch (const lsys::DerivationError& e) { // past a budget (memory, modules), like a scene too large
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
