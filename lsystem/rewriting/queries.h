#pragma once
// cpfg's query modules (Prusinkiewicz, James and Měch 1994, "Synthetic
// topiary", §2): a '?' followed by P, H, L or U — "?P(x,y,z)" — asks the
// turtle for its position, heading, left or up vector where the module
// stands. Before each derivation step, and once more after the last (where
// cpfg draws the string), the turtle reads the string and writes the
// answers into the parameters of the module after each '?', so that
// productions can use them in conditions and contexts. Which modules are
// queries is lsystem/language/query_modules.h's.

#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"

namespace lsys {

// Interprets `string` with the turtle of the grammar's header settings,
// through its interpretation rules as cpfg's turtle reads it through the
// homomorphism (surfaces are not built), and writes each query's answer into
// the first three parameters of its P, H, L or U. A cpfg file's ?U answers
// cpfg's up vector, L x H (TurtleStyle::cpfgModules; lsystem/turtle/turtle_frame.h).
void answerQueries(const Grammar& grammar, ModuleString& string);

} // namespace lsys
