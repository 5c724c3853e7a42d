// Context matching with lpfg's bracket rules and cpfg's (docs/LSYS_FORMAT.md). Each case rewrites
// the module A to X when its context matches, and checks the whole word after
// one step, so a wrong match anywhere in the word shows up.

#include "test_support.h"

#include "lsystem/instancing/bgrammar.h"

namespace lsys::test {
namespace {

std::string once(const std::string& header, const std::string& axiom, const std::string& rule) {
    return derived(header + "Axiom: " + axiom + "\n" + rule + "\n", 1);
}

TEST(LsysRightContext, ImmediateNeighbour) { EXPECT_EQ(once("", "ABAC", "A > B --> X"), "XBAC"); }

TEST(LsysRightContext, SkipsALateralBranch) { EXPECT_EQ(once("", "A[C]B", "A > B --> X"), "X[C]B"); }

TEST(LsysRightContext, SkipsSeveralLateralBranchesAtOneNode) {
    EXPECT_EQ(once("", "A[C][D[E]F][G]B", "A > B --> X"), "X[C][D[E]F][G]B");
}

TEST(LsysRightContext, EndOfBranchStopsTheSearch) {
    // The A inside the branch has nothing after it on its axis: the B after ']' is on the parent axis.
    EXPECT_EQ(once("", "C[A]B", "A > B --> X"), "C[A]B");
}

TEST(LsysRightContext, EndOfStringDoesNotMatch) { EXPECT_EQ(once("", "BA", "A > B --> X"), "BA"); }

TEST(LsysRightContext, DoesNotSeeTheNextModuleOfAParentBranch) {
    EXPECT_EQ(once("", "[[A]]B", "A > B --> X"), "[[A]]B");
}

TEST(LsysRightContext, DescendsIntoALateralBranch) {
    EXPECT_EQ(once("", "A[B]C A[C]B", "A > [B] --> X"), "X[B]CA[C]B");
}

TEST(LsysRightContext, TriesEachLateralBranchAtTheNode) { EXPECT_EQ(once("", "A[C][B]", "A > [B] --> X"), "X[C][B]"); }

TEST(LsysRightContext, ClosingBracketInPatternSkipsRestOfBranch) {
    // After matching B inside the branch, ']' skips D and the nested [E], then C must follow A.
    EXPECT_EQ(once("", "A[BD[E]]C A[BD]E", "A > [B]C --> X"), "X[BD[E]]CA[BD]E");
}

TEST(LsysRightContext, MultiModule) { EXPECT_EQ(once("", "AB[D]C ABD", "A > BC --> X"), "XB[D]CABD"); }

TEST(LsysRightContext, NestedBranchesInsideASkippedBranch) {
    EXPECT_EQ(once("", "A[C[D[E]]F]B", "A > B --> X"), "X[C[D[E]]F]B");
}

TEST(LsysLeftContext, ImmediateNeighbour) { EXPECT_EQ(once("", "BACA", "B < A --> X"), "BXCA"); }

TEST(LsysLeftContext, ClimbsToTheParentAxisAtABracket) { EXPECT_EQ(once("", "B[A]C[A]", "B < A --> X"), "B[X]C[A]"); }

TEST(LsysLeftContext, ClimbsSeveralLevels) { EXPECT_EQ(once("", "B[[[A]]]", "B < A --> X"), "B[[[X]]]"); }

TEST(LsysLeftContext, SkipsEarlierBranchesOnTheSameAxis) {
    EXPECT_EQ(once("", "B[C][D[E]]A", "B < A --> X"), "B[C][D[E]]X");
}

TEST(LsysLeftContext, SkipsSiblingBranchesBeforeClimbing) { EXPECT_EQ(once("", "B[C][A]", "B < A --> X"), "B[C][X]"); }

TEST(LsysLeftContext, DoesNotLookIntoBranches) {
    // The B inside the branch is not on A's path to the root.
    EXPECT_EQ(once("", "C[B]A", "B < A --> X"), "C[B]A");
}

TEST(LsysLeftContext, MultiModuleAcrossBrackets) {
    EXPECT_EQ(once("", "B[D]C[A] CB[A]", "BC < A --> X"), "B[D]C[X]CB[A]");
}

TEST(LsysLeftContext, StartOfStringDoesNotMatch) {
    EXPECT_EQ(once("", "AB", "B < A --> X"), "AB");
    EXPECT_EQ(once("", "[A]", "B < A --> X"), "[A]");
}

TEST(LsysLeftContext, UnmatchedBracketsAreHarmless) {
    EXPECT_EQ(once("", "]A", "B < A --> X"), "]A");
    EXPECT_EQ(once("", "B]A", "B < A --> X"), "B]A");
    EXPECT_EQ(once("", "A[B", "A > B --> X"), "A[B"); // the unclosed branch is skipped to the end: nothing follows A
    EXPECT_EQ(once("", "A[", "A > B --> X"), "A[");
    EXPECT_EQ(once("", "B[A", "B < A --> X"), "B[X");
}

TEST(LsysBothContexts, MustMatchTogether) { EXPECT_EQ(once("", "BAC BAD EAC", "B < A > C --> X"), "BXCBADEAC"); }

TEST(LsysIgnoredSymbols, AreSkippedOnBothSides) {
    EXPECT_EQ(once("ignore: + -\n", "B+-A-+C", "B < A > C --> X"), "B+-X-+C");
}

TEST(LsysIgnoredSymbols, NotIgnoredWithoutTheDeclaration) { EXPECT_EQ(once("", "B+A", "B < A --> X"), "B+A"); }

TEST(LsysIgnoredSymbols, SkippedInsideBranchesAndBeforeBrackets) {
    EXPECT_EQ(once("ignore: F\n", "BF[FA]", "B < A --> X"), "BF[FX]");
    EXPECT_EQ(once("ignore: F\n", "AF[C]FB", "A > B --> X"), "XF[C]FB");
    EXPECT_EQ(once("ignore: F\n", "AF[FB]", "A > [B] --> X"), "XF[FB]");
}

TEST(LsysIgnoredSymbols, ConsiderListsTheOnlySymbolsThatCount) {
    EXPECT_EQ(once("consider: A B\n", "BCDA", "B < A --> X"), "BCDX");
    EXPECT_EQ(once("consider: A B C\n", "BCDA", "B < A --> X"), "BCDA");
}

TEST(LsysParameters, ContextParametersAreBound) {
    EXPECT_EQ(once("", "B(1)A(2)[E]C(3)", "B(x) < A(y) > C(z) --> A(x*100+y*10+z)"), "B(1)A(123)[E]C(3)");
}

TEST(LsysParameters, ParameterCountMustAgree) {
    EXPECT_EQ(once("", "B(1,2)A(2)", "B(x) < A(y) --> X"), "B(1,2)A(2)");
    EXPECT_EQ(once("", "BA(1)", "B < A --> X"), "BA(1)");
}

TEST(LsysParameters, ConditionSeesContextParameters) {
    EXPECT_EQ(once("", "B(1)A B(5)A", "B(x) < A : x > 2 --> X"), "B(1)AB(5)X");
}

// cpfg's '=' in a right context skips the rest of the current branch, up to
// its ']' (the pipe model's "S > [S(a,d,f)=]S(b,e,g)": the first module of
// each lateral branch and the next one on the axis).
TEST(LsysRightContext, EqualsSkipsTheRestOfTheBranch) {
    EXPECT_EQ(once("", "A[BCD[E]F]G", "A > [B=]G --> X"), "X[BCD[E]F]G");
    EXPECT_EQ(once("", "A[BCD]G", "A > [B=] --> X"), "X[BCD]G");
    // '=' stops at the branch's ']': what follows must still match.
    EXPECT_EQ(once("", "A[BCD]G", "A > [B=]H --> X"), "A[BCD]G");
    EXPECT_EQ(once("", "A[BC]G", "A > [C=]G --> X"), "A[BC]G");
}

// cpfg writes an empty context as '*'.
TEST(LsysContext, StarIsAnEmptyContext) {
    EXPECT_EQ(once("", "BAC", "* < A > * --> X"), "BXC");
    EXPECT_EQ(once("", "BAC", "* < A > C --> X"), "BXC");
    EXPECT_FALSE(parseLsystem("Axiom: A\nB * < A --> X\n").ok());
    EXPECT_FALSE(parseLsystem("Axiom: A\n* A --> X\n").ok());
}

// cpfg's strict predecessors of several modules replace them all, matched
// left to right; contexts lie either side of the whole predecessor.
TEST(LsysMatching, AStrictPredecessorOfSeveralModules) {
    EXPECT_EQ(once("", "ABCABD", "AB --> X"), "XCXD");
    EXPECT_EQ(once("", "AAA", "AA --> X"), "XA");
    EXPECT_EQ(once("", "CABD", "C < AB > D --> X"), "CXD");
    EXPECT_EQ(once("", "CABE", "C < AB > D --> X"), "CABE");
    EXPECT_EQ(derived("Axiom: A(1)B(2)C\nA(x)B(y) : x < y --> X(x+y)\n", 1), "X(3)C");
    Grammar grammar = parseOk("Axiom: ABABABABAB\nAB --> X\nB --> Y\n");
    DeriveOptions options = stepsOf(1);
    options.threads = 4;
    options.parallelThreshold = 1; // one range all the same: a match may not cross a range's end
    EXPECT_EQ(toString(derive(grammar, options), grammar.symbols), "XXXXX");
}

// lpfg cuts a branch after the step that produced its '%'; cpfg when the next
// step reads it, so the last step's cut is still in the string.
TEST(LsysCut, InThisStepOrInTheNext) {
    const std::string rules = "Axiom: [AB]C\nA --> X%\n";
    EXPECT_EQ(derived(rules, 1), "[X]C");
    EXPECT_EQ(derived("cut: next step\n" + rules, 1), "[X%B]C");
    EXPECT_EQ(derived("cut: next step\n" + rules, 2), "[X]C");
    EXPECT_EQ(derived("cut: this step\n" + rules, 1), "[X]C");
    EXPECT_FALSE(parseLsystem("cut: sometimes\nAxiom: A\n").ok());
}

TEST(LsysMatching, ProductionsAreTriedInFileOrder) {
    EXPECT_EQ(derived("Axiom: BA CA\nB < A --> X\nA --> Y\n", 1), "BXCY");
    EXPECT_EQ(derived("Axiom: BA CA\nA --> Y\nB < A --> X\n", 1), "BYCY");
}

TEST(LsysMatching, ContextIsReadFromThePreviousWord) {
    // Parallel rewriting: every module sees the word before this step.
    EXPECT_EQ(derived("Axiom: BAA\nB < A --> B\n", 1), "BBA");
}

// cpfg's ring L-systems: the string's ends are joined, so contexts wrap round
// them (cpfg generate.c, LconDiff and RconDiff). The expected words are
// cpfg's, from cpfg-str.sh on the same systems.
TEST(LsysRing, ContextsWrapRoundTheEnds) {
    const std::string rules = "B < A --> X\nB > A --> Y";
    // The first module's left context is the last module, the last one's right context the first.
    EXPECT_EQ(once("ring lsystem\n", "ACB", rules), "XCY");
    EXPECT_EQ(once("ring lsystem\n", "A(1)B(2)", "B(y) < A(x) --> X(x,y)\nB(y) > A(x) --> Y(x,y)"), "X(1,2)Y(1,2)");
    // Branches and ignored modules at the ends are skipped as anywhere else.
    EXPECT_EQ(once("ring lsystem\n", "[E]ACB[D]", rules), "[E]XCY[D]");
    EXPECT_EQ(once("ring lsystem\nignore: F\n", "FACBF", rules), "FXCYF");
    EXPECT_EQ(once("ring lsystem\n", "[C]BA", "A > [C]B --> X"), "[C]BX");
    // A left context climbs out of the first branch and wraps; a right context still ends at a ']'.
    EXPECT_EQ(once("ring lsystem\n", "[A]CB", "B < A --> X"), "[X]CB");
    EXPECT_EQ(once("ring lsystem\n", "A[CB]", "B > A --> Y"), "A[CB]");
    // A context may come round onto the module itself, and round the ring more than once.
    EXPECT_EQ(once("ring lsystem\n", "A", "A < A --> X"), "X");
    EXPECT_EQ(once("ring lsystem\n", "A[B]", "A > A --> X"), "X[B]");
    EXPECT_EQ(once("ring lsystem\n", "AB", "BABAB < A --> X"), "XB");
    EXPECT_EQ(once("ring lsystem\n", "AB", "A > BABAB --> X"), "XB");
}

TEST(LsysRing, WithoutTheHeaderNothingWraps) {
    EXPECT_EQ(once("", "ACB", "B < A --> X\nB > A --> Y"), "ACB");
    EXPECT_EQ(once("", "[E]ACB[D]", "B < A --> X\nB > A --> Y"), "[E]ACB[D]");
    EXPECT_EQ(once("", "A", "A < A --> X\nA > A --> Y"), "A");
    EXPECT_EQ(once("", "AB", "BABAB < A --> X"), "AB");
}

// Where no module of the ring can be read cpfg goes round for ever; here the context does not match.
TEST(LsysRing, ARingWithNothingToReadDoesNotMatch) {
    EXPECT_EQ(once("ring lsystem\n", "[A]", "A < A --> X"), "[A]");
    EXPECT_EQ(once("ring lsystem\nignore: C\n", "C", "C > C --> X\nC < C --> Y"), "C");
    EXPECT_EQ(once("ring lsystem\nignore: C\n", "C", "C > [C] --> X"), "C");
}

TEST(LsysRing, HeaderAsCpfgSpellsIt) {
    EXPECT_TRUE(parseOk("Ring Lsystem\nAxiom: A\n").ring);
    EXPECT_TRUE(parseOk("ring lsystem\nAxiom: A\n").ring);
    EXPECT_FALSE(parseOk("Axiom: A\n").ring);
    EXPECT_FALSE(parseLsystem("ring lsystem: 1\nAxiom: A\n").ok());
    EXPECT_FALSE(parseLsystem("ring\nAxiom: A\n").ok());
}

// Every way of deriving wraps: on several threads, and in a b-grammar (derived, then compressed).
TEST(LsysRing, EveryDerivationPathWraps) {
    const Grammar grammar = parseOk("ring lsystem\nAxiom: ACB[E]ACB\nB < A --> X\nB > A --> Y\n");
    DeriveOptions options = stepsOf(1);
    options.threads = 4;
    options.parallelThreshold = 1;
    EXPECT_EQ(toString(derive(grammar, options), grammar.symbols), "XCY[E]XCY");
    BGrammarOptions bgrammar;
    bgrammar.steps = 1;
    EXPECT_EQ(toString(expand(buildBGrammar(grammar, bgrammar)), grammar.symbols), "XCY[E]XCY");
}

// vlab's own ring example (oofs, 10-manuals/11-CPFG/Ring/ring.l): 32 cells,
// one A, passed each step to the B on its right (dir 0) or on its left
// (dir 1), round the ring. A Start: block makes it derive sequentially.
constexpr std::string_view kVlabRing = R"(#define dir 0
#define NR 32

Lsystem: 0
ring lsystem
derivation length: 1
Start: {ang = 180/NR;}
Axiom: X(NR)

A < B : dir==0 --> A
B > A : dir==1 --> A
A --> B

decomposition
maximum depth: 1000

X(n) : n>1 --> X(n-1)B
X(n) : n==1 --> A

homomorphism
maximum depth: 2

A --> ;(1)S
B --> ;(2)S
S --> [+(90)F(5)]-(ang)f-(ang)

endlsystem
)";

// The word cpfg derives with the given derivation length. Its first step
// only decomposes X(32) into the ring: cpfg does not decompose the axiom
// (generate.c decomposes a step's successors only), nor does the cpfg
// dialect ("decompose axiom: no").
std::string vlabRing(int cpfgLength, double dir) {
    ParseOptions options;
    options.defines["dir"] = dir;
    ParseResult parsed = parseDialect(Dialect::Cpfg, kVlabRing, options);
    EXPECT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, std::string(kVlabRing));
    EXPECT_TRUE(parsed.grammar.ring);
    return toString(derive(parsed.grammar, stepsOf(cpfgLength)), parsed.grammar.symbols);
}

