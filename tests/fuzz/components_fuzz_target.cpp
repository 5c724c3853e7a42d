#include "fuzz_targets.h"
#include "input_file.h"

#include "lsystem/components/component_graph.h"

namespace pf::fuzz {

void runComponentsInput(const uint8_t* data, size_t size) {
    try {
        // 64 MiB: an input may raise its own budgets, and 200 000 leaves within 256 MiB took 14 s in
        // this instrumented build (4 s in the release build): heavy, not stuck.
        (void)lsys::components::loadComponentPlant(writeInputFile(data, size, "components/input.comp.json"),
                                                   lsys::MemoryBudget{64ull << 20});
    } catch (const lsys::components::ComponentError&) {
        // A clear error naming file, line and column is the right outcome.
    } catch (const lsys::MemoryBudgetError&) {
        // So is a plant refused, before it is drawn, for the memory it would take.
    }
}

} // namespace pf::fuzz
