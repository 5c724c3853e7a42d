#include "fuzz_targets.h"

#include "lsystem/common/error.h"
#include "lsystem/dialects/dialect.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/turtle.h"

#include <algorithm>
#include <exception>
#include <string_view>

namespace pf::fuzz {

void runLsysInput(const uint8_t* data, size_t size) {
    // Through the dialect entry point, so a "dialect:" first line fuzzes that translator too.
    const lsys::ParseResult parsed =
        lsys::parseDialect(std::nullopt, std::string_view(reinterpret_cast<const char*>(data), size));
    if (!parsed.ok()) return;
    lsys::DeriveOptions options;
    // Bounded work per input: a grammar may ask for a billion steps.
    options.steps = std::clamp(parsed.grammar.derivationLength, 0, 6);
    options.maxModules = 20000;
    options.threads = 1;
    try {
        const lsys::ModuleString derived = lsys::derive(parsed.grammar, options);
        (void)lsys::plantFromGrammar(parsed.grammar, derived);
    } catch (const lsys::DerivationError&) {
        // A clear error for over-budget or invalid derivations is the right outcome.
    } catch (const lsys::SurfaceError&) {
        // So is one for a ~name that is neither built in nor a mesh file.
    }
}

} // namespace pf::fuzz
