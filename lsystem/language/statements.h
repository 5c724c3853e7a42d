#pragma once
// cpfg's statement blocks (Měch 2005, "CPFG Version 4.0 User's Manual",
// §5.1; Prusinkiewicz, Hanan and Měch 1999, "An L-system-based plant modeling
// language", §3): C-like assignments, if/else, while and do-while loops and
// procedure calls, run before and after a production's condition, and at
// the start and end of a derivation and of each of its steps. They read and
// write a production's local variables and the grammar's global ones.

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsystem/common/random.h"
#include "lsystem/language/expression.h"
#include "lsystem/language/lexer.h"

namespace lsys {

enum class Storage : uint8_t { Local, Global };

struct BlockStatement {
    enum class Kind : uint8_t { Assign, If, While, DoWhile, Evaluate, Print };
    Kind kind = Kind::Evaluate;
    // Assign: the variable written; for an array element, `index` computes
    // the flat element index and `extent` is the array's size.
    Storage storage = Storage::Local;
    uint32_t slot = 0;
    uint32_t extent = 0;
    std::optional<Expression> index;
    Expression value; // Assign: the value; If, While, DoWhile: the condition; Evaluate: the call
    std::vector<BlockStatement> body, otherwise;
    std::string format;                // Print: printf's format
    std::vector<Expression> arguments; // Print: its values
};
using Block = std::vector<BlockStatement>;

// What the names of a block refer to while it is parsed. A name assigned
// before it is known becomes a local variable of the production (appended
// to `locals`, after the formal parameters) or, in a block outside any
// production (locals is null), a global variable.
struct BlockScope {
    std::vector<std::string>* locals = nullptr;
    GlobalTable* globals = nullptr;
    const std::unordered_map<std::string, double>* constants = nullptr;
    Arithmetic arithmetic = Arithmetic::Native;
    bool arrayDefinitions = false; // cpfg's define: block, "array a[2][3] = {...};"
    FunctionTable functions;       // what func(id, x) reads (ParseOptions::functions)
};

// Parses "{ statements }" at the cursor. On error appends a diagnostic and
// returns nullopt.
std::optional<Block> parseBlock(Cursor& cursor, BlockScope& scope, const std::string& file,
                                std::vector<Diagnostic>& diagnostics);

// A block's loops may run this many times in all, per run: a loop that never
// ends is a DerivationError, not a hang.
inline constexpr uint64_t kMaxLoopIterations = 10'000'000;

// Runs a block. printf writes to standard error, as cpfg's does.
void runBlock(const Block& block, double* locals, double* globals, RandomStream& random);

} // namespace lsys
