// Context matching with lpfg's bracket rules (docs/LSYS_FORMAT.md). Each case rewrites
// the module A to X when its context matches, and checks the whole word after
// one step, so a wrong match anywhere in the word shows up.

#include "test_support.h"

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

} // namespace
} // namespace lsys::test
