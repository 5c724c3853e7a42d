#include "fuzz_targets.h"
#include "input_file.h"

#include "lsystem/components/component_graph.h"

namespace pf::fuzz {

void runComponentsInput(const uint8_t* data, size_t size) {
    try {
        (void)lsys::components::loadComponentPlant(writeInputFile(data, size, "components/input.comp.json"),
                                                   lsys::MemoryBudget{256ull << 20});
    } catch (const lsys::components::ComponentError&) {
        // A clear error naming file, line and column is the right outcome.
    } catch (const lsys::MemoryBudgetError&) {
        // So is a plant refused, before it is drawn, for the memory it would take.
    }
}

} // namespace pf::fuzz
