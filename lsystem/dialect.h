#pragma once
// The notations of the source documents besides the native one (DESIGN.md §2).
// A dialect front end translates its text into native statements, one per
// line, with a map from each native line back to where the statement was in
// the original; the native parser then builds the same Grammar as always.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/error.h"

namespace lsys {

enum class Dialect { Native, Crankshaw, Robbins, Plantlang };

std::optional<Dialect> dialectByName(std::string_view name);

// The dialect named by a "dialect: NAME" line (the first non-blank,
// non-comment line of a file), if there is one.
std::optional<std::string> declaredDialect(std::string_view source);

struct Translation {
    std::string native;
    struct Origin {
        int line;
        int column;
    };
    std::vector<Origin> origins;  // origins[i]: where native line i+1 came from
    std::vector<Diagnostic> diagnostics;
};

// Crankshaw 2020 (seed 004): "#n = 6; #define r 20; #object F BRANCH;
// #w : axiom; #p1 : predecessor : condition : successor;" where the condition
// is '*', '~p' (stochastic) or an expression; multi-letter module names are
// separated by spaces; {a, b} is a uniform random number in [a, b).
Translation translateCrankshaw(std::string_view source, const std::string& file);

// Robbins 1998 (seed 003): "iterations 10 angle 30 length 1 thickness .2
// startpoint x y z forward x y z left x y z up x y z" header, then the axiom,
// then "NAME --> successor" productions; names are separated by spaces.
// Commands whose meaning differs from the native notation are renamed:
// > < roll (native / and \), % roll 180 (/(180)), " ' length scale (@Lm),
// ; : angle scale (@Am), ? ! thickness scale (@Wm), each with Robbins'
// default factor when it has no parameter. The start frame is ignored.
Translation translateRobbins(std::string_view source, const std::string& file);

// The turtle language of seed 002: "Axiom = f20t15dX", "X => t<dY",
// "(0.2) F -> [-F]F" (stochastic: probability first),
// "Default angle = 30", "Number of iterations = 12". Commands are one letter,
// optionally reversed by '<' and followed by a value (digits or "(x)"):
// d m draw/move, f u r rotate about Forward/Up/Right, t T thickness, o O
// circles, c colour, a A angle, l L length, { . } polygons; other letters
// are variables. + and - turn right and left (the reverse of ABOP). Each
// command becomes the native module with the same meaning (see the table in
// dialect_plantlang.cpp).
Translation translatePlantlang(std::string_view source, const std::string& file);

// Translation into native statements for any dialect but Native.
Translation translate(Dialect dialect, std::string_view source, const std::string& file);

}  // namespace lsys
