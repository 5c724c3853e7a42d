/* Included by preprocessor.l: a macro with arguments that expands to
   modules, one that expands to an expression, and a production. */
#define LEAF(size, turn) [ +(turn) L(size) ]
#define SHRINK(x) ((x)*RATE)
#define PAIR(a, b) a b

L(s) : s > 0.3 --> L(SHRINK(s)) PAIR(F(s), LEAF(s, 15))
