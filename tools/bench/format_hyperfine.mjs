// Turns hyperfine JSON exports (one per system, commands "lsys" and one
// peer: lindenmayer or cpfg) into the Markdown tables of docs/BENCHMARKS.md.
import {readFileSync} from 'node:fs';
import {basename} from 'node:path';

const rows = [];
for (const file of process.argv.slice(2)) {
    const {results} = JSON.parse(readFileSync(file, 'utf8'));
    const ours = results.find((r) => r.command === 'lsys'), theirs = results.find((r) => r.command !== 'lsys');
    if (rows.length === 0) {
        const peer = theirs.command;
        rows.push(`| system | lsys (s) | ${peer} (s) | ${peer} / lsys |`, '|---|---|---|---|');
    }
    const fmt = (r) => `${r.mean.toFixed(3)} ± ${r.stddev.toFixed(3)}`;
    rows.push(`| ${basename(file, '.json')} | ${fmt(ours)} | ${fmt(theirs)} | ${(theirs.mean / ours.mean).toFixed(1)}× |`);
}
console.log(rows.join('\n'));
