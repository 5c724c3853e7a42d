// A program outside the project, built against an installed plantfield
// (tests/install/install_test.sh): parses and derives an L-system, then
// writes the plant as glTF, which links the libraries' private dependencies.
// Usage: consumer OUT.glb. Prints "modules N" and exits 0 when all went well.
#include "lsystem/export/plant_export.h"
#include "lsystem/language/parser.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: consumer OUT.glb\n";
        return 2;
    }
    const lsys::ParseResult parsed = lsys::parseLsystem("angle: 25\nAxiom: F\nF --> F[+F]F\n");
    if (!parsed.ok()) {
        std::cerr << "parse failed\n";
        return 1;
    }
    lsys::DeriveOptions options;
    options.steps = 3;
    const lsys::ModuleString derived = lsys::derive(parsed.grammar, options);
    std::cout << "modules " << derived.size() << "\n";
    // F -> F[+F]F three times: 27 F and 39 brackets and turns.
    if (derived.size() != 66) return 1;

    const lsys::PlantAsset plant = lsys::plantFromGrammar(parsed.grammar, derived);
    lsys::exportPlant(plant, argv[1]);
    if (!std::filesystem::is_regular_file(argv[1]) || std::filesystem::file_size(argv[1]) == 0) {
        std::cerr << "no glTF written\n";
        return 1;
    }
    std::cout << "wrote " << argv[1] << "\n";
    return 0;
}