// cpfg's strings: cpfg-str.sh ring.l (derivation length 1), then with its derivation length and dir changed.
TEST(LsysRing, VlabRingExampleDerivesCpfgsString) {
    EXPECT_EQ(vlabRing(1, 0), "ABBBBBBBBBBBBBBBBBBBBBBBBBBBBBBB");
    EXPECT_EQ(vlabRing(2, 0), "BABBBBBBBBBBBBBBBBBBBBBBBBBBBBBB");
    // The A reaches the last cell; then the first B's left context is that A.
    EXPECT_EQ(vlabRing(32, 0), "BBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBA");
    EXPECT_EQ(vlabRing(33, 0), "ABBBBBBBBBBBBBBBBBBBBBBBBBBBBBBB");
    EXPECT_EQ(vlabRing(40, 0), "BBBBBBBABBBBBBBBBBBBBBBBBBBBBBBB");
    // Leftwards, the last B's right context is the A in the first cell.
    EXPECT_EQ(vlabRing(2, 1), "BBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBA");
    EXPECT_EQ(vlabRing(32, 1), "BABBBBBBBBBBBBBBBBBBBBBBBBBBBBBB");
    EXPECT_EQ(vlabRing(33, 1), "ABBBBBBBBBBBBBBBBBBBBBBBBBBBBBBB");
    EXPECT_EQ(vlabRing(34, 1), "BBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBA");
}

