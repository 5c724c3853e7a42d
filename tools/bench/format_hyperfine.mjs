// Turns hyperfine JSON exports (one per system: the command "lsys" and its
// peers, e.g. cpfg and lindenmayer) into the Markdown tables of
// docs/BENCHMARKS.md: each peer's mean time and its ratio to lsys's. A file
// NAME.inprocess beside NAME.json holds a peer's in-process seconds, a line a
// run, the warm-up's first (lindenmayer_bench.mjs writes it); it adds that
// peer's in-process mean and its ratio to lsys's whole-process mean.
// Usage: node format_hyperfine.mjs SYSTEM.json...
import {existsSync, readFileSync} from 'node:fs';
import {basename} from 'node:path';

const mean = (xs) => xs.reduce((a, b) => a + b, 0) / xs.length;
const stddev = (xs) => Math.sqrt(mean(xs.map((x) => (x - mean(xs)) ** 2)));
const fmt = (m, s) => `${m.toFixed(3)} ± ${s.toFixed(3)}`;

const rows = [];
for (const file of process.argv.slice(2)) {
    const {results} = JSON.parse(readFileSync(file, 'utf8'));
    const ours = results.find((r) => r.command === 'lsys');
    const peers = results.filter((r) => r !== ours);
    const inProcessFile = file.replace(/\.json$/, '.inprocess');
    // The first line is hyperfine's warm-up run, which its own figures leave out too.
    const inProcess = existsSync(inProcessFile)
                          ? readFileSync(inProcessFile, 'utf8').trim().split('\n').slice(1).map(Number)
                          : [];
    if (rows.length === 0) {
        const head = ['system', 'lsys (s)'];
        for (const p of peers) head.push(`${p.command} (s)`, `${p.command} / lsys`);
        if (inProcess.length) head.push('lindenmayer in-process (s)', 'in-process / lsys');
        rows.push(`| ${head.join(' | ')} |`, `|${'---|'.repeat(head.length)}`);
    }
    const cells = [basename(file, '.json'), fmt(ours.mean, ours.stddev)];
    for (const p of peers) cells.push(fmt(p.mean, p.stddev), `${(p.mean / ours.mean).toFixed(1)}×`);
    if (inProcess.length)
        cells.push(fmt(mean(inProcess), stddev(inProcess)), `${(mean(inProcess) / ours.mean).toFixed(1)}×`);
    rows.push(`| ${cells.join(' | ')} |`);
}
console.log(rows.join('\n'));
