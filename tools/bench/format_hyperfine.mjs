// Turns hyperfine JSON exports (one per system, commands "lsys" and
// "lindenmayer") into the Markdown table of docs/BENCHMARKS.md.
import {readFileSync} from 'node:fs';
import {basename} from 'node:path';

const rows = ['| system | lsys (s) | lindenmayer (s) | lindenmayer / lsys |', '|---|---|---|---|'];
for (const file of process.argv.slice(2)) {
    const {results} = JSON.parse(readFileSync(file, 'utf8'));
    const byName = Object.fromEntries(results.map((r) => [r.command, r]));
    const ours = byName.lsys, theirs = byName.lindenmayer;
    const fmt = (r) => `${r.mean.toFixed(3)} ± ${r.stddev.toFixed(3)}`;
    rows.push(`| ${basename(file, '.json')} | ${fmt(ours)} | ${fmt(theirs)} | ${(theirs.mean / ours.mean).toFixed(1)}× |`);
}
console.log(rows.join('\n'));