// cpfg's context rules ("context: cpfg", which the cpfg dialect sets; cpfg
// generate.c, RconDiff and LconDiff). The expected words are cpfg's, from
// cpfg-str.sh on the same systems.
std::string onceCpfg(const std::string& header, const std::string& axiom, const std::string& rule) {
    return once("context: cpfg\n" + header, axiom, rule);
}

TEST(CpfgRightContext, ABracketOfThePatternMustComeNext) {
    // '[' meets the first lateral branch only.
    EXPECT_EQ(onceCpfg("", "A[C][B]", "A > [B] --> X"), "A[C][B]");
    EXPECT_EQ(onceCpfg("", "A[B][C]", "A > [B] --> X"), "X[B][C]");
    // ']' must come right after the branch's last named module; '=' skips the rest.
    EXPECT_EQ(onceCpfg("", "A[BD[E]]C A[BD]E A[B]C", "A > [B]C --> X"), "A[BD[E]]CA[BD]EX[B]C");
    EXPECT_EQ(onceCpfg("", "A[BCD[E]F]G", "A > [B=]G --> X"), "X[BCD[E]F]G");
    // A ']' of the pattern reads out of the module's own branch, past lateral branches.
    EXPECT_EQ(onceCpfg("", "[A]B [A[C]]D", "A > ]B --> X\nA > ] --> Y"), "[X]B[Y[C]]D");
}

