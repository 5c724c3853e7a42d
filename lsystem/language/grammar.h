#pragma once
// The parsed form of an L-system: header settings, axiom and the three
// production tables (rules, decomposition, interpretation).

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/language/expression.h"
#include "lsystem/language/plant_look.h"
#include "lsystem/language/statements.h"
#include "lsystem/language/symbols.h"

namespace lsys {

// A module of a predecessor or context: its parameters bind the formal
// variables firstVariable .. firstVariable+paramCount-1 of the production.
struct PatternModule {
    SymbolId symbol = 0;
    uint16_t paramCount = 0;
    uint16_t firstVariable = 0;
};

struct SuccessorModule {
    SymbolId symbol = 0;
    std::vector<Expression> arguments;
};

struct Production {
    std::string label;
    int line = 0;
    std::vector<PatternModule> left; // left context, in string order
    PatternModule strict;            // the module being replaced
    // cpfg's strict predecessors of several modules: the ones after `strict`,
    // matched where they stand and replaced with it by the successor.
    std::vector<PatternModule> strictTail;
    std::vector<PatternModule> right;   // right context, may contain [ and ]
    std::vector<std::string> variables; // formal parameters, then the blocks' local variables
    uint16_t formalCount = 0;           // of variables; the rest are locals
    // Where a derivation keeps the locals from one application to the next
    // (cpfg's rule): their first index into its Grammar::localCount values.
    uint32_t firstLocal = 0;
    Block before; // cpfg's statements before the condition, when the predecessor matches
    std::optional<Expression> condition;
    Block after; // and after it, when it holds
    std::vector<SuccessorModule> successor;
    // Stochastic productions: the first of a group holds groupSize, the number
    // of consecutive alternatives (itself included); the others hold 0.
    double probability = 1.0;
    bool stochastic = false;
    uint32_t groupSize = 1;
    bool usesRandom = false; // condition, probability choice or arguments draw random numbers
};

struct ProductionSet {
    std::vector<Production> productions; // file order
    // Per symbol, the productions to try in order (group leaders only).
    std::vector<std::vector<uint32_t>> bySymbol;
    int maxDepth = 1; // decomposition / interpretation passes
    bool producesParameters = false;
    bool contextSensitive = false;
    bool consumesSeveral = false; // a strict predecessor of several modules: rewritten on one thread, left to right
    bool empty() const { return productions.empty(); }
};

// cpfg's movements (Měch's tropisms, cpfg movements.c), a vlab view file's
// `tropism:` and `torque:` lines: before every F, G, f and g a tropism turns
// the heading toward its direction T (or, at an angle γ, toward the cone of
// headings at γ from T) by its elasticity, all tropisms together; a twist
// (torque) turns the up vector toward T about the heading. Each turtle state
// carries the movements' current elasticities, which @Ti, @Td and @Ts change.
inline constexpr size_t kMaxMovements = 10; // cpfg's MAXMOVEMENTS
enum class MovementKind : uint8_t { Tropism, Twist };
struct Movement {
    MovementKind kind = MovementKind::Tropism;
    glm::vec3 direction{0.0f, 1.0f, 0.0f}; // T: unit length times the intensity (I:, at most 1)
    float angle = 0.0f;                    // γ (A:), degrees: 0 toward T, 90 perpendicular to it
    float elasticity = 0.0f;               // at the start of the plant (E:)
    float increment = 0.0f;                // of @Ti and @Td without a value (S:)
};

// How the turtle draws beyond angle, step and width: ABOP's turtle unless a
// vlab object's view and colour files say otherwise (lsystem/vlab/object.h).
struct TurtleStyle {
    double widthFactor = 0.7;    // a bare ! multiplies the width by it, a bare # divides by it,
    double widthIncrement = 0.0; // then ! subtracts this and # adds it (cpfg's "line width increment")
    int colorIncrement = 1;      // a bare ; adds it to the material index, a bare , subtracts it
    uint32_t material = 0;       // the material index the plant starts with
    glm::vec3 tropism{0.0f, -1.0f, 0.0f};
    double elasticity = 0.0;
    // Widths are cpfg's screen pixels ("initial line width: 2 pixels"):
    // interpretPlant turns them into lengths (widenPixelLines, lsystem/turtle/turtle.h).
    bool pixelLines = false;
    // cpfg's turtle ("turtle modules: cpfg", which cpfg's files set): G and g
    // draw and move without a polygon vertex and @M and @R place the turtle
    // (elsewhere all four are ordinary modules), tropism bends as cpfg's, ?U
    // answers cpfg's up vector.
    bool cpfgModules = false;
    std::vector<Movement> movements; // at most kMaxMovements
    PlantLook look;
};

// The most derivation steps a file's 'derivation length:' or a tool's -n asks for.
inline constexpr int kMaxDerivationLength = 1'000'000;

struct Grammar {
    std::string file;
    SymbolTable symbols;
    std::unordered_map<std::string, double> constants;
    uint64_t seed = 0;
    int derivationLength = 0;
    double angle = 45.0; // degrees, default for bare + - & ^ \ /
    double step = 1.0;   // default length for bare F f
    double width = 1.0;  // initial width
    TurtleStyle style;
    std::vector<SuccessorModule> axiom; // evaluated when a derivation starts, with its seed
    std::vector<uint8_t> ignored;       // per symbol: 1 when skipped while matching context
    // cpfg's ring L-system ("ring lsystem"): the string's last module
    // precedes its first, so contexts wrap round its ends (cpfg generate.c,
    // LconDiff and RconDiff; lsystem/rewriting/context.h).
    bool ring = false;
    // cpfg's context rules ("context: cpfg", lsystem/rewriting/context.h): a right
    // context reads the pattern's brackets module for module and ignored
    // brackets like any ignored module; a bracket in a left context never
    // matches. Otherwise lpfg's rules (docs/LSYS_FORMAT.md).
    bool cpfgContexts = false;
    ProductionSet rules;
    ProductionSet decomposition;
    ProductionSet interpretation;
    // Whether the decomposition rules rewrite the axiom before the first
    // step, as lpfg's do (lderive.cpp, LEngine::Axiom), or only what each step
    // makes, as cpfg's do ("decompose axiom: no"; generate.c, ApplyProd).
    bool decomposeAxiom = true;
    uint32_t localCount = 0; // the productions' local variables (Production::firstLocal)
    Arithmetic arithmetic = Arithmetic::Native;
    // When a '%' cuts its branch: after the step that produced it (lpfg's
    // rule, "cut: this step"), or while the next step reads the string, so
    // the last step's cuts stay in the derived string (cpfg's, "cut: next step").
    bool cutInNextStep = false;
    // cpfg's global variables and the blocks that run at the start of a
    // derivation (before the axiom is evaluated), before and after each
    // step, and after the last step.
    GlobalTable globals;
    Block startBlock, startEachBlock, endEachBlock, endBlock;
    // Blocks, global variables or srand() make rewriting depend on the order modules are
    // visited in: such grammars are rewritten sequentially, left to right,
    // with one random stream, as cpfg rewrites (lsystem/rewriting/rewriter.h).
    bool sequential = false;
    // The turtle answers query modules (?P, ?H, ?L, ?U) before each step (lsystem/rewriting/queries.h).
    bool queries = false;
};

// Indexes productions by symbol and sizes the per-symbol tables; called by the parser.
void finalizeGrammar(Grammar& grammar);

} // namespace lsys
