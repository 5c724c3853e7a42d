// The peer of the rewriter benchmark (tools/bench/rewriter_vs_peers.sh):
// the npm `lindenmayer` library (v1.5.4) deriving the same three systems as
// data/plants/fractal_bush.lsys, decreasing_tree.lsys and
// context_benchmark.lsys. Prints the module count so runs can be checked
// against lsys; hyperfine times the whole process. With a third argument it
// also appends the seconds spent in iterate() alone (its in-process time,
// without node's start and the module's loading) to that file, a line a run.
// Usage: node lindenmayer_bench.mjs bush|tree|context STEPS [IN_PROCESS_FILE]
import {appendFileSync} from 'node:fs';
import LSystem from 'lindenmayer';

const [system, stepsText, inProcessFile] = process.argv.slice(2);
const steps = Number(stepsText);

const systems = {
    // (a) F → FF+[+F-F-F]-[-F+F+F]
    bush: () => new LSystem({axiom: 'F', productions: {F: 'FF+[+F-F-F]-[-F+F+F]'}}),
    // (b) A(w) → F(1)!(w)[+A(w*0.707)][-A(w*0.707)], F(s) → F(s*1.456): parametric modules are objects.
    tree: () => new LSystem({
        axiom: [{symbol: 'A', w: 5}],
        productions: {
            A: ({part}) => [{symbol: 'F', s: 1}, {symbol: '!', w: part.w}, {symbol: '['}, {symbol: '+'},
                            {symbol: 'A', w: part.w * 0.707}, {symbol: ']'}, {symbol: '['}, {symbol: '-'},
                            {symbol: 'A', w: part.w * 0.707}, {symbol: ']'}],
            F: ({part}) => ({symbol: 'F', s: part.s * 1.456}),
        },
    }),
    // (c) context-sensitive, ignoring + and -.
    context: () => new LSystem({axiom: 'AB', productions: {'A<B': 'B[+A]B', 'B<B': 'BA', 'A>A': 'B'},
                                ignoredSymbols: '+-'}),
};

if (!(system in systems) || !Number.isInteger(steps) || steps < 0) {
    console.error('usage: node lindenmayer_bench.mjs bush|tree|context STEPS [IN_PROCESS_FILE]');
    process.exit(2);
}
const start = performance.now();
const lsystem = systems[system]();
lsystem.iterate(steps);
const seconds = (performance.now() - start) / 1000;
if (inProcessFile) appendFileSync(inProcessFile, `${seconds}\n`);
console.log(JSON.stringify({system, steps, modules: lsystem.axiom.length}));