TEST(CpfgRightContext, BranchesTheContextDoesNotNameAreSkippedAsLpfgSkipsThem) {
    EXPECT_EQ(onceCpfg("", "A[C][D[E]]B", "A > B --> X"), "X[C][D[E]]B");
    EXPECT_EQ(onceCpfg("", "C[A]B", "A > B --> X"), "C[A]B");
    EXPECT_EQ(onceCpfg("", "A(1)[E]C(3)", "A(y) > C(z) --> A(y*10+z)"), "A(13)[E]C(3)");
}

// cpfg's consider: ignores the brackets it does not list (lsys_input.y), and
// RconDiff reads past an ignored module before it looks for a branch.
TEST(CpfgRightContext, IgnoredBracketsAreReadPast) {
    // Into a lateral branch and out of the module's own; a '[' of the pattern then never matches.
    EXPECT_EQ(onceCpfg("consider: A B D\n", "A[B]D [A]BD A[C[B]]D CA]]]BD", "A > B --> X"),
              "X[B]D[X]BDX[C[B]]DCX]]]BD");
    EXPECT_EQ(onceCpfg("consider: A B\n", "A[B]", "A > [B] --> X"), "A[B]");
    EXPECT_EQ(onceCpfg("consider: A B D\n", "A(1)[B(2)]D(3)", "A(a) > B(b) D(d) --> X(a+b+d)"), "X(6)[B(2)]D(3)");
    // One bracket listed, the other not.
    EXPECT_EQ(onceCpfg("consider: A B D ]\n", "A[B]D [A]BD A[C]B", "A > B --> X"), "X[B]D[A]BDA[C]B");
    EXPECT_EQ(onceCpfg("consider: A B D [\n", "A[B]D [A]BD A]B", "A > B --> X"), "A[B]D[X]BDX]B");
    EXPECT_EQ(onceCpfg("ignore: ]\n", "[A]B [A[C]]B", "A > B --> X"), "[X]B[X[C]]B");
    // In a ring, out of the last branch and round to the first module.
    EXPECT_EQ(onceCpfg("ring lsystem\nconsider: A B\n", "A[CB]", "B > A --> Y"), "A[CY]");
}

TEST(CpfgLeftContext, SkipsBranchesWhateverIsIgnored) {
    EXPECT_EQ(onceCpfg("consider: A B D\n", "B[A] B[C]A B[A[C]] D[B]A", "B < A --> X"), "B[X]B[C]XB[X[C]]D[B]A");
}

// cpfg reads a bracket in a left context as a module to compare, but its
// left context never stops on a bracket: such a production never applies.
TEST(CpfgLeftContext, ABracketInThePatternNeverMatches) {
    const std::string source = "Axiom: A(1)[B(2)C]B(3)C[C]D[B(4)[C]]C\n"
                               "[B(c) < C --> X(c)\n"
                               "]B(c) < C --> Y(c)\n"
                               "B(c)[ < C --> Z(c)\n"
                               "B(c) < C --> W(c)\n";
    EXPECT_FALSE(parseLsystem(source).ok()); // lpfg's rules reject it
    const ParseResult parsed = parseLsystem("context: cpfg\n" + source);
    ASSERT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, source);
    EXPECT_EQ(parsed.warnings.size(), 3u);
    EXPECT_EQ(toString(derive(parsed.grammar, stepsOf(1)), parsed.grammar.symbols),
              "A(1)[B(2)W(2)]B(3)W(3)[C]D[B(4)[W(4)]]C");
}

TEST(CpfgContexts, TheHeaderAndTheCpfgDialectChooseThem) {
    EXPECT_TRUE(parseOk("context: cpfg\nAxiom: A\n").cpfgContexts);
    EXPECT_FALSE(parseOk("context: cpfg\ncontext: native\nAxiom: A\n").cpfgContexts);
    EXPECT_FALSE(parseOk("Axiom: A\n").cpfgContexts);
    EXPECT_FALSE(parseLsystem("context: lpfg\nAxiom: A\n").ok());
    const ParseResult cpfg = parseDialect(Dialect::Cpfg, "Lsystem: 1\nAxiom: A\nendlsystem\n", {});
    ASSERT_TRUE(cpfg.ok());
    EXPECT_TRUE(cpfg.grammar.cpfgContexts);
    // Without cpfg's rules consider: counts the brackets (lpfg).
    EXPECT_EQ(once("consider: A B\n", "A[B]", "A > B --> X"), "A[B]");
}

} // namespace
} // namespace lsys::test
